#pragma once

#include <cstdint>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// The grid cells (ascending) of a CGNS surface group, named as a boundary condition (BC_t) or a
// family (every condition whose FamilyName is that family): the cells whose "cgns:bc" value is
// such a condition's index. A condition on vertices has no cells (CgnsGroupNodes has its nodes).
// NotFound listing the conditions and families there are when the name matches neither.
absl::StatusOr<std::vector<std::int64_t>> CgnsGroupCells(const MeshDocument& document,
                                                         absl::string_view group);

// The nodes (0-based, ascending, unique) of the same group: its cells' nodes and the nodes of
// its vertex conditions.
absl::StatusOr<std::vector<std::int64_t>> CgnsGroupNodes(const MeshDocument& document,
                                                         absl::string_view group);

}  // namespace getme::formats
