// A whole run gives the same mesh, bit for bit, whatever vector width its element passes use
// (SmoothingParams::kernel_lanes: the reference 2 lanes, 4 with AVX2, 8 with AVX-512; issue 16,
// item 2), and reports the width it used. A width the machine cannot run is refused, never
// narrowed silently.

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "getme/meshgen/hybrid_block.h"
#include "getme/smoothing/element_passes_dispatch.h"
#include "getme/smoothing/smoother.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

class KernelLanesTest : public ::testing::TestWithParam<Method> {};

TEST_P(KernelLanesTest, EveryWidthGivesTheReferenceMesh) {
  SmoothingParams params;
  params.method = GetParam();
  params.simultaneous_max_iterations = 20;
  params.threads = 2;
  struct WidthRun {
    int lanes;
    testing::CoordinateSnapshot coordinates;
    SmoothingResult result;
  };
  std::vector<WidthRun> runs;
  for (int lanes : SupportedLaneWidths()) {
    absl::StatusOr<Mesh> mesh = meshgen::HybridBlock(9, 9, 7, 0.3, 11);
    ASSERT_TRUE(mesh.ok()) << mesh.status();
    params.kernel_lanes = lanes;
    absl::StatusOr<SmoothingResult> result = Smooth(*mesh, params);
    ASSERT_TRUE(result.ok()) << lanes << " lanes: " << result.status();
    EXPECT_EQ(result->kernel_lanes, lanes);
    runs.push_back({lanes, testing::CoordinateSnapshot(*mesh), *std::move(result)});
  }
  ASSERT_FALSE(runs.empty());
  ASSERT_EQ(runs[0].lanes, 2);
  for (const WidthRun& run : runs) {
    EXPECT_TRUE(run.coordinates == runs[0].coordinates) << run.lanes << " lanes differ from 2";
    EXPECT_EQ(run.result.after.q_min, runs[0].result.after.q_min) << run.lanes << " lanes";
    EXPECT_EQ(run.result.after.q_mean, runs[0].result.after.q_mean) << run.lanes << " lanes";
    EXPECT_EQ(run.result.iterations_simultaneous, runs[0].result.iterations_simultaneous);
  }
  // The run moved nodes, so the comparison is not vacuous.
  absl::StatusOr<Mesh> original = meshgen::HybridBlock(9, 9, 7, 0.3, 11);
  ASSERT_TRUE(original.ok());
  EXPECT_FALSE(testing::CoordinateSnapshot(*original) == runs[0].coordinates);
  EXPECT_GT(runs[0].result.iterations_simultaneous, 0);
}

INSTANTIATE_TEST_SUITE_P(Methods, KernelLanesTest,
                         ::testing::Values(Method::kSimultaneous, Method::kGetme),
                         [](const auto& info) { return MethodName(info.param); });

TEST(KernelLanesDefaultTest, ZeroRunsTheWidestThisMachineRuns) {
  absl::StatusOr<Mesh> mesh = meshgen::HybridBlock(4, 4, 3, 0.3, 5);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  SmoothingParams params;
  params.method = Method::kSimultaneous;
  params.simultaneous_max_iterations = 2;
  absl::StatusOr<SmoothingResult> result = Smooth(*mesh, params);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->kernel_lanes, SupportedLaneWidths().back());
}

TEST(KernelLanesDefaultTest, AWidthThisMachineCannotRunIsFailedPrecondition) {
  const std::vector<int> widths = SupportedLaneWidths();
  int refused = 0;
  for (int lanes : {4, 8}) {
    if (std::find(widths.begin(), widths.end(), lanes) != widths.end()) continue;
    absl::StatusOr<Mesh> mesh = meshgen::HybridBlock(4, 4, 3, 0.3, 5);
    ASSERT_TRUE(mesh.ok()) << mesh.status();
    const testing::CoordinateSnapshot before(*mesh);
    SmoothingParams params;
    params.kernel_lanes = lanes;
    absl::StatusOr<SmoothingResult> result = Smooth(*mesh, params);
    EXPECT_EQ(result.status().code(), absl::StatusCode::kFailedPrecondition) << result.status();
    EXPECT_TRUE(testing::CoordinateSnapshot(*mesh) == before);  // refused before any step
    ++refused;
  }
  if (refused == 0) GTEST_SKIP() << "this machine runs every width (2, 4 and 8 lanes)";
}

}  // namespace
}  // namespace getme
