#include "formats/exodus/exodus_writer.h"

#include <exodusII.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "formats/exodus/exodus_element_types.h"
#include "formats/exodus/exodus_functions.h"
#include "formats/exodus/exodus_library.h"
#include "formats/file_io.h"
#include "formats/vtk_cell_type.h"
#include "spdlog/spdlog.h"

namespace getme::formats {
namespace {

constexpr char kBlockArray[] = "exodus:block";
constexpr char kSideSetArray[] = "exodus:sideset";

struct PlannedBlock {
  std::int64_t id = 0;
  std::string name;
  std::string topology;
  int vtk_type = 0;
  int node_count = 0;
  std::vector<std::int64_t> cells;
  const ExodusBlock* kept = nullptr;  // the extras' block it writes back, if any
};

struct PlannedSideSet {
  const ExodusSideSet* source = nullptr;
  std::vector<std::int64_t> elements;
  std::vector<std::int64_t> sides;
};

// Everything to write, decided before the file is created.
struct Plan {
  std::vector<PlannedBlock> blocks;
  std::vector<PlannedSideSet> side_sets;
  std::vector<const ExodusNodeSet*> node_sets;
  std::int64_t element_count = 0;
  bool reordered = false;
  // One-component cell arrays (the quality arrays of a smoothed mesh), written as element
  // variables of one time step; their values on side set faces have no element to go to.
  std::vector<const DataArray*> element_variables;
};

// A cell array of integers per cell (nullptr if absent).
absl::StatusOr<const DataArray*> CellTags(const UnstructuredGrid& grid, absl::string_view name) {
  const DataArray* array = FindArray(grid.cell_data, name);
  if (array == nullptr) return nullptr;
  if (array->components != 1 || array->tuple_count() != grid.cells.size()) {
    return absl::InvalidArgumentError(
        absl::StrCat("cell array '", name, "' has ", array->tuple_count(), " tuples of ",
                     array->components, " for ", grid.cells.size(), " cells"));
  }
  return array;
}

bool IsRotationOf(std::span<const std::int64_t> face, std::span<const std::int64_t> side) {
  if (face.size() != side.size()) return false;
  for (std::size_t shift = 0; shift < side.size(); ++shift) {
    bool same = true;
    for (std::size_t i = 0; i < side.size() && same; ++i) {
      same = face[i] == side[(i + shift) % side.size()];
    }
    if (same) return true;
  }
  return false;
}

bool SameNodes(std::span<const std::int64_t> face, std::span<const std::int64_t> side) {
  if (face.size() != side.size()) return false;
  std::vector<std::int64_t> a(face.begin(), face.end()), b(side.begin(), side.end());
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  return a == b;
}

absl::Status PlanBlocks(const MeshDocument& document, const DataArray* block_tags,
                        const std::vector<bool>& is_side_face, Plan* plan) {
  const GridCells& cells = document.grid.cells;
  std::map<std::pair<std::int64_t, int>, std::size_t> block_of_key;
  for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
    if (is_side_face[cell]) continue;
    const int type = cells.types[cell];
    const std::optional<ExodusTopology> topology = TopologyOfVtkCell(type);
    const std::optional<VtkCellTypeInfo> info = CellTypeInfo(type);
    if (!topology.has_value()) {
      return absl::InvalidArgumentError(
          absl::StrCat("cell ", cell, ": a VTK ", info.has_value() ? info->name : "unknown",
                       " cell (type ", type,
                       ") cannot be written to Exodus: getme writes tetra, pyramid, "
                       "wedge, hexahedron, triangle, quad, line and vertex cells"));
    }
    if (cells.node_count(cell) != topology->node_count) {
      return absl::InvalidArgumentError(absl::StrCat("cell ", cell, ": ", cells.node_count(cell),
                                                     " nodes for a ", info->name, " cell"));
    }
    const std::int64_t tag =
        block_tags == nullptr ? -1 : static_cast<std::int64_t>(block_tags->AsDouble(cell));
    const auto [found, inserted] = block_of_key.try_emplace({tag, type}, plan->blocks.size());
    if (inserted) {
      PlannedBlock block;
      block.id = tag;
      block.vtk_type = type;
      block.node_count = topology->node_count;
      block.topology = std::string(topology->written_name);
      plan->blocks.push_back(std::move(block));
    }
    plan->blocks[found->second].cells.push_back(cell);
  }
  // Ids: a tag keeps its id for its first block; other blocks take the lowest ids not in use.
  std::set<std::int64_t> used;
  for (PlannedBlock& block : plan->blocks) {
    if (block.id >= 0 && !used.insert(block.id).second) block.id = -1;
  }
  std::int64_t next = 1;
  for (PlannedBlock& block : plan->blocks) {
    if (block.id >= 0) continue;
    while (used.contains(next)) ++next;
    block.id = next;
    used.insert(next);
    block.name = std::string(CellTypeInfo(block.vtk_type)->name);
  }
  if (document.exodus.has_value()) {
    for (PlannedBlock& block : plan->blocks) {
      for (const ExodusBlock& kept : document.exodus->blocks) {
        if (kept.id != block.id ||
            kept.cell_count != static_cast<std::int64_t>(block.cells.size())) {
          continue;
        }
        const absl::StatusOr<ExodusTopology> topology =
            TopologyOfBlock(kept.topology, block.node_count);
        if (!topology.ok() || topology->vtk_type != block.vtk_type) continue;
        block.name = kept.name;
        block.topology = kept.topology;
        block.kept = &kept;
      }
    }
  }
  std::int64_t previous = -1;
  for (const PlannedBlock& block : plan->blocks) {
    for (const std::int64_t cell : block.cells) {
      if (cell < previous) plan->reordered = true;
      previous = cell;
    }
    plan->element_count += static_cast<std::int64_t>(block.cells.size());
  }
  return absl::OkStatus();
}

// The Exodus-order nodes of grid cell `cell`.
std::vector<std::int64_t> ExodusNodes(const GridCells& cells, std::int64_t cell) {
  std::vector<std::int64_t> nodes(cells.nodes(cell), cells.nodes(cell) + cells.node_count(cell));
  ConvertExodusVtkOrder(cells.types[cell], nodes);
  return nodes;
}

absl::Status PlanSideSets(const MeshDocument& document, const DataArray* side_tags,
                          const std::vector<bool>& is_side_face, Plan* plan) {
  if (!document.exodus.has_value() || side_tags == nullptr) return absl::OkStatus();
  const GridCells& cells = document.grid.cells;
  std::vector<std::int64_t> element_of_cell(static_cast<std::size_t>(cells.size()), 0);
  std::vector<std::vector<std::int64_t>> elements_of_node(
      static_cast<std::size_t>(document.grid.point_count()));
  std::int64_t element = 0;
  for (const PlannedBlock& block : plan->blocks) {
    for (const std::int64_t cell : block.cells) {
      element_of_cell[cell] = ++element;
      if (SideCount(block.vtk_type) == 0) continue;
      for (std::int64_t k = 0; k < cells.node_count(cell); ++k) {
        elements_of_node[cells.nodes(cell)[k]].push_back(cell);
      }
    }
  }
  for (const ExodusSideSet& set : document.exodus->side_sets) {
    PlannedSideSet planned;
    planned.source = &set;
    for (std::int64_t face = 0; face < cells.size(); ++face) {
      if (!is_side_face[face] || static_cast<std::int64_t>(side_tags->AsDouble(face)) != set.id) {
        continue;
      }
      const std::span<const std::int64_t> nodes(cells.nodes(face),
                                                static_cast<std::size_t>(cells.node_count(face)));
      std::int64_t best_element = 0;
      std::int64_t best_side = 0;
      bool oriented = false;
      for (const std::int64_t candidate : elements_of_node[nodes[0]]) {
        const std::vector<std::int64_t> element_nodes = ExodusNodes(cells, candidate);
        const int type = cells.types[candidate];
        for (int side = 1; side <= SideCount(type) && !oriented; ++side) {
          const ExodusSide local = SideNodes(type, side);
          std::vector<std::int64_t> side_nodes;
          for (int i = 0; i < local.size; ++i) side_nodes.push_back(element_nodes[local.nodes[i]]);
          if (IsRotationOf(nodes, side_nodes)) {
            best_element = element_of_cell[candidate];
            best_side = side;
            oriented = true;
          } else if (best_element == 0 && SameNodes(nodes, side_nodes)) {
            best_element = element_of_cell[candidate];
            best_side = side;
          }
        }
        if (oriented) break;
      }
      if (best_element == 0) {
        return absl::InvalidArgumentError(absl::StrCat(
            "side set ", set.id, set.name.empty() ? "" : absl::StrCat(" ('", set.name, "')"),
            ": cell ", face, " (nodes ", absl::StrJoin(nodes, " "),
            ") is no side of a volume element"));
      }
      planned.elements.push_back(best_element);
      planned.sides.push_back(best_side);
    }
    plan->side_sets.push_back(std::move(planned));
  }
  return absl::OkStatus();
}

absl::StatusOr<Plan> PlanFile(const MeshDocument& document) {
  const UnstructuredGrid& grid = document.grid;
  if (grid.points.components != 3) {
    return absl::InvalidArgumentError(
        absl::StrCat("points have ", grid.points.components, " components, not 3"));
  }
  const GridCells& cells = grid.cells;
  for (const std::int64_t node : cells.connectivity) {
    if (node < 0 || node >= grid.point_count()) {
      return absl::InvalidArgumentError(
          absl::StrCat("a cell refers to point ", node, " of ", grid.point_count()));
    }
  }
  absl::StatusOr<const DataArray*> block_tags = CellTags(grid, kBlockArray);
  if (!block_tags.ok()) return block_tags.status();
  absl::StatusOr<const DataArray*> side_tags = CellTags(grid, kSideSetArray);
  if (!side_tags.ok()) return side_tags.status();

  std::set<std::int64_t> side_set_ids;
  if (document.exodus.has_value()) {
    for (const ExodusSideSet& set : document.exodus->side_sets) side_set_ids.insert(set.id);
  }
  std::vector<bool> is_side_face(static_cast<std::size_t>(cells.size()), false);
  if (*side_tags != nullptr) {
    for (std::int64_t cell = 0; cell < cells.size(); ++cell) {
      const int type = cells.types[cell];
      is_side_face[cell] =
          (type == kVtkTriangle || type == kVtkQuad) &&
          side_set_ids.contains(static_cast<std::int64_t>((*side_tags)->AsDouble(cell)));
    }
  }
  Plan plan;
  if (absl::Status status = PlanBlocks(document, *block_tags, is_side_face, &plan); !status.ok()) {
    return status;
  }
  if (plan.blocks.empty()) {
    return absl::InvalidArgumentError("no cells to write: Exodus needs at least one element block");
  }
  if (absl::Status status = PlanSideSets(document, *side_tags, is_side_face, &plan); !status.ok()) {
    return status;
  }
  if (document.exodus.has_value()) {
    for (const ExodusNodeSet& set : document.exodus->node_sets) {
      for (const std::int64_t node : set.nodes) {
        if (node < 0 || node >= grid.point_count()) {
          return absl::InvalidArgumentError(absl::StrCat("node set ", set.id, ": node ", node,
                                                         " not among the ", grid.point_count(),
                                                         " points"));
        }
      }
      plan.node_sets.push_back(&set);
    }
  }
  return plan;
}

void PlanElementVariables(const MeshDocument& document, Plan* plan) {
  for (const VtkAttribute& attribute : document.grid.cell_data) {
    for (const DataArray& array : attribute.arrays) {
      if (array.name == kBlockArray || array.name == kSideSetArray || array.components != 1 ||
          array.tuple_count() != document.grid.cells.size()) {
        continue;
      }
      plan->element_variables.push_back(&array);
    }
  }
}

void WarnAboutUnwritten(const MeshDocument& document, const Plan& plan) {
  std::vector<std::string> arrays;
  const auto collect = [&](const std::vector<VtkAttribute>& attributes, absl::string_view kind) {
    for (const VtkAttribute& attribute : attributes) {
      for (const DataArray& array : attribute.arrays) {
        if (array.name == kBlockArray || array.name == kSideSetArray) continue;
        if (std::find(plan.element_variables.begin(), plan.element_variables.end(), &array) !=
            plan.element_variables.end()) {
          continue;
        }
        arrays.push_back(absl::StrCat(kind, " '", array.name, "'"));
      }
    }
  };
  collect(document.grid.point_data, "point array");
  collect(document.grid.cell_data, "cell array");
  collect(document.grid.field_data, "field data");
  if (!arrays.empty()) {
    spdlog::warn(
        "Exodus: not written (getme writes one-component cell arrays as element variables): {}",
        absl::StrJoin(arrays, ", "));
  }
  if (plan.reordered) {
    spdlog::warn("Exodus: cells regrouped into element blocks by type; cell numbers change");
  }
}

// Calls the library with the names as the char* array it takes.
template <typename Put>
int WithNames(const std::vector<std::string>& names, Put put) {
  std::vector<std::vector<char>> buffers;
  std::vector<char*> pointers;
  for (const std::string& name : names) {
    buffers.emplace_back(name.begin(), name.end());
    buffers.back().push_back('\0');
  }
  for (std::vector<char>& buffer : buffers) pointers.push_back(buffer.data());
  return put(pointers.data());
}

std::string SetName(absl::string_view kind, std::int64_t id, const std::string& name) {
  return absl::StrCat(kind, " ", id, name.empty() ? "" : absl::StrCat(" ('", name, "')"));
}

// Exodus II manual, "Results Data": element variables per block and time step; one step at
// time 0 holds the arrays of the document.
absl::Status WriteElementVariables(int exoid, const Plan& plan) {
  const int count = static_cast<int>(plan.element_variables.size());
  if (count == 0) return absl::OkStatus();
  if (Exodus().ex_put_variable_param(exoid, EX_ELEM_BLOCK, count) < 0) {
    return ExodusError("cannot declare the element variables");
  }
  std::vector<std::string> names;
  for (const DataArray* array : plan.element_variables) names.push_back(array->name);
  if (WithNames(names, [&](char** list) {
        return Exodus().ex_put_variable_names(exoid, EX_ELEM_BLOCK, count, list);
      }) < 0) {
    return ExodusError("cannot write the element variable names");
  }
  const double time = 0.0;
  if (Exodus().ex_put_time(exoid, 1, &time) < 0) return ExodusError("cannot write the time step");
  for (int variable = 0; variable < count; ++variable) {
    const DataArray& array = *plan.element_variables[variable];
    for (const PlannedBlock& block : plan.blocks) {
      std::vector<double> values;
      values.reserve(block.cells.size());
      for (const std::int64_t cell : block.cells) values.push_back(array.AsDouble(cell));
      if (Exodus().ex_put_var(exoid, 1, EX_ELEM_BLOCK, variable + 1, block.id,
                              static_cast<std::int64_t>(values.size()), values.data()) < 0) {
        return ExodusError(
            absl::StrCat("element variable '", array.name, "', element block ", block.id));
      }
    }
  }
  return absl::OkStatus();
}

absl::Status WritePlan(int exoid, const MeshDocument& document, const Plan& plan) {
  const UnstructuredGrid& grid = document.grid;
  const std::int64_t point_count = grid.point_count();
  std::size_t longest_name = 0;
  for (const PlannedBlock& block : plan.blocks)
    longest_name = std::max(longest_name, block.name.size());
  for (const PlannedSideSet& set : plan.side_sets) {
    longest_name = std::max(longest_name, set.source->name.size());
  }
  for (const ExodusNodeSet* set : plan.node_sets)
    longest_name = std::max(longest_name, set->name.size());
  for (const DataArray* array : plan.element_variables) {
    longest_name = std::max(longest_name, array->name.size());
  }
  if (longest_name > MAX_NAME_LENGTH &&
      Exodus().ex_set_max_name_length(exoid, static_cast<int>(longest_name)) < 0) {
    return ExodusError("cannot set the name length");
  }

  ex_init_params init{};
  const std::string title = document.exodus.has_value() && !document.exodus->title.empty()
                                ? document.exodus->title
                                : "written by getme";
  std::strncpy(init.title, title.c_str(), MAX_LINE_LENGTH);
  init.num_dim = 3;
  init.num_nodes = point_count;
  init.num_elem = plan.element_count;
  init.num_elem_blk = static_cast<std::int64_t>(plan.blocks.size());
  init.num_side_sets = static_cast<std::int64_t>(plan.side_sets.size());
  init.num_node_sets = static_cast<std::int64_t>(plan.node_sets.size());
  if (Exodus().ex_put_init_ext(exoid, &init) < 0)
    return ExodusError("cannot write the Exodus header");

  std::vector<double> x(point_count), y(point_count), z(point_count);
  for (std::int64_t node = 0; node < point_count; ++node) {
    x[node] = grid.points.AsDouble(3 * node);
    y[node] = grid.points.AsDouble(3 * node + 1);
    z[node] = grid.points.AsDouble(3 * node + 2);
  }
  if (Exodus().ex_put_coord(exoid, x.data(), y.data(), z.data()) < 0) {
    return ExodusError("cannot write the node coordinates");
  }
  if (WithNames({"X", "Y", "Z"},
                [&](char** names) { return Exodus().ex_put_coord_names(exoid, names); }) < 0) {
    return ExodusError("cannot write the coordinate names");
  }

  const GridCells& cells = grid.cells;
  std::vector<std::string> block_names;
  for (const PlannedBlock& block : plan.blocks) {
    const std::string where = SetName("element block", block.id, block.name);
    const ExodusBlock* kept = block.kept;
    const std::int64_t attribute_count = kept != nullptr && !kept->attributes.empty()
                                             ? static_cast<std::int64_t>(kept->attributes.size()) /
                                                   std::max<std::int64_t>(1, kept->cell_count)
                                             : 0;
    const std::int64_t count = static_cast<std::int64_t>(block.cells.size());
    if (Exodus().ex_put_block(exoid, EX_ELEM_BLOCK, block.id, block.topology.c_str(), count,
                              block.node_count, 0, 0, attribute_count) < 0) {
      return ExodusError(where);
    }
    std::vector<std::int64_t> connectivity;
    connectivity.reserve(static_cast<std::size_t>(count * block.node_count));
    for (const std::int64_t cell : block.cells) {
      for (const std::int64_t node : ExodusNodes(cells, cell)) connectivity.push_back(node + 1);
    }
    if (Exodus().ex_put_conn(exoid, EX_ELEM_BLOCK, block.id, connectivity.data(), nullptr,
                             nullptr) < 0) {
      return ExodusError(absl::StrCat(where, ": cannot write the connectivity"));
    }
    if (attribute_count > 0) {
      if (Exodus().ex_put_attr(exoid, EX_ELEM_BLOCK, block.id, kept->attributes.data()) < 0) {
        return ExodusError(absl::StrCat(where, ": cannot write the attributes"));
      }
      if (static_cast<std::int64_t>(kept->attribute_names.size()) == attribute_count &&
          WithNames(kept->attribute_names, [&](char** names) {
            return Exodus().ex_put_attr_names(exoid, EX_ELEM_BLOCK, block.id, names);
          }) < 0) {
        return ExodusError(absl::StrCat(where, ": cannot write the attribute names"));
      }
    }
    block_names.push_back(block.name);
  }
  if (WithNames(block_names, [&](char** names) {
        return Exodus().ex_put_names(exoid, EX_ELEM_BLOCK, names);
      }) < 0) {
    return ExodusError("cannot write the element block names");
  }

  if (!plan.side_sets.empty()) {
    std::vector<std::string> names;
    for (const PlannedSideSet& set : plan.side_sets) {
      const ExodusSideSet& source = *set.source;
      const std::string where = SetName("side set", source.id, source.name);
      const std::int64_t count = static_cast<std::int64_t>(set.elements.size());
      const bool keep_factors = count == static_cast<std::int64_t>(source.elements.size()) &&
                                !source.distribution_factors.empty();
      const std::int64_t factors =
          keep_factors ? static_cast<std::int64_t>(source.distribution_factors.size()) : 0;
      if (Exodus().ex_put_set_param(exoid, EX_SIDE_SET, source.id, count, factors) < 0) {
        return ExodusError(where);
      }
      if (count > 0 && Exodus().ex_put_set(exoid, EX_SIDE_SET, source.id, set.elements.data(),
                                           set.sides.data()) < 0) {
        return ExodusError(absl::StrCat(where, ": cannot write its sides"));
      }
      if (factors > 0 && Exodus().ex_put_set_dist_fact(exoid, EX_SIDE_SET, source.id,
                                                       source.distribution_factors.data()) < 0) {
        return ExodusError(absl::StrCat(where, ": cannot write its distribution factors"));
      }
      names.push_back(source.name);
    }
    if (WithNames(names, [&](char** list) {
          return Exodus().ex_put_names(exoid, EX_SIDE_SET, list);
        }) < 0) {
      return ExodusError("cannot write the side set names");
    }
  }

  if (!plan.node_sets.empty()) {
    std::vector<std::string> names;
    for (const ExodusNodeSet* set : plan.node_sets) {
      const std::string where = SetName("node set", set->id, set->name);
      const std::int64_t count = static_cast<std::int64_t>(set->nodes.size());
      const std::int64_t factors = static_cast<std::int64_t>(set->distribution_factors.size());
      if (Exodus().ex_put_set_param(exoid, EX_NODE_SET, set->id, count, factors) < 0) {
        return ExodusError(where);
      }
      std::vector<std::int64_t> nodes(set->nodes);
      for (std::int64_t& node : nodes) ++node;
      if (count > 0 &&
          Exodus().ex_put_set(exoid, EX_NODE_SET, set->id, nodes.data(), nullptr) < 0) {
        return ExodusError(absl::StrCat(where, ": cannot write its nodes"));
      }
      if (factors > 0 && Exodus().ex_put_set_dist_fact(exoid, EX_NODE_SET, set->id,
                                                       set->distribution_factors.data()) < 0) {
        return ExodusError(absl::StrCat(where, ": cannot write its distribution factors"));
      }
      names.push_back(set->name);
    }
    if (WithNames(names, [&](char** list) {
          return Exodus().ex_put_names(exoid, EX_NODE_SET, list);
        }) < 0) {
      return ExodusError("cannot write the node set names");
    }
  }

  if (absl::Status status = WriteElementVariables(exoid, plan); !status.ok()) return status;

  if (document.exodus.has_value()) {
    const std::vector<std::int64_t>& nodes = document.exodus->node_number_map;
    if (static_cast<std::int64_t>(nodes.size()) == point_count &&
        Exodus().ex_put_id_map(exoid, EX_NODE_MAP, nodes.data()) < 0) {
      return ExodusError("cannot write the node number map");
    }
    const std::vector<std::int64_t>& elements = document.exodus->element_number_map;
    if (static_cast<std::int64_t>(elements.size()) == plan.element_count && !plan.reordered &&
        Exodus().ex_put_id_map(exoid, EX_ELEM_MAP, elements.data()) < 0) {
      return ExodusError("cannot write the element number map");
    }
  }
  return absl::OkStatus();
}

}  // namespace

