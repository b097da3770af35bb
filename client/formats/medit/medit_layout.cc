#include "formats/medit/medit_layout.h"

#include <cmath>
#include <limits>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "formats/vtk_cell_type.h"

namespace getme::formats::medit {
namespace {

constexpr int kVtkVertex = 1;

}  // namespace

absl::StatusOr<CellLayout> PlanCells(const UnstructuredGrid& grid) {
  const GridCells& cells = grid.cells;
  if (cells.offsets.size() != cells.types.size() + 1 || cells.offsets.front() != 0 ||
      cells.offsets.back() != static_cast<std::int64_t>(cells.connectivity.size())) {
    return absl::InvalidArgumentError(
        absl::StrCat("cells: ", cells.types.size(), " cell types need ", cells.types.size() + 1,
                     " offsets from 0 to the connectivity size ", cells.connectivity.size()));
  }
  CellLayout layout;
  std::vector<int> section_of_kind(kElementKindCount, -1);
  int last_section = -1;
  for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
    const int type = cells.types[cell];
    const std::optional<VtkCellTypeInfo> info = CellTypeInfo(type);
    const ElementKind* kind = ElementKindOfCell(type);
    if (type == kVtkVertex) {
      ++layout.vertex_cells;
      continue;
    }
    if (kind == nullptr) {
      return absl::InvalidArgumentError(absl::StrCat(
          "cell ", cell, " has VTK type ", type, info ? absl::StrCat(" (", info->name, ")") : "",
          ", which MEDIT cannot hold (it has lines, triangles, quads, tetrahedra, prisms, "
          "hexahedra and pyramids)"));
    }
    if (cells.offsets[cell + 1] - cells.offsets[cell] != kind->node_count) {
      return absl::InvalidArgumentError(absl::StrCat("cell ", cell, " (", info->name, ") has ",
                                                     cells.offsets[cell + 1] - cells.offsets[cell],
                                                     " nodes; expected ", kind->node_count));
    }
    for (std::int64_t k = cells.offsets[cell]; k < cells.offsets[cell + 1]; ++k) {
      if (cells.connectivity[k] < 0 || cells.connectivity[k] >= grid.point_count()) {
        return absl::InvalidArgumentError(absl::StrCat("cell ", cell, " refers to point ",
                                                       cells.connectivity[k], ", but there are ",
                                                       grid.point_count(), " points"));
      }
    }
    const auto kind_index = static_cast<std::size_t>(kind - ElementKinds().data());
    if (section_of_kind[kind_index] < 0) {
      section_of_kind[kind_index] = static_cast<int>(layout.sections.size());
      layout.sections.push_back(ElementSection{kind, {}});
    }
    const int section = section_of_kind[kind_index];
    // Returning to an earlier kind's section moves this cell before cells already laid out.
    if (section < last_section) layout.regrouped = true;
    last_section = section;
    layout.sections[section].cells.push_back(cell);
  }
  return layout;
}

absl::StatusOr<std::vector<std::int64_t>> CellRefs(const UnstructuredGrid& grid,
                                                   std::string* source) {
  std::vector<std::int64_t> refs(grid.cells.size(), 0);
  source->clear();
  const DataArray* array = nullptr;
  for (absl::string_view name : {"medit:ref", "gmsh:physical"}) {
    if ((array = FindArray(grid.cell_data, name)) != nullptr) break;
  }
  if (array == nullptr) return refs;
  *source = array->name;
  if (array->components != 1 || array->tuple_count() != grid.cells.size()) {
    return absl::InvalidArgumentError(
        absl::StrCat("cell data '", array->name, "' has ", array->tuple_count(), " tuples of ",
                     array->components, " components; expected ", grid.cells.size(),
                     " single values, one per cell"));
  }
  for (std::int64_t cell = 0; cell < grid.cells.size(); ++cell) {
    const double value = array->AsDouble(cell);
    if (!(value >= std::numeric_limits<std::int32_t>::min() &&
          value <= std::numeric_limits<std::int32_t>::max() && std::trunc(value) == value)) {
      return absl::InvalidArgumentError(absl::StrCat("cell data '", array->name, "' at cell ", cell,
                                                     " is ", value,
                                                     "; a MEDIT ref is a 32-bit integer"));
    }
    refs[cell] = static_cast<std::int64_t>(value);
  }
  return refs;
}

}  // namespace getme::formats::medit
