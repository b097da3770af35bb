// Batches of sequential picks (issue 16, item 1; sequential_smoother.cc): a batch's picks are
// independent, so a batched run is the same for every thread count (thread_determinism_test.cc,
// and ThreadSanitizer would see two picks of a batch touching one node); here, what a batch
// changes against the paper's one pick at a time, and when there are no batches at all.

#include <gtest/gtest.h>

#include "getme/meshgen/hybrid_block.h"
#include "getme/smoothing/smoother.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

struct BlockRun {
  testing::CoordinateSnapshot coordinates;
  SmoothingResult result;
};

BlockRun SmoothBlock(const SmoothingParams& params, int cubes, std::uint64_t seed) {
  auto mesh = meshgen::HybridBlock(cubes, cubes, cubes, 0.3, seed);
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  auto result = Smooth(*mesh, params);
  EXPECT_TRUE(result.ok()) << result.status();
  return {testing::CoordinateSnapshot(*mesh), *result};
}

// The measure: a batched run's q_min is within 1 % of the one-at-a-time run's (or above
// it). The sequential substep alone, then the default run with the polish after it.
class BatchedQualityTest : public ::testing::TestWithParam<Method> {};

TEST_P(BatchedQualityTest, QMinWithinOnePercentOfOnePickAtATime) {
  for (std::uint64_t seed : {3, 4}) {
    SmoothingParams serial;
    serial.method = GetParam();
    serial.threads = 2;
    serial.sequential_batch = 1;
    SmoothingParams batched = serial;
    batched.sequential_batch = 64;
    batched.sequential_batch_elements = 64;  // batches of up to 64 picks on this small mesh
    const BlockRun one = SmoothBlock(serial, 14, seed);
    const BlockRun many = SmoothBlock(batched, 14, seed);
    EXPECT_GE(many.result.after.q_min, 0.99 * one.result.after.q_min) << "seed " << seed;
    EXPECT_EQ(many.result.after.invalid, 0);
    // The batches did change the run: it is not the serial one under another name.
    EXPECT_FALSE(many.coordinates == one.coordinates) << "seed " << seed;
  }
}

INSTANTIATE_TEST_SUITE_P(SequentialAndDefault, BatchedQualityTest,
                         ::testing::Values(Method::kSequential, Method::kGetme),
                         [](const auto& info) { return std::string(MethodName(info.param)); });

// Below 16 × sequential_batch_elements there is one pick per batch: the default run is then the
// serial algorithm's, bit for bit, on the meshes where batches would not pay.
TEST(SequentialBatchTest, SmallMeshIsSmoothedOnePickAtATime) {
  SmoothingParams defaults;
  defaults.threads = 2;
  SmoothingParams serial = defaults;
  serial.sequential_batch = 1;
  const BlockRun with_default = SmoothBlock(defaults, 12, 5);
  const BlockRun one_at_a_time = SmoothBlock(serial, 12, 5);
  ASSERT_LT(with_default.result.after.elements, 16 * defaults.sequential_batch_elements);
  EXPECT_TRUE(with_default.coordinates == one_at_a_time.coordinates);
  EXPECT_EQ(with_default.result.iterations_sequential, one_at_a_time.result.iterations_sequential);
  // With 15 picks' worth of elements per batch still one at a time; with 16, batches.
  SmoothingParams fifteen = defaults;
  fifteen.sequential_batch_elements = with_default.result.after.elements / 15;
  EXPECT_TRUE(SmoothBlock(fifteen, 12, 5).coordinates == one_at_a_time.coordinates);
  SmoothingParams sixteen = defaults;
  sixteen.sequential_batch_elements = with_default.result.after.elements / 16;
  EXPECT_FALSE(SmoothBlock(sixteen, 12, 5).coordinates == one_at_a_time.coordinates);
}

// With no band, a batch takes only the elements tied at the lowest key (and the blockers of the
// last batch): the run still smooths, validly, the same for any thread count.
TEST(SequentialBatchTest, ZeroBandStillSmoothsTheSameForAnyThreadCount) {
  SmoothingParams params;
  params.method = Method::kSequential;
  params.sequential_batch_elements = 64;
  params.sequential_batch_band = 0.0;
  params.sequential_max_iterations = 4000;
  const auto runs = testing::SmoothAtThreadCounts(
      [] { return meshgen::HybridBlock(10, 10, 10, 0.3, 9); }, params, {1, 3});
  ASSERT_EQ(runs.size(), 2u);
  testing::ExpectSameForEveryThreadCount(runs, {1, 3});
  EXPECT_GT(runs[0].result.after.q_min, runs[0].result.before.q_min);
  EXPECT_EQ(runs[0].result.after.invalid, 0);
}

}  // namespace
}  // namespace getme
