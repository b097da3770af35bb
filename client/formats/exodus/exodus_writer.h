#pragma once

#include <string>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// Writes `document` as an Exodus II file (netCDF 64-bit offset, doubles, 32-bit integers; netCDF-4
// with 64-bit integers only past 2^31 - 1 nodes or elements) through Debian's Exodus library:
// - Nodes: the grid points, X/Y/Z.
// - Element blocks: the grid's cells other than side set faces, grouped by the cell array
//   "exodus:block" (when present) and by cell type, in order of first appearance; volume cells as
//   TETRA, PYRAMID, WEDGE (VTK's wedge written back in Exodus order), HEX8, passthrough cells as
//   TRI3, SHELL4, BAR2, SPHERE. A block whose id is in the document's ExodusExtras with the same
//   cell count and type keeps its name, its type's spelling and its attributes; other blocks are
//   numbered 1, 2, … (ids not taken) and named after their type. Regrouping reorders cells when a
//   grid interleaves types: a spdlog warning says so.
// - Side sets: the triangle and quad cells whose "exodus:sideset" value is the id of a side set
//   of the extras. Each becomes (element, side): the volume element having the face as a side
//   with the same orientation (else as any side), with the Exodus manual's side numbering; a face
//   that is no element's side is InvalidArgument. Names and distribution factors are kept while
//   the set keeps its size.
// - Node sets, the title and the number maps of the extras, while they still fit the grid.
// - One-component cell arrays (the quality arrays mean_ratio, warpage, valid of a smoothed mesh)
//   → element variables of one time step (t = 0), per block, as ParaView and meshio read them;
//   their values on side set faces have no place in Exodus. Point arrays, field data and
//   multi-component cell arrays are not written: a spdlog warning names them.
// InvalidArgument for cells Exodus cannot hold here (voxels, quadratic cells, polyhedra) and for
// an inconsistent document; the library's errors carry its message.
absl::Status WriteExodus(const std::string& path, const MeshDocument& document,
                         const WriteOptions& options);

// Node sets have no cells, so no other format holds them: when a document read from Exodus is
// written as `format` (not Exodus), a spdlog warning names the node sets left out. Side sets and
// blocks travel as cells with the cell arrays "exodus:sideset" and "exodus:block".
void WarnExodusNodeSetsNotWritten(const MeshDocument& document, FileFormat format);

// The bytes of the file WriteExodus writes (through a temporary file: the library writes only
// named files).
absl::StatusOr<std::string> SerializeExodus(const MeshDocument& document,
                                            const WriteOptions& options);

}  // namespace getme::formats
