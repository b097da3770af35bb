// Regular elements stay regular: on a grid of unit cubes every element has q = 1, every weight
// (1 − q)^η is 0, so GETMe must not move a single node.

#include <gtest/gtest.h>

#include "getme/meshgen/distorted_hex_block.h"
#include "getme/smoothing/smoother.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

TEST(RegularMeshTest, RegularHexGridIsLeftBitIdentical) {
  auto mesh = meshgen::DistortedHexBlock(5, 4, 3, 0.0, 1);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const testing::CoordinateSnapshot before(*mesh);
  for (Method method : {Method::kGetme, Method::kWarpage, Method::kSmartLaplace}) {
    SmoothingParams params;
    params.method = method;
    auto result = Smooth(*mesh, params);
    ASSERT_TRUE(result.ok()) << result.status();
    EXPECT_EQ(result->before.q_min, 1.0);
    EXPECT_EQ(result->after.q_min, 1.0) << MethodName(method);
    EXPECT_TRUE(testing::CoordinateSnapshot(*mesh) == before) << MethodName(method);
  }
}

TEST(RegularMeshTest, BiasedHexBlockBecomesTheRegularGrid) {
  // Mesquite's 1000hex-block-internal-bias: the ideal answer is the regular grid.
  Mesh mesh = testing::LoadSharedMesh("1000hex-block-internal-bias.vtk");
  auto result = Smooth(mesh, SmoothingParams{});
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_LT(result->before.q_min, 0.4);
  EXPECT_GT(result->after.q_min, 0.999);
  EXPECT_GT(result->after.q_mean, 0.9999);
}

TEST(ScaleInvarianceTest, PowerOfTwoScaledMeshSmoothsToExactlyScaledCoordinates) {
  // Lemma 1 at the mesh level. Scaling by 2^-40 is exact in floating point, and so is every
  // operation of the engine on the scaled mesh: sums, products and quotients scale by powers of
  // two, and the cube root (cube_root.h) works on mantissa and exponent apart, so ∛(2^-240 x) is
  // exactly 2^-80 ∛x. The smoothed coordinates must therefore be exactly the scaled ones.
  Mesh large = testing::LoadSharedMesh("large_box_hex_1000.vtk");
  Mesh scaled = testing::LoadSharedMesh("large_box_hex_1000.vtk");
  constexpr double kScale = 0x1.0p-40;
  for (NodeId node = 0; node < scaled.node_count(); ++node) {
    scaled.x()[node] *= kScale;
    scaled.y()[node] *= kScale;
    scaled.z()[node] *= kScale;
  }
  auto large_result = Smooth(large, SmoothingParams{});
  auto scaled_result = Smooth(scaled, SmoothingParams{});
  ASSERT_TRUE(large_result.ok()) << large_result.status();
  ASSERT_TRUE(scaled_result.ok()) << scaled_result.status();
  EXPECT_EQ(large_result->after.q_mean, scaled_result->after.q_mean);
  EXPECT_EQ(large_result->iterations_simultaneous, scaled_result->iterations_simultaneous);
  EXPECT_EQ(large_result->iterations_sequential, scaled_result->iterations_sequential);
  EXPECT_EQ(large_result->iterations_polish, scaled_result->iterations_polish);
  for (NodeId node = 0; node < large.node_count(); ++node) {
    ASSERT_EQ(large.x()[node] * kScale, scaled.x()[node]) << node;
    ASSERT_EQ(large.y()[node] * kScale, scaled.y()[node]) << node;
    ASSERT_EQ(large.z()[node] * kScale, scaled.z()[node]) << node;
  }
}

TEST(ScaleInvarianceTest, LargeAndSmallBoxesReachTheSameQuality) {
  // The two Mesquite boxes (edge 10,000 and 0.00001, written in single precision, so not exact
  // copies of each other) must smooth alike.
  Mesh large = testing::LoadSharedMesh("large_box_hex_1000.vtk");
  Mesh small = testing::LoadSharedMesh("small_box_hex_1000.vtk");
  auto large_result = Smooth(large, SmoothingParams{});
  auto small_result = Smooth(small, SmoothingParams{});
  ASSERT_TRUE(large_result.ok()) << large_result.status();
  ASSERT_TRUE(small_result.ok()) << small_result.status();
  EXPECT_NEAR(large_result->before.q_mean, small_result->before.q_mean, 1e-3);
  EXPECT_NEAR(large_result->after.q_mean, small_result->after.q_mean, 1e-3);
  EXPECT_GT(small_result->after.q_mean, small_result->before.q_mean);
  EXPECT_GT(large_result->after.q_mean, large_result->before.q_mean);
}

}  // namespace
}  // namespace getme
