// The simultaneous substep hands on its best-q_mean state, not the last one
// (docs/paper-notes.md#simultaneous-stop-rule). The engine keeps that state without copying the
// mesh after every improving iteration, so the test checks it against an independent run stopped
// at the best iteration.

#include <gtest/gtest.h>

#include <vector>

#include "getme/meshgen/hybrid_block.h"
#include "getme/smoothing/smoother.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

SmoothingParams FixedIterations(std::int64_t iterations) {
  SmoothingParams params;
  params.method = Method::kSimultaneous;
  params.simultaneous_tolerance = 0.0;  // run every iteration
  params.simultaneous_max_iterations = iterations;
  params.threads = 2;
  return params;
}

TEST(BestStateTest, HandsOnTheBestIterationsCoordinatesWhenQMeanDipsAfterIt) {
  auto mesh = meshgen::HybridBlock(5, 5, 5, 0.3, 7);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const Mesh original = *mesh;
  std::vector<double> q_means;
  auto result = Smooth(*mesh, FixedIterations(60), [&](const ProgressEvent& event) {
    if (!event.phase_done) q_means.push_back(event.q_mean);
  });
  ASSERT_TRUE(result.ok()) << result.status();
  ASSERT_EQ(q_means.size(), 60u);
  std::size_t best = 0;
  for (std::size_t i = 1; i < q_means.size(); ++i) {
    if (q_means[i] > q_means[best]) best = i;
  }
  // Not vacuous: the best iteration is neither the first nor the last, and q_mean fell after it.
  ASSERT_GT(best, 0u);
  ASSERT_LT(q_means.back(), q_means[best]);

  EXPECT_EQ(result->after.q_mean, q_means[best]);
  Mesh stopped_at_best = original;
  auto reference = Smooth(stopped_at_best, FixedIterations(static_cast<std::int64_t>(best) + 1));
  ASSERT_TRUE(reference.ok()) << reference.status();
  EXPECT_TRUE(testing::CoordinateSnapshot(*mesh) == testing::CoordinateSnapshot(stopped_at_best));
}

}  // namespace
}  // namespace getme
