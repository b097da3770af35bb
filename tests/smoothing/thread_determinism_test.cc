// Results must be bit-identical for any thread count (the simultaneous substep sums each node's
// contributions in a fixed corner order; reductions use fixed chunks).

#include <gtest/gtest.h>

#include "getme/meshgen/hybrid_block.h"
#include "getme/smoothing/smoother.h"
#include "shuffled_mesh.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

class ThreadDeterminismTest : public ::testing::TestWithParam<Method> {};

TEST_P(ThreadDeterminismTest, SameCoordinatesForAnyThreadCount) {
  SmoothingParams params;
  params.method = GetParam();
  params.simultaneous_max_iterations = 15;
  params.sequential_max_iterations = 3000;
  params.sequential_batch_elements = 64;  // batches of up to 64 picks on this small mesh
  const std::vector<testing::ThreadCountRun> runs = testing::SmoothAtThreadCounts(
      [] { return meshgen::HybridBlock(10, 10, 8, 0.3, 7); }, params, {1, 2, 3, 4});
  ASSERT_EQ(runs.size(), 4u);
  testing::ExpectSameForEveryThreadCount(runs, {1, 2, 3, 4});
  for (std::size_t i = 1; i < runs.size(); ++i) {
    EXPECT_EQ(runs[i].result.iterations_simultaneous, runs[0].result.iterations_simultaneous);
    EXPECT_EQ(runs[i].result.iterations_sequential, runs[0].result.iterations_sequential);
  }
  // The smoothing did move nodes, so the comparison is not vacuous.
  auto original = meshgen::HybridBlock(10, 10, 8, 0.3, 7);
  ASSERT_TRUE(original.ok());
  EXPECT_FALSE(testing::CoordinateSnapshot(*original) == runs[0].coordinates);
}

// A mesh numbered without locality: the simultaneous substep's tiles follow the Morton order
// (parallel/element_tiles.h), and the result is still the same for every thread count.
TEST(ThreadDeterminismShuffledTest, SameCoordinatesForAnyThreadCount) {
  SmoothingParams params;
  params.method = Method::kSimultaneous;
  params.simultaneous_max_iterations = 15;
  const auto make = [] {
    absl::StatusOr<Mesh> block = meshgen::HybridBlock(10, 10, 8, 0.3, 7);
    if (!block.ok()) return block;
    return absl::StatusOr<Mesh>(mesh_test::Shuffled(*block, 21));
  };
  const std::vector<testing::ThreadCountRun> runs =
      testing::SmoothAtThreadCounts(make, params, {1, 2, 3, 4});
  ASSERT_EQ(runs.size(), 4u);
  testing::ExpectSameForEveryThreadCount(runs, {1, 2, 3, 4});
  const absl::StatusOr<Mesh> original = make();
  ASSERT_TRUE(original.ok());
  EXPECT_FALSE(testing::CoordinateSnapshot(*original) == runs[0].coordinates);
}

INSTANTIATE_TEST_SUITE_P(Methods, ThreadDeterminismTest,
                         // kSequential and kWarpage: batches of sequential picks (issue 16),
                         // selected by q and by q_γ.
                         ::testing::Values(Method::kSimultaneous, Method::kSequential,
                                           Method::kGetme, Method::kWarpage, Method::kLaplace),
                         [](const auto& info) {
                           std::string name = MethodName(info.param);
                           for (char& c : name) {
                             if (c == '-') c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace getme
