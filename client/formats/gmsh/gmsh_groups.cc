#include "formats/gmsh/gmsh_groups.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "absl/container/flat_hash_map.h"
#include "absl/status/status.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "absl/strings/str_split.h"
#include "formats/gmsh/gmsh_element_type.h"

namespace getme::formats {
namespace {

using DimTag = std::pair<int, int>;

// Each cell's physical groups, calling `visit(cell, dim, tag)` once per group.
template <typename Visit>
void ForEachMembership(const MeshDocument& document, Visit&& visit) {
  const UnstructuredGrid& grid = document.grid;
  const std::int64_t cells = grid.cells.size();
  const GmshExtras* extras = document.gmsh ? &*document.gmsh : nullptr;
  if (extras != nullptr && extras->version_major == 4 && extras->has_entities &&
      static_cast<std::int64_t>(extras->element_entities.size()) == cells) {
    absl::flat_hash_map<DimTag, const std::vector<int>*> physical;
    for (const GmshEntity& entity : extras->entities) {
      physical.try_emplace(DimTag(entity.dim, entity.tag), &entity.physical_tags);
    }
    for (std::int64_t c = 0; c < cells; ++c) {
      const GmshDimTag entity = extras->element_entities[c];
      const auto it = physical.find(DimTag(entity.dim, entity.tag));
      if (it == physical.end()) continue;
      for (int tag : *it->second) visit(c, entity.dim, tag);
    }
    return;
  }
  const DataArray* array = FindArray(grid.cell_data, "gmsh:physical");
  if (array == nullptr || array->components != 1 || array->tuple_count() != cells) return;
  for (std::int64_t c = 0; c < cells; ++c) {
    const double tag = array->AsDouble(c);
    const std::optional<GmshElementTypeInfo> type = GmshElementTypeOfVtk(grid.cells.types[c]);
    // 0 is "no physical group" in MSH 2.2.
    if (tag == 0 || !std::isfinite(tag) || !type) continue;
    visit(c, type->dim, static_cast<int>(tag));
  }
}

}  // namespace

absl::StatusOr<std::vector<std::int64_t>> GmshGroupCells(const MeshDocument& document,
                                                         absl::string_view group) {
  // Every group there is, with its name if it has one, sorted by (dim, tag).
  std::map<DimTag, std::string> groups;
  ForEachMembership(document, [&](std::int64_t, int dim, int tag) {
    groups.try_emplace({dim, tag});
  });
  if (document.gmsh) {
    for (const GmshPhysicalName& name : document.gmsh->physical_names) {
      groups[{name.dim, name.tag}] = name.name;
    }
  }

  std::vector<DimTag> wanted;
  for (const auto& [dim_tag, name] : groups) {
    if (!name.empty() && name == group) wanted.push_back(dim_tag);
  }
  int number = 0;
  if (wanted.empty() && absl::SimpleAtoi(group, &number)) {
    for (const auto& [dim_tag, name] : groups) {
      if (dim_tag.second == number) wanted.push_back(dim_tag);
    }
  }
  const std::vector<absl::string_view> parts = absl::StrSplit(group, ':');
  int dim = 0;
  if (wanted.empty() && parts.size() == 2 && absl::SimpleAtoi(parts[0], &dim) &&
      absl::SimpleAtoi(parts[1], &number) && groups.contains({dim, number})) {
    wanted.push_back({dim, number});
  }
  if (wanted.empty()) {
    std::vector<std::string> listed;
    for (const auto& [dim_tag, name] : groups) {
      listed.push_back(absl::StrCat(name.empty() ? "(unnamed)" : absl::StrCat("\"", name, "\""),
                                    " dim ", dim_tag.first, " tag ", dim_tag.second));
    }
    return absl::NotFoundError(
        listed.empty()
            ? absl::StrCat("no physical group '", group, "': the mesh has no physical groups")
            : absl::StrCat("no physical group '", group,
                           "' (a name, a tag or DIM:TAG); the mesh has ",
                           absl::StrJoin(listed, ", ")));
  }

  std::vector<std::int64_t> cells;
  ForEachMembership(document, [&](std::int64_t cell, int cell_dim, int tag) {
    if (std::find(wanted.begin(), wanted.end(), DimTag(cell_dim, tag)) != wanted.end() &&
        (cells.empty() || cells.back() != cell)) {
      cells.push_back(cell);
    }
  });
  return cells;
}

}  // namespace getme::formats
