#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace getme::wire {

// What the wire carries beside a mesh's geometry and connectivity: the caller's ids of nodes and
// elements (Mesh.node_ids / element_ids; empty means the 0-based index) and the fixed-node list
// as it was sent. A job keeps these with its engine mesh, so results name what the caller named
// and echo the topology unchanged.
struct WireMeshIds {
  std::vector<std::uint64_t> node_ids;
  std::vector<std::uint64_t> element_ids;
  std::vector<std::uint32_t> fixed_nodes;

  // The caller's id of an engine element (element_ids when given, else its number).
  std::uint64_t ElementId(std::int64_t element) const;
  // "node 4" or "node 4 (id 1004)".
  std::string NodeLabel(std::int64_t node) const;
  // Element labels of error messages: "wedge 0 (element 3)" or "wedge 0 (element 3, id 103)".
  std::string ElementLabel(const char* type_name, std::int64_t index_in_type,
                           std::int64_t element) const;
};

}  // namespace getme::wire
