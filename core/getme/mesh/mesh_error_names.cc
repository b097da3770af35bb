#include "getme/mesh/mesh_error_names.h"

#include "absl/strings/str_cat.h"

namespace getme {

std::string MeshErrorNames::EmptyMesh(std::int64_t nodes, std::int64_t elements) const {
  return absl::StrCat("empty mesh: ", nodes, " nodes and ", elements, " volume elements");
}

std::string MeshErrorNames::NonFiniteCoordinate(std::int64_t node, double x, double y,
                                                double z) const {
  return absl::StrCat("node ", node, " has a non-finite coordinate (", x, ", ", y, ", ", z, ")");
}

std::string MeshErrorNames::FixedNodeOutOfRange(std::int64_t, std::int64_t node,
                                                std::int64_t node_count) const {
  return absl::StrCat("fixed node id ", node, " out of range [0, ", node_count, ")");
}

std::string MeshErrorNames::NodeOutOfRange(std::int64_t element, ElementType type, int position,
                                           std::int64_t node, std::int64_t node_count) const {
  return absl::StrCat("element ", element, " (", TypeName(type), ") node ", position, " has id ",
                      node, ", out of range [0, ", node_count, ")");
}

std::string MeshErrorNames::RepeatedNode(std::int64_t element, ElementType type, std::int64_t node,
                                         int first, int second) const {
  return absl::StrCat("element ", element, " (", TypeName(type), ") uses node ", node,
                      " twice (local nodes ", first, " and ", second, ")");
}

}  // namespace getme
