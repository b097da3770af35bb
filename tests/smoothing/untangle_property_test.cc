// The node-local Newton untangler (core/getme/smoothing/untangle.h) on randomly tangled meshes:
// a valid hybrid block (all four element types) whose interior nodes are thrown about far enough
// to invert many elements. Untangling alone must leave no invalid element and every boundary node
// bit-identical, the whole default run must succeed, and any thread count must give the same bits.

#include <gtest/gtest.h>

#include <random>

#include "getme/meshgen/hybrid_block.h"
#include "getme/parallel/thread_pool.h"
#include "getme/smoothing/smoother.h"
#include "getme/smoothing/smoothing_context.h"
#include "getme/smoothing/untangle.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

// HybridBlock(n, n, n) with every interior node moved by up to `amplitude` (unit cubes) per axis.
absl::StatusOr<Mesh> TangledHybridBlock(int n, double amplitude, std::uint64_t seed) {
  absl::StatusOr<Mesh> mesh = meshgen::HybridBlock(n, n, n, 0.2, seed);
  if (!mesh.ok()) return mesh;
  std::mt19937_64 random(seed * 7919 + 1);
  std::uniform_real_distribution<double> offset(-amplitude, amplitude);
  for (NodeId node = 0; node < mesh->node_count(); ++node) {
    if (mesh->is_boundary(node)) continue;
    mesh->x()[node] += offset(random);
    mesh->y()[node] += offset(random);
    mesh->z()[node] += offset(random);
  }
  return mesh;
}

struct UntangleRun {
  absl::StatusOr<PhaseSummary> summary;
  testing::CoordinateSnapshot coordinates;
};

UntangleRun UntangleOnly(Mesh& mesh, int threads) {
  SmoothingParams params;
  params.threads = threads;
  ThreadPool pool(threads);
  const ProgressCallback no_progress;
  SmoothingContext context(mesh, params, pool, no_progress, nullptr);
  absl::StatusOr<PhaseSummary> summary = RunUntangle(context);
  return {summary, testing::CoordinateSnapshot(mesh)};
}

class RandomlyTangledTest : public ::testing::TestWithParam<std::uint64_t> {};

TEST_P(RandomlyTangledTest, UntanglesWithTheBoundaryFixed) {
  absl::StatusOr<Mesh> mesh = TangledHybridBlock(6, 0.7, GetParam());
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const std::int64_t invalid_before = testing::CountInvalid(*mesh);
  // Not vacuous: the displacement inverts a good share of the elements.
  ASSERT_GT(invalid_before, mesh->element_count() / 20);
  const std::vector<NodeId> boundary = testing::ImmovableNodes(*mesh, SmoothingParams{});
  ASSERT_FALSE(boundary.empty());
  const testing::CoordinateSnapshot before(*mesh);

  const UntangleRun run = UntangleOnly(*mesh, 2);
  ASSERT_TRUE(run.summary.ok()) << run.summary.status() << " (" << invalid_before
                                << " invalid before)";
  EXPECT_EQ(testing::CountInvalid(*mesh), 0);
  EXPECT_GT(run.summary->iterations, 0);
  EXPECT_LE(run.summary->iterations, SmoothingParams{}.untangle_max_iterations);
  for (NodeId node : boundary) {
    ASSERT_EQ(run.coordinates.x[node], before.x[node]) << node;
    ASSERT_EQ(run.coordinates.y[node], before.y[node]) << node;
    ASSERT_EQ(run.coordinates.z[node], before.z[node]) << node;
  }

  // The whole default run from the tangled input: untangling, then GETMe, then the result check.
  absl::StatusOr<Mesh> again = TangledHybridBlock(6, 0.7, GetParam());
  ASSERT_TRUE(again.ok());
  auto result = Smooth(*again, SmoothingParams{});
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->before.invalid, invalid_before);
  EXPECT_EQ(result->after.invalid, 0);
  EXPECT_GT(result->after.q_min, 0.0);
}

INSTANTIATE_TEST_SUITE_P(Seeds, RandomlyTangledTest, ::testing::Values(1, 2, 3, 4, 5, 6));

TEST(UntangleDeterminismTest, SameBitsForOneTwoAndThreeThreads) {
  // Large enough that a colour spans several ParallelFor chunks.
  constexpr int kCells = 10;
  std::vector<UntangleRun> runs;
  for (int threads : {1, 2, 3}) {
    absl::StatusOr<Mesh> mesh = TangledHybridBlock(kCells, 0.45, 11);
    ASSERT_TRUE(mesh.ok()) << mesh.status();
    ASSERT_GT(testing::CountInvalid(*mesh), 0);
    runs.push_back(UntangleOnly(*mesh, threads));
    ASSERT_TRUE(runs.back().summary.ok()) << runs.back().summary.status();
    EXPECT_EQ(testing::CountInvalid(*mesh), 0);
  }
  absl::StatusOr<Mesh> original = TangledHybridBlock(kCells, 0.45, 11);
  ASSERT_TRUE(original.ok());
  EXPECT_FALSE(testing::CoordinateSnapshot(*original) == runs[0].coordinates);
  for (std::size_t i = 1; i < runs.size(); ++i) {
    EXPECT_TRUE(runs[i].coordinates == runs[0].coordinates) << "run " << i;
    EXPECT_EQ(runs[i].summary->iterations, runs[0].summary->iterations);
  }

  // And through Smooth(): untangling followed by GETMe.
  SmoothingParams params;
  params.simultaneous_max_iterations = 15;
  params.sequential_max_iterations = 3000;
  const std::vector<testing::ThreadCountRun> smoothed = testing::SmoothAtThreadCounts(
      [] { return TangledHybridBlock(kCells, 0.45, 11); }, params, {1, 2, 3});
  ASSERT_EQ(smoothed.size(), 3u);
  testing::ExpectSameForEveryThreadCount(smoothed, {1, 2, 3});
  for (const testing::ThreadCountRun& run : smoothed) {
    EXPECT_EQ(run.result.iterations_untangle, smoothed[0].result.iterations_untangle);
    EXPECT_GT(run.result.iterations_untangle, 0);
  }
}

}  // namespace
}  // namespace getme
