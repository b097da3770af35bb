#pragma once

#include <cstdint>
#include <vector>

#include "formats/unstructured_grid.h"

namespace getme::formats {

// Mirrored elements. Some SU2 meshes number elements mirror-wise: a hexahedron's bottom quad
// clockwise instead of counter-clockwise seen from the top, and so on, so that in VTK's
// convention every corner Jacobian (every node tetrahedron determinant, Def. 2 and eq. 9 of the
// paper) is negative, while the element itself is a perfectly good one. SU2 does not mind (its
// finite-volume dual mesh takes absolute volumes); getme would see an inverted element.
//
// Reversing the element's orientation — a symmetry of the reference element that swaps two of
// the three edges at every corner — flips the sign of every corner determinant at once, so a
// mirrored element becomes valid and a valid one mirrored. The renumbering, in VTK order:
//   tetra (0 2 1 3), hexahedron (0 3 2 1 4 7 6 5), wedge (0 2 1 3 5 4), pyramid (0 3 2 1 4).
// Each is its own inverse: applying it again restores the file's order.
//
// An element with only some corners negative is tangled, not mirrored: it is left alone for
// the untangling stage.

// Whether volume cell `cell` (VTK tetra, hexahedron, wedge or pyramid) has every corner
// determinant negative. False for other cell types and for node ids outside the points.
bool IsMirroredCell(const UnstructuredGrid& grid, std::int64_t cell);

// Applies the renumbering above to the nodes of `cell` (a volume cell; others are left alone).
void MirrorCellNodeOrder(GridCells& cells, std::int64_t cell);

// Renumbers every mirrored volume cell of `grid`; returns their indices, ascending.
std::vector<std::int64_t> RenumberMirroredCells(UnstructuredGrid& grid);

}  // namespace getme::formats
