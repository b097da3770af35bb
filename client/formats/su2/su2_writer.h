#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// Serializes `document` as an ASCII SU2 native mesh (.su2), as SU2's own writer lays it out:
// NDIME= 3, NELEM= with one row "type node… [index]" per volume cell (tetra 10, hexahedron 12,
// wedge 13, pyramid 14; VTK's node order, which is SU2's), NPOIN= with "x y z [index]" rows
// (shortest decimals that read back bit-identical), NMARK= and one MARKER_TAG= / MARKER_ELEMS=
// block per marker holding its triangles, quads and lines.
//
// Markers: the boundary cells (triangle, quad, line) grouped by their value in the cell array
// "su2:tag", else "gmsh:physical", else "medit:ref" (all in one marker "0" without any). A marker
// is named as the document's Su2Extras names it, else by its Gmsh physical name, else by the
// number; markers the extras list come first, in their order, the others by first appearance.
//
// With Su2Extras, the row indices are written or left out as in the file read, the elements the
// reader renumbered as mirrored (su2_mirrored_elements.h) are written back in the file's own node
// order, and the verbatim tail follows the markers: an SU2 → SU2 round trip keeps every row's
// node order.
//
// A .su2 mesh holds no data arrays: point and cell arrays other than the marker tags, field data
// and vertex cells are named in a spdlog warning and not written. InvalidArgument for binary
// output (SU2 has no binary native mesh), points that are not 3D, cells SU2 cannot hold
// (voxels, quadratic cells, polyhedra, …) and node ids out of range.
absl::StatusOr<std::string> SerializeSu2(const MeshDocument& document, const WriteOptions& options);

}  // namespace getme::formats
