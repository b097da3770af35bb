#include "formats/gmsh/gmsh_layout.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <tuple>

#include "absl/container/flat_hash_map.h"
#include "absl/container/flat_hash_set.h"
#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "formats/gmsh/gmsh_element_type.h"
#include "formats/vtk_cell_type.h"
#include "spdlog/spdlog.h"

namespace getme::formats {
namespace {

// An integer cell-data array of the grid's cell count, or null.
const DataArray* CellArray(const UnstructuredGrid& grid, absl::string_view name) {
  const DataArray* array = FindArray(grid.cell_data, name);
  if (array == nullptr || array->components != 1 || array->tuple_count() != grid.cells.size()) {
    return nullptr;
  }
  return array;
}

int IntValue(const DataArray* array, std::int64_t index) {
  if (array == nullptr) return 0;
  const double value = array->AsDouble(index);
  if (!std::isfinite(value)) return 0;
  return static_cast<int>(std::clamp(std::round(value), double{std::numeric_limits<int>::min()},
                                     double{std::numeric_limits<int>::max()}));
}

void ExpandBox(GmshEntity& entity, const DataArray& points, std::int64_t i, bool first) {
  const double point[3] = {points.AsDouble(3 * i), points.AsDouble(3 * i + 1),
                           points.AsDouble(3 * i + 2)};
  for (int k = 0; k < 3; ++k) {
    entity.min[k] = first ? point[k] : std::min(entity.min[k], point[k]);
    entity.max[k] = first ? point[k] : std::max(entity.max[k], point[k]);
  }
}

// Entities and each cell's entity from the grid's cell data (see gmsh_layout.h).
void DeriveEntities(const UnstructuredGrid& grid, const std::vector<int>& cell_dims,
                    GmshLayout& layout, std::vector<int>& physical) {
  const DataArray* geometrical = CellArray(grid, "gmsh:geometrical");
  const DataArray* gmsh_physical = CellArray(grid, "gmsh:physical");
  const DataArray* ref = CellArray(grid, "medit:ref");
  const DataArray* entity_source =
      geometrical != nullptr ? geometrical : (ref != nullptr ? ref : gmsh_physical);
  const DataArray* physical_source = gmsh_physical != nullptr ? gmsh_physical : ref;

  using Key = std::tuple<int, int, int>;  // dim, entity value, physical value
  absl::flat_hash_map<Key, int> key_index;
  std::vector<Key> keys;
  std::vector<int> cell_key(grid.cells.size());
  for (std::int64_t c = 0; c < grid.cells.size(); ++c) {
    const Key key{cell_dims[c], IntValue(entity_source, c), IntValue(physical_source, c)};
    const auto [it, inserted] = key_index.try_emplace(key, static_cast<int>(keys.size()));
    if (inserted) keys.push_back(key);
    cell_key[c] = it->second;
  }
  // Entity tags: the entity values themselves where they are positive and name one key each
  // within their dimension, else 1..k in order of appearance.
  std::vector<int> key_tag(keys.size());
  for (int dim = 0; dim <= 3; ++dim) {
    absl::flat_hash_set<int> values;
    bool usable = true;
    for (const Key& key : keys) {
      if (std::get<0>(key) != dim) continue;
      usable = usable && std::get<1>(key) > 0 && values.insert(std::get<1>(key)).second;
    }
    int next = 1;
    for (std::size_t i = 0; i < keys.size(); ++i) {
      if (std::get<0>(keys[i]) == dim) key_tag[i] = usable ? std::get<1>(keys[i]) : next++;
    }
  }
  // Entities ordered by dimension, as $Entities lists them.
  std::vector<int> order(keys.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return std::get<0>(keys[a]) < std::get<0>(keys[b]); });
  std::vector<int> entity_of_key(keys.size());
  for (int key : order) {
    GmshEntity entity;
    entity.dim = std::get<0>(keys[key]);
    entity.tag = key_tag[key];
    if (std::get<2>(keys[key]) != 0) entity.physical_tags.push_back(std::get<2>(keys[key]));
    entity_of_key[key] = static_cast<int>(layout.entities.size());
    layout.entities.push_back(std::move(entity));
  }
  std::vector<bool> boxed(layout.entities.size(), false);
  layout.element_entities.reserve(grid.cells.size());
  physical.reserve(grid.cells.size());
  for (std::int64_t c = 0; c < grid.cells.size(); ++c) {
    const int e = entity_of_key[cell_key[c]];
    GmshEntity& entity = layout.entities[e];
    for (std::int64_t k = 0; k < grid.cells.node_count(c); ++k) {
      // A point entity is its first node.
      if (entity.dim == 0 && boxed[e]) break;
      ExpandBox(entity, grid.points, grid.cells.nodes(c)[k], !boxed[e]);
      boxed[e] = true;
    }
    layout.element_entities.push_back(GmshDimTag{entity.dim, entity.tag});
    physical.push_back(std::get<2>(keys[cell_key[c]]));
  }
  // Every node on one entity of the highest dimension: one block keeps the point order.
  const std::int64_t n = grid.point_count();
  if (n > 0) {
    if (layout.entities.empty()) {
      GmshEntity volume;
      volume.dim = 3;
      volume.tag = 1;
      for (std::int64_t i = 0; i < n; ++i) ExpandBox(volume, grid.points, i, i == 0);
      layout.entities.push_back(volume);
    }
    const GmshEntity& host = layout.entities.back();
    layout.node_blocks.push_back(GmshNodeBlock{host.dim, host.tag, false, n, {}});
  }
}

// Names 4.1 entities of the input with more than one physical group, which one 2.2 tag per
// element (or a re-derived entity) cannot carry.
void WarnMultiplePhysical(const GmshExtras& extras, absl::string_view target) {
  std::vector<std::string> lost;
  for (const GmshEntity& entity : extras.entities) {
    if (entity.physical_tags.size() > 1) {
      lost.push_back(absl::StrCat("(", entity.dim, ", ", entity.tag, ") in groups ",
                                  absl::StrJoin(entity.physical_tags, ", ")));
    }
  }
  if (!lost.empty()) {
    spdlog::warn(
        "Gmsh: {} keeps one physical group per element; entities {} keep only their first "
        "group",
        std::string(target), absl::StrJoin(lost, "; "));
  }
}

// Extras built by hand (not by the reader) must still not make the writer read out of bounds
// or write a file Gmsh misreads.
absl::Status CheckExtras(const GmshExtras& extras) {
  const auto bad = [](absl::string_view what) {
    return absl::InvalidArgumentError(absl::StrCat("inconsistent Gmsh extras: ", what));
  };
  const auto bad_text = [](absl::string_view text) {
    return text.find_first_of("\"\n\r") != absl::string_view::npos;
  };
  for (const GmshPhysicalName& name : extras.physical_names) {
    if (bad_text(name.name)) return bad(absl::StrCat("physical name '", name.name, "'"));
  }
  for (const GmshEntity& entity : extras.entities) {
    if (entity.dim < 0 || entity.dim > 3) {
      return bad(absl::StrCat("entity dimension ", entity.dim));
    }
  }
  for (const GmshNodeBlock& block : extras.node_blocks) {
    if (block.dim < 0 || block.dim > 3 || block.count < 0 ||
        static_cast<std::int64_t>(block.parametric_coords.size()) !=
            (block.parametric ? block.count * block.dim : 0)) {
      return bad(absl::StrCat("node block (", block.dim, ", ", block.tag, ")"));
    }
  }
  const GmshTagLists& lists = extras.element_tag_lists;
  if (lists.offsets.empty() || lists.offsets.front() != 0 ||
      lists.offsets.back() != static_cast<std::int64_t>(lists.values.size()) ||
      !std::is_sorted(lists.offsets.begin(), lists.offsets.end())) {
    return bad("element tag lists");
  }
  for (const GmshDataView& view : extras.data_views) {
    if (view.integer_tags.size() < 3) return bad(absl::StrCat("view '", view.array_name, "'"));
    for (const std::string& tag : view.string_tags) {
      if (bad_text(tag)) return bad(absl::StrCat("view string tag '", tag, "'"));
    }
  }
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<GmshLayout> BuildGmshLayout(const MeshDocument& document, GmshVersion version) {
  const UnstructuredGrid& grid = document.grid;
  const std::int64_t n = grid.point_count();
  const std::int64_t m = grid.cells.size();
  if (grid.points.components != 3 || grid.points.value_count() != 3 * n) {
    return absl::InvalidArgumentError("the points must have 3 components");
  }
  for (std::int64_t id : grid.cells.connectivity) {
    if (id < 0 || id >= n) {
      return absl::InvalidArgumentError(
          absl::StrCat("a cell refers to point ", id, ", but there are ", n, " points"));
    }
  }
  const GridCells& cells = grid.cells;
  if (static_cast<std::int64_t>(cells.offsets.size()) != m + 1 || cells.offsets.front() != 0 ||
      cells.offsets.back() != static_cast<std::int64_t>(cells.connectivity.size()) ||
      !std::is_sorted(cells.offsets.begin(), cells.offsets.end())) {
    return absl::InvalidArgumentError("the cells' offsets do not match their types and nodes");
  }
  std::vector<int> cell_dims(m);
  for (std::int64_t c = 0; c < m; ++c) {
    const std::optional<GmshElementTypeInfo> info = GmshElementTypeOfVtk(grid.cells.types[c]);
    if (!info) {
      const std::optional<VtkCellTypeInfo> vtk = CellTypeInfo(grid.cells.types[c]);
      return absl::InvalidArgumentError(absl::StrCat(
          "cell ", c, " has VTK type ", grid.cells.types[c],
          vtk ? absl::StrCat(" (", vtk->name, ")") : std::string(),
          ", which the Gmsh writer cannot store; it writes vertex, line, triangle, quad, tetra, "
          "hexahedron, wedge and pyramid cells"));
    }
    if (grid.cells.node_count(c) != info->node_count) {
      return absl::InvalidArgumentError(absl::StrCat("cell ", c, " (", info->name, ") has ",
                                                     grid.cells.node_count(c), " nodes, expected ",
                                                     info->node_count));
    }
    cell_dims[c] = info->dim;
  }

  GmshLayout layout;
  const GmshExtras* extras = document.gmsh ? &*document.gmsh : nullptr;
  if (extras != nullptr) {
    if (absl::Status status = CheckExtras(*extras); !status.ok()) return status;
  }
  layout.keeps_tags = extras != nullptr &&
                      static_cast<std::int64_t>(extras->node_tags.size()) == n &&
                      static_cast<std::int64_t>(extras->element_tags.size()) == m;
  if (layout.keeps_tags) {
    layout.node_tags = extras->node_tags;
    layout.element_tags = extras->element_tags;
  } else {
    if (extras != nullptr) {
      spdlog::warn(
          "Gmsh: the input's {} node and {} element tags do not match the mesh ({} points, {} "
          "cells); nodes and elements are renumbered from 1",
          extras->node_tags.size(), extras->element_tags.size(), n, m);
    }
    layout.node_tags.resize(n);
    std::iota(layout.node_tags.begin(), layout.node_tags.end(), std::int64_t{1});
    layout.element_tags.resize(m);
    std::iota(layout.element_tags.begin(), layout.element_tags.end(), std::int64_t{1});
  }
  if (extras != nullptr) layout.physical_names = extras->physical_names;

  const bool want41 = version == GmshVersion::k41;
  const bool same_version = extras != nullptr && extras->version_major == (want41 ? 4 : 2);
  if (want41 && same_version && layout.keeps_tags &&
      static_cast<std::int64_t>(extras->element_entities.size()) == m) {
    std::int64_t block_nodes = 0;
    for (const GmshNodeBlock& block : extras->node_blocks) block_nodes += block.count;
    if (block_nodes == n) {
      layout.write_entities = extras->has_entities;
      layout.entities = extras->entities;
      layout.node_blocks = extras->node_blocks;
      layout.element_entities = extras->element_entities;
      return layout;
    }
  }
  if (!want41 && same_version && layout.keeps_tags && extras->element_tag_lists.size() == m) {
    layout.element_tag_lists = extras->element_tag_lists;
    return layout;
  }

  if (extras != nullptr && extras->version_major == 4) {
    WarnMultiplePhysical(*extras, want41 ? "rebuilding the entities" : "MSH 2.2");
  }
  if (extras != nullptr && extras->version_major == 2) {
    const GmshTagLists& lists = extras->element_tag_lists;
    for (std::int64_t c = 0; c < lists.size(); ++c) {
      if (lists.offsets[c + 1] - lists.offsets[c] > 2) {
        spdlog::warn(
            "Gmsh: element tags beyond the physical and elementary ones (MSH 2.2 partitions, first "
            "on element {}) are not carried over",
            extras->element_tags.size() > static_cast<std::size_t>(c) ? extras->element_tags[c]
                                                                      : c + 1);
        break;
      }
    }
  }
  std::vector<int> physical;
  DeriveEntities(grid, cell_dims, layout, physical);
  if (!want41) {
    GmshTagLists& lists = layout.element_tag_lists;
    lists.values.reserve(2 * m);
    lists.offsets.reserve(m + 1);
    for (std::int64_t c = 0; c < m; ++c) {
      lists.values.push_back(physical[c]);
      lists.values.push_back(layout.element_entities[c].tag);
      lists.offsets.push_back(static_cast<std::int64_t>(lists.values.size()));
    }
    layout.entities.clear();
    layout.node_blocks.clear();
    layout.element_entities.clear();
  }
  return layout;
}

}  // namespace getme::formats
