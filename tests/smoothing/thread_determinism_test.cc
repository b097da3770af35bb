// Results must be bit-identical for any thread count (the simultaneous substep sums each node's
// contributions in a fixed corner order; reductions use fixed chunks).

#include <gtest/gtest.h>

#include "getme/meshgen/hybrid_block.h"
#include "getme/smoothing/smoother.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

class ThreadDeterminismTest : public ::testing::TestWithParam<Method> {};

TEST_P(ThreadDeterminismTest, SameCoordinatesForAnyThreadCount) {
  std::vector<testing::CoordinateSnapshot> results;
  std::vector<SmoothingResult> reports;
  for (int threads : {1, 2, 3, 4}) {
    auto mesh = meshgen::HybridBlock(10, 10, 8, 0.3, 7);
    ASSERT_TRUE(mesh.ok()) << mesh.status();
    SmoothingParams params;
    params.method = GetParam();
    params.threads = threads;
    params.simultaneous_max_iterations = 15;
    params.sequential_max_iterations = 3000;
    auto result = Smooth(*mesh, params);
    ASSERT_TRUE(result.ok()) << result.status();
    EXPECT_EQ(result->threads, threads);
    results.emplace_back(*mesh);
    reports.push_back(*result);
  }
  for (std::size_t i = 1; i < results.size(); ++i) {
    EXPECT_TRUE(results[i] == results[0]) << "threads " << i + 1 << " differ from 1 thread";
    EXPECT_EQ(reports[i].after.q_mean, reports[0].after.q_mean);
    EXPECT_EQ(reports[i].after.q_min, reports[0].after.q_min);
    EXPECT_EQ(reports[i].iterations_simultaneous, reports[0].iterations_simultaneous);
    EXPECT_EQ(reports[i].iterations_sequential, reports[0].iterations_sequential);
  }
  // The smoothing did move nodes, so the comparison is not vacuous.
  auto original = meshgen::HybridBlock(10, 10, 8, 0.3, 7);
  ASSERT_TRUE(original.ok());
  EXPECT_FALSE(testing::CoordinateSnapshot(*original) == results[0]);
}

INSTANTIATE_TEST_SUITE_P(Methods, ThreadDeterminismTest,
                         ::testing::Values(Method::kSimultaneous, Method::kGetme, Method::kLaplace),
                         [](const auto& info) {
                           std::string name = MethodName(info.param);
                           for (char& c : name) {
                             if (c == '-') c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace getme
