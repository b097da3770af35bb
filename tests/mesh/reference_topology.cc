#include "reference_topology.h"

#include <algorithm>
#include <set>

namespace getme::mesh_test {

const std::vector<std::vector<int>>& ReferenceFaces(ElementType type) {
  static const std::vector<std::vector<int>> kTet = {{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  static const std::vector<std::vector<int>> kHex = {{0, 1, 2, 3}, {0, 1, 5, 4}, {1, 2, 6, 5},
                                                     {2, 3, 7, 6}, {3, 0, 4, 7}, {4, 7, 6, 5}};
  static const std::vector<std::vector<int>> kPyramid = {
      {0, 1, 2, 3}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  static const std::vector<std::vector<int>> kPrism = {
      {0, 1, 2}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}, {3, 5, 4}};
  switch (type) {
    case ElementType::kTetrahedron:
      return kTet;
    case ElementType::kHexahedron:
      return kHex;
    case ElementType::kPyramid:
      return kPyramid;
    case ElementType::kPrism:
      break;
  }
  return kPrism;
}

ReferenceTopology ComputeReferenceTopology(const MeshSpec& spec) {
  const auto node_count = static_cast<std::int64_t>(spec.nodes.size());
  const auto element_count = static_cast<std::int64_t>(spec.elements.size());
  ReferenceTopology topology;
  // The engine's canonical element order: by type (tet, hex, pyramid, prism), then by id.
  std::vector<std::int64_t> canonical(element_count);
  for (std::int64_t e = 0; e < element_count; ++e) canonical[e] = e;
  std::stable_sort(canonical.begin(), canonical.end(), [&](std::int64_t a, std::int64_t b) {
    return static_cast<int>(spec.elements[a].type) < static_cast<int>(spec.elements[b].type);
  });

  topology.node_elements.resize(node_count);
  for (std::int64_t node = 0; node < node_count; ++node) {
    for (std::int64_t e : canonical) {
      const auto& nodes = spec.elements[e].nodes;
      if (std::find(nodes.begin(), nodes.end(), node) != nodes.end()) {
        topology.node_elements[node].push_back(e);
      }
    }
  }

  topology.element_neighbours.resize(element_count);
  for (std::int64_t e = 0; e < element_count; ++e) {
    const std::set<std::int64_t> mine(spec.elements[e].nodes.begin(), spec.elements[e].nodes.end());
    for (std::int64_t other : canonical) {
      if (other == e) continue;
      for (std::int64_t node : spec.elements[other].nodes) {
        if (mine.count(node) != 0) {
          topology.element_neighbours[e].push_back(other);
          break;
        }
      }
    }
  }

  std::vector<std::set<std::int64_t>> faces;
  for (const ElementSpec& element : spec.elements) {
    for (const std::vector<int>& face : ReferenceFaces(element.type)) {
      std::set<std::int64_t> ids;
      for (int local : face) ids.insert(element.nodes[local]);
      faces.push_back(ids);
    }
  }
  topology.boundary.assign(node_count, false);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto uses = std::count(faces.begin(), faces.end(), faces[f]);
    if (uses != 1) continue;
    ++topology.boundary_face_count;
    for (std::int64_t node : faces[f]) topology.boundary[node] = true;
  }
  return topology;
}

}  // namespace getme::mesh_test
