#include "formats/cgns/cgns_groups.h"

#include <algorithm>
#include <string>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "formats/cgns/cgns_extras.h"

namespace getme::formats {
namespace {

// 1-based indices of the conditions the group names, or NotFound.
absl::StatusOr<std::vector<std::int64_t>> ConditionsOf(const MeshDocument& document,
                                                       absl::string_view group) {
  std::vector<std::int64_t> indices;
  std::vector<std::string> names;
  std::vector<std::string> families;
  if (document.cgns.has_value()) {
    const std::vector<CgnsBoundaryCondition>& conditions = document.cgns->boundary_conditions;
    for (std::size_t i = 0; i < conditions.size(); ++i) {
      if (conditions[i].name == group || conditions[i].family == group) {
        indices.push_back(static_cast<std::int64_t>(i) + 1);
      }
      names.push_back(absl::StrCat("'", conditions[i].name, "'"));
    }
    for (const CgnsFamily& family : document.cgns->families) {
      families.push_back(absl::StrCat("'", family.name, "'"));
      if (family.name == group && indices.empty()) return indices;  // a family without members
    }
  }
  if (!indices.empty()) return indices;
  return absl::NotFoundError(
      absl::StrCat("no group '", group, "': the CGNS file's boundary conditions are ",
                   names.empty() ? "none" : absl::StrJoin(names, ", "), "; its families ",
                   families.empty() ? "none" : absl::StrJoin(families, ", ")));
}

}  // namespace

absl::StatusOr<std::vector<std::int64_t>> CgnsGroupCells(const MeshDocument& document,
                                                         absl::string_view group) {
  absl::StatusOr<std::vector<std::int64_t>> conditions = ConditionsOf(document, group);
  if (!conditions.ok()) return conditions.status();
  std::vector<std::int64_t> cells;
  const DataArray* owner = FindArray(document.grid.cell_data, kCgnsBcArray);
  if (owner == nullptr || owner->components != 1 ||
      owner->tuple_count() != document.grid.cells.size()) {
    return cells;
  }
  for (std::int64_t cell = 0; cell < owner->tuple_count(); ++cell) {
    const auto value = static_cast<std::int64_t>(owner->AsDouble(cell));
    if (std::find(conditions->begin(), conditions->end(), value) != conditions->end()) {
      cells.push_back(cell);
    }
  }
  return cells;
}

absl::StatusOr<std::vector<std::int64_t>> CgnsGroupNodes(const MeshDocument& document,
                                                         absl::string_view group) {
  absl::StatusOr<std::vector<std::int64_t>> conditions = ConditionsOf(document, group);
  if (!conditions.ok()) return conditions.status();
  absl::StatusOr<std::vector<std::int64_t>> cells = CgnsGroupCells(document, group);
  if (!cells.ok()) return cells.status();
  std::vector<std::int64_t> nodes;
  const GridCells& grid_cells = document.grid.cells;
  for (const std::int64_t cell : *cells) {
    nodes.insert(nodes.end(), grid_cells.nodes(cell),
                 grid_cells.nodes(cell) + grid_cells.node_count(cell));
  }
  for (const std::int64_t index : *conditions) {
    const CgnsBoundaryCondition& condition = document.cgns->boundary_conditions[index - 1];
    if (condition.on_nodes) {
      nodes.insert(nodes.end(), condition.nodes.begin(), condition.nodes.end());
    }
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

}  // namespace getme::formats
