#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// Serializes `document` as a Gmsh MSH file of options.gmsh_version (2.2 or 4.1) in
// options.encoding (binary: little-endian, 8-byte size_t, as Gmsh writes on x86-64).
//
// Tags, entities and physical groups come from document.gmsh when it matches the grid, else
// from cell data (see gmsh_layout.h). Points are written in grid order, cells in grid order with
// VTK's wedge mirrored back to Gmsh's prism; ASCII numbers are the shortest decimals that read
// back bit-identical (vtk_values.h), so a parse → serialize round trip in the same version and
// encoding keeps every coordinate bit and every tag.
//
// Arrays: each point_data / cell_data array becomes one $NodeData / $ElementData section (a
// Gmsh view), values as doubles, except the cell arrays "gmsh:physical", "gmsh:geometrical" and
// "medit:ref", which the entities and element tags carry. Arrays read from a data section are
// written back with that section's tags (time, step, partition) and entries; arrays with other
// than 1, 3 or 9 components — the counts Gmsh's views know — are split into one view per
// component ("name[0]", …) with a warning. Sections the reader kept verbatim are written back in
// place when the version and encoding are the ones read and the tags are kept; otherwise, as
// for VTK field data, a warning names what is left out.
//
// MSH 2.2 cell arrays and meshio. meshio's MSH 2.2 reader (5.0 to 7.0, gmsh/_gmsh22.py) splits
// an $ElementData section among its cell blocks by the length of its (type, data) tuples, 2,
// instead of the blocks' sizes, and fails ("Incompatible cell data … has length 2") whenever the
// $Elements hold more than one run of one element type — any mesh with surface triangles or
// mixed volume types. So in MSH 2.2 with more than one run, each cell array is written as an
// $ElementNodeData view instead: the element's value once per node of the element. Gmsh shows it
// as the same piecewise-constant field, meshio skips the section and reads the mesh, and the
// reader turns such a section back into the cell array (gmsh_reader.h). MSH 4.1 (meshio reads
// its $ElementData right) and single-run 2.2 meshes keep $ElementData.
//
// InvalidArgument for a grid MSH cannot hold: a cell type other than vertex, line, triangle,
// quad, tetra, hexahedron, wedge or pyramid, node ids out of range, array lengths that do not
// match, a tag beyond the 32-bit ints of a binary field.
absl::StatusOr<std::string> SerializeGmsh(const MeshDocument& document,
                                          const WriteOptions& options);

}  // namespace getme::formats
