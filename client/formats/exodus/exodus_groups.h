#pragma once

#include <cstdint>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// The points (0-based, ascending, no repeats) of an Exodus group of `document` (which has
// ExodusExtras): a node set, a side set (the nodes of its faces) or an element block (the nodes
// of its cells), matched by name first, then by id, in that order of kinds. This is what
// `getme smooth --fix-physical G` holds for an Exodus input. NotFound listing the sets and
// blocks there are.
absl::StatusOr<std::vector<std::int64_t>> ExodusGroupNodes(const MeshDocument& document,
                                                           absl::string_view group);

}  // namespace getme::formats
