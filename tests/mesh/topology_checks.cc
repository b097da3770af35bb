#include "topology_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "reference_topology.h"

namespace getme::mesh_test {
namespace {

std::vector<std::int64_t> ToVector(std::span<const std::int32_t> row) {
  return {row.begin(), row.end()};
}

// The node a corner stands for, decoded as mesh.h documents it: corner c of type t is
// corner_offset(t) + block_index·NodeCount(t) + k.
NodeId CornerNode(const Mesh& mesh, std::int64_t corner) {
  for (ElementType type : kAllElementTypes) {
    const std::int64_t local = corner - mesh.corner_offset(type);
    const auto corners = static_cast<std::int64_t>(mesh.block(type).nodes.size());
    if (local >= 0 && local < corners) {
      const std::int64_t block_index = local / NodeCount(type);
      const int k = static_cast<int>(local % NodeCount(type));
      return mesh.element_nodes(mesh.block(type).elements[block_index])[k];
    }
  }
  ADD_FAILURE() << "corner " << corner << " lies in no block";
  return -1;
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

  std::int64_t corner_total = 0;
  std::vector<int> corner_uses(mesh.corner_count(), 0);
  for (std::int64_t node = 0; node < node_count; ++node) {
    const auto id = static_cast<NodeId>(node);
    EXPECT_EQ(ToVector(mesh.node_elements(id)), reference.node_elements[node]) << "node " << node;
    EXPECT_EQ(mesh.is_boundary(id), reference.boundary[node]) << "node " << node;
    EXPECT_EQ(mesh.boundary_flags()[node] != 0, reference.boundary[node]) << "node " << node;

    const std::span<const std::int32_t> corners = mesh.node_corners().Row(node);
    EXPECT_EQ(corners.size(), mesh.node_elements(id).size()) << "node " << node;
    EXPECT_TRUE(std::is_sorted(corners.begin(), corners.end())) << "node " << node;
    for (std::int32_t corner : corners) {
      ASSERT_GE(corner, 0);
      ASSERT_LT(corner, mesh.corner_count());
      EXPECT_EQ(CornerNode(mesh, corner), id) << "corner " << corner << " of node " << node;
      ++corner_uses[corner];
    }
    corner_total += static_cast<std::int64_t>(corners.size());
  }
  EXPECT_EQ(mesh.node_corners().RowCount(), node_count);
  EXPECT_EQ(corner_total, mesh.corner_count());
  for (std::int64_t corner = 0; corner < mesh.corner_count(); ++corner) {
    EXPECT_EQ(corner_uses[corner], 1) << "corner " << corner;
  }
  EXPECT_EQ(mesh.boundary_face_count(), reference.boundary_face_count);
}

}  // namespace getme::mesh_test
