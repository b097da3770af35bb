#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// Reads an Exodus II file (netCDF-3 classic or 64-bit offset, or netCDF-4/HDF5, whatever the
// Exodus library opens) through Debian's Exodus II library into a MeshDocument:
// - num_dim must be 3 (getme smooths volume meshes): a 2D file is InvalidArgument.
// - Nodes → grid points (coordx/y/z as doubles), in file order.
// - Element blocks in file order → grid cells, element k of the file = grid cell k - 1.
//   TETRA, PYRAMID, WEDGE, HEX (4/5/6/8 nodes) are volume elements; SHELL/QUAD, TRI, BAR/BEAM/
//   TRUSS and SPHERE blocks pass through as quads, triangles, lines and vertices (moved with
//   their nodes, not smoothed). Type names as exodus_element_types.h accepts them; other types
//   (HEX20, TETRA10, NFACED, …) are InvalidArgument naming the block. The cell array
//   "exodus:block" (Int64) holds each cell's block id, -1 on side set faces.
// - Side sets → one triangle or quad cell per (element, side) entry, after the block cells, in
//   set order, with the nodes the Exodus library gives for that side (ex_get_side_set_node_list,
//   each face counter-clockwise seen from outside its element). The cell array "exodus:sideset"
//   (Int64) holds each face's side set id, -1 on block cells. Sides of non-volume elements are
//   InvalidArgument.
// - Node sets, block and set ids and names, attributes, distribution factors, the title and the
//   node and element number maps → ExodusExtras, so that writing Exodus again keeps them.
// - Results (time steps with nodal, element or global variables), QA and info records are not
//   read; a spdlog warning names what is left out.
//
// Every library call is checked; errors are InvalidArgument naming the block or set and carrying
// the library's own message, e.g. "element block 2 ('solid'): element 1: node 7 out of range
// 1..4". Sizes the header declares are checked against the file's size before anything is
// allocated (a netCDF header can declare any dimension length).
absl::StatusOr<MeshDocument> ReadExodus(const std::string& path);

// The same from the bytes of a file: written to a temporary file first, because the Exodus
// library opens files by name only (exodus_library.h). Used by ParseMeshDocument and the
// fuzzer; errors carry no path.
absl::StatusOr<MeshDocument> ParseExodus(absl::string_view bytes);

}  // namespace getme::formats
