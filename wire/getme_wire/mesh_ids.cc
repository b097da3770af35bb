#include "getme_wire/mesh_ids.h"

#include "absl/strings/str_cat.h"

namespace getme::wire {

std::uint64_t WireMeshIds::ElementId(std::int64_t element) const {
  if (element >= 0 && element < static_cast<std::int64_t>(element_ids.size())) {
    return element_ids[element];
  }
  return static_cast<std::uint64_t>(element);
}

std::string WireMeshIds::NodeLabel(std::int64_t node) const {
  if (node >= 0 && node < static_cast<std::int64_t>(node_ids.size())) {
    return absl::StrCat("node ", node, " (id ", node_ids[node], ")");
  }
  return absl::StrCat("node ", node);
}

std::string WireMeshIds::ElementLabel(const char* type_name, std::int64_t index_in_type,
                                      std::int64_t element) const {
  std::string label = absl::StrCat(type_name, " ", index_in_type, " (element ", element);
  if (element >= 0 && element < static_cast<std::int64_t>(element_ids.size())) {
    absl::StrAppend(&label, ", id ", element_ids[element]);
  }
  return absl::StrCat(label, ")");
}

}  // namespace getme::wire