absl::Status WriteExodus(const std::string& path, const MeshDocument& document,
                         const WriteOptions& /*options: Exodus files are binary only*/) {
  absl::StatusOr<Plan> plan = PlanFile(document);
  if (!plan.ok()) return plan.status();
  PlanElementVariables(document, &*plan);
  WarnAboutUnwritten(document, *plan);
  constexpr std::int64_t kInt32Max = std::numeric_limits<std::int32_t>::max();
  const bool int64_db =
      document.grid.point_count() >= kInt32Max || plan->element_count >= kInt32Max;
  std::unique_lock<std::mutex> lock = LockExodusLibrary();
  absl::StatusOr<ExodusFile> file = ExodusFile::Create(path, int64_db);
  if (!file.ok()) return file.status();
  if (absl::Status status = WritePlan(file->id(), document, *plan); !status.ok()) return status;
  return file->Close();
}

void WarnExodusNodeSetsNotWritten(const MeshDocument& document, FileFormat format) {
  if (format == FileFormat::kExodus || !document.exodus.has_value() ||
      document.exodus->node_sets.empty()) {
    return;
  }
  spdlog::warn("Exodus node sets not written (no place for them in this format): {}",
               absl::StrJoin(document.exodus->node_sets, ", ",
                             [](std::string* out, const ExodusNodeSet& set) {
                               absl::StrAppend(out, set.name.empty() ? "(unnamed)" : set.name, " (",
                                               set.id, ")");
                             }));
}

absl::StatusOr<std::string> SerializeExodus(const MeshDocument& document,
                                            const WriteOptions& options) {
  absl::StatusOr<TemporaryFile> file = TemporaryFile::Create(".exo");
  if (!file.ok()) return file.status();
  if (absl::Status status = WriteExodus(file->path(), document, options); !status.ok()) {
    return status;
  }
  return ReadFileBytes(file->path());
}

}  // namespace getme::formats
