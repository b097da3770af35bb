#pragma once

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// Parses an SU2 native mesh file (.su2, ASCII; SU2 Mesh File documentation, "SU2 Native
// Format") into a MeshDocument:
// - NDIME= must come before the elements and points and be 3 (getme smooths volume meshes).
// - NELEM= n, then n rows "type node… [index]": VTK type codes 10 tetrahedron, 12 hexahedron,
//   13 prism (VTK wedge), 14 pyramid, node indices 0-based in VTK's node order (SU2 takes its
//   element numbering from VTK) → grid cells in file order.
// - NPOIN= n [domain points], then n rows "x y z [index…]" → grid points in file order.
// - NMARK= m, then m markers "MARKER_TAG= name", "MARKER_ELEMS= k" and k rows "type node…"
//   (5 triangle, 9 quadrilateral, 3 line) → grid cells after the elements, marker by marker.
//   The cell array "su2:tag" (Int32) holds 0 for the elements and each marker's tag for its
//   cells: the marker's name if that is an integer, else the previous marker's tag + 1 —
//   meshio's rule, so both tools give a converted file the same tags (a clash, which meshio lets
//   through, takes the next free tag). Names (the rest of the MARKER_TAG= line), order and tags
//   go to Su2Extras.
// - The row index at the end of element and point rows is optional (SU2 writes it, meshio does
//   not); its value is ignored, as SU2 ignores it, and the writer renumbers rows from 0.
// - Whatever follows the last of these sections (NPERIODIC, FFD_* of a deformed mesh) is kept
//   verbatim in Su2Extras::tail. NZONE= 1 / IZONE= 1 are accepted; more zones are refused.
// - Mirrored elements (every corner determinant negative, su2_mirrored_elements.h) are
//   renumbered to be valid and listed in Su2Extras::mirrored_cells.
//
// Errors (InvalidArgument) name the line and the field, e.g.
// "line 17: NELEM element 5: node 120 out of range 0..99 (NPOIN= 100)". The parser never reads
// out of bounds and never reserves more rows than the remaining bytes could hold.
absl::StatusOr<MeshDocument> ParseSu2(absl::string_view bytes);

}  // namespace getme::formats
