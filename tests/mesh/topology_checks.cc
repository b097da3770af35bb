#include "topology_checks.h"

#include <gtest/gtest.h>

#include <vector>

#include "reference_topology.h"

namespace getme::mesh_test {
namespace {

std::vector<std::int64_t> ToVector(std::span<const std::int32_t> row) {
  return {row.begin(), row.end()};
}

}  // namespace

void ExpectTopologyMatchesReference(const Mesh& mesh, const MeshSpec& spec) {
  const ReferenceTopology reference = ComputeReferenceTopology(spec);
  const auto node_count = static_cast<std::int64_t>(spec.nodes.size());
  const auto element_count = static_cast<std::int64_t>(spec.elements.size());
  ASSERT_EQ(mesh.node_count(), node_count);
  ASSERT_EQ(mesh.element_count(), element_count);

  std::vector<std::int64_t> seen_per_type(kElementTypeCount, 0);
  for (std::int64_t e = 0; e < element_count; ++e) {
    const auto id = static_cast<ElementId>(e);
    const ElementType type = spec.elements[e].type;
    EXPECT_EQ(mesh.type(id), type) << "element " << e;
    EXPECT_EQ(mesh.block_index(id), seen_per_type[TypeIndex(type)]) << "element " << e;
    EXPECT_EQ(mesh.block(type).elements[seen_per_type[TypeIndex(type)]], id) << "element " << e;
    ++seen_per_type[TypeIndex(type)];
    EXPECT_EQ(ToVector(mesh.element_nodes(id)), spec.elements[e].nodes) << "element " << e;
    EXPECT_EQ(ToVector(mesh.element_neighbours(id)), reference.element_neighbours[e])
        << "element " << e;
  }

  for (std::int64_t node = 0; node < node_count; ++node) {
    const auto id = static_cast<NodeId>(node);
    EXPECT_EQ(ToVector(mesh.node_elements(id)), reference.node_elements[node]) << "node " << node;
    EXPECT_EQ(mesh.is_boundary(id), reference.boundary[node]) << "node " << node;
    EXPECT_EQ(mesh.boundary_flags()[node] != 0, reference.boundary[node]) << "node " << node;
  }
  EXPECT_EQ(mesh.boundary_face_count(), reference.boundary_face_count);
}

}  // namespace getme::mesh_test
