#include <gtest/gtest.h>

#include "getme/meshgen/distorted_hex_block.h"
#include "getme/smoothing/smoother.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

TEST(FixedNodesTest, FreeBoundaryMovesBoundaryButNotCallerFixedNodes) {
  auto mesh = meshgen::DistortedHexBlock(6, 6, 6, 0.3, 5);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  std::vector<NodeId> caller_fixed;
  for (NodeId node = 0; node < mesh->node_count(); node += 5) {
    mesh->set_fixed(node, true);
    caller_fixed.push_back(node);
  }
  const testing::CoordinateSnapshot before(*mesh);
  SmoothingParams params;
  params.fix_boundary = false;
  auto result = Smooth(*mesh, params);
  ASSERT_TRUE(result.ok()) << result.status();
  const testing::CoordinateSnapshot after(*mesh);
  for (NodeId node : caller_fixed) {
    EXPECT_EQ(after.x[node], before.x[node]);
    EXPECT_EQ(after.y[node], before.y[node]);
    EXPECT_EQ(after.z[node], before.z[node]);
  }
  std::int64_t moved_boundary = 0;
  for (NodeId node = 0; node < mesh->node_count(); ++node) {
    if (mesh->is_boundary(node) && !mesh->is_fixed(node) &&
        (after.x[node] != before.x[node] || after.y[node] != before.y[node] ||
         after.z[node] != before.z[node])) {
      ++moved_boundary;
    }
  }
  EXPECT_GT(moved_boundary, 0);
  EXPECT_EQ(testing::CountInvalid(*mesh), 0);
}

TEST(FixedNodesTest, AllNodesFixedLeavesTheMeshUnchanged) {
  auto mesh = meshgen::DistortedHexBlock(4, 4, 4, 0.3, 5);
  ASSERT_TRUE(mesh.ok());
  for (NodeId node = 0; node < mesh->node_count(); ++node) mesh->set_fixed(node, true);
  const testing::CoordinateSnapshot before(*mesh);
  auto result = Smooth(*mesh, SmoothingParams{});
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_TRUE(testing::CoordinateSnapshot(*mesh) == before);
  EXPECT_EQ(result->after.q_mean, result->before.q_mean);
}

}  // namespace
}  // namespace getme
