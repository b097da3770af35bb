#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "formats/medit/medit_keywords.h"
#include "formats/unstructured_grid.h"

namespace getme::formats::medit {

// The cells of one MEDIT element section, as grid cell indices in grid order.
struct ElementSection {
  const ElementKind* kind = nullptr;
  std::vector<std::int64_t> cells;
};

// How the cells of a grid are laid out in a MEDIT file. MEDIT numbers elements per kind, one
// section per kind, so a grid whose kinds are interleaved (tetra, pyramid, tetra, …) comes out
// grouped: sections in the order each kind first appears, cells in grid order within each. A
// grid read from MEDIT is already grouped and keeps its order.
struct CellLayout {
  std::vector<ElementSection> sections;
  std::int64_t vertex_cells = 0;  // VTK vertex cells (1): MEDIT has no such element
  bool regrouped = false;         // the file's element order differs from the grid's cell order
};

// Checks the grid's cells (offsets, node counts of each type, point ids in range) and plans the
// sections. InvalidArgument, naming the cell, for an inconsistent grid or a cell type MEDIT
// cannot hold (anything but vertex, line, triangle, quad, tetra, hexahedron, wedge, pyramid).
absl::StatusOr<CellLayout> PlanCells(const UnstructuredGrid& grid);

// The ref of every grid cell: from the cell array "medit:ref", else "gmsh:physical", else 0.
// `source` is set to the name of the array used ("" for none). InvalidArgument if that array
// has the wrong length, more than one component, or a value that is not a 32-bit integer.
absl::StatusOr<std::vector<std::int64_t>> CellRefs(const UnstructuredGrid& grid,
                                                   std::string* source);

}  // namespace getme::formats::medit
