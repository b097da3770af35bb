#include "formats/exodus/exodus_groups.h"

#include <algorithm>
#include <optional>
#include <string>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"

namespace getme::formats {
namespace {

std::vector<std::int64_t> NodesOfCellsWithTag(const UnstructuredGrid& grid, absl::string_view array,
                                              std::int64_t id) {
  std::vector<std::int64_t> nodes;
  const DataArray* tags = FindArray(grid.cell_data, array);
  if (tags == nullptr || tags->components != 1 || tags->tuple_count() != grid.cells.size()) {
    return nodes;
  }
  for (std::int64_t cell = 0; cell < grid.cells.size(); ++cell) {
    if (static_cast<std::int64_t>(tags->AsDouble(cell)) != id) continue;
    nodes.insert(nodes.end(), grid.cells.nodes(cell),
                 grid.cells.nodes(cell) + grid.cells.node_count(cell));
  }
  return nodes;
}

std::vector<std::int64_t> Unique(std::vector<std::int64_t> nodes) {
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

template <typename Entry>
std::string Listed(const std::vector<Entry>& entries) {
  if (entries.empty()) return "none";
  return absl::StrJoin(entries, ", ", [](std::string* out, const Entry& entry) {
    absl::StrAppend(out, entry.name.empty() ? "(unnamed)" : entry.name, " (", entry.id, ")");
  });
}

}  // namespace

absl::StatusOr<std::vector<std::int64_t>> ExodusGroupNodes(const MeshDocument& document,
                                                           absl::string_view group) {
  if (!document.exodus.has_value()) {
    return absl::NotFoundError(absl::StrCat("no group '", group, "': not an Exodus file"));
  }
  const ExodusExtras& extras = *document.exodus;
  std::optional<std::int64_t> number;
  if (std::int64_t value = 0; absl::SimpleAtoi(group, &value)) number = value;
  // Names before ids: a set may be named "2" while another has id 2.
  for (const bool by_name : {true, false}) {
    const auto matches = [&](const std::string& name, std::int64_t id) {
      return by_name ? name == group : number.has_value() && id == *number;
    };
    for (const ExodusNodeSet& set : extras.node_sets) {
      if (matches(set.name, set.id)) return Unique(set.nodes);
    }
    for (const ExodusSideSet& set : extras.side_sets) {
      if (matches(set.name, set.id)) {
        return Unique(NodesOfCellsWithTag(document.grid, "exodus:sideset", set.id));
      }
    }
    for (const ExodusBlock& block : extras.blocks) {
      if (matches(block.name, block.id)) {
        return Unique(NodesOfCellsWithTag(document.grid, "exodus:block", block.id));
      }
    }
  }
  return absl::NotFoundError(absl::StrCat(
      "no node set, side set or element block '", group,
      "' (by name or id); node sets: ", Listed(extras.node_sets),
      "; side sets: ", Listed(extras.side_sets), "; element blocks: ", Listed(extras.blocks)));
}

}  // namespace getme::formats
