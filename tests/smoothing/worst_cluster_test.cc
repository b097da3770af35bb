// The polish's worst-cluster stage (core/getme/smoothing/worst_cluster.h, issue 14 item 3), called
// directly on distorted random meshes: it never lowers q_min, never inverts an element, leaves
// every immovable node where it was, keeps the per-element qualities exact, lifts q_min where the
// worst element has a free node, ends at once where it has none, and gives the same bits for every
// thread count. pinned_artery_test.cc shows what it is for: the coupled plateaus of pinned thin
// layers that node-local steps cannot lift.

#include "getme/smoothing/worst_cluster.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "getme/meshgen/distorted_hex_block.h"
#include "getme/meshgen/hybrid_block.h"
#include "getme/smoothing/smoother.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

struct StageRun {
  SmoothingContext::Summary before;
  SmoothingContext::Summary after;
  PhaseSummary summary{Phase::kPolish, 0, 0.0, 0.0, 0.0, 0};
  std::vector<double> quality;  // context.quality after the stage
  absl::Status status;
};

StageRun RunStage(Mesh& mesh, const SmoothingParams& params, int threads) {
  ThreadPool pool(threads);
  const ProgressCallback no_progress;
  SmoothingContext context(mesh, params, pool, no_progress, nullptr);
  StageRun run;
  run.before = context.Summarize();
  run.after = run.before;
  run.status = RunWorstCluster(context, run.after, run.summary);
  run.quality = context.quality;
  // What the stage hands on must be the state it leaves.
  const SmoothingContext::Summary fresh = context.Summarize();
  EXPECT_EQ(run.after.q_min, fresh.q_min);
  EXPECT_EQ(run.after.q_mean, fresh.q_mean);
  return run;
}

TEST(WorstClusterTest, LiftsQMinNeverInvertsAndKeepsImmovableNodesAndExactQualities) {
  for (const testing::NamedMesh& named : testing::DistortedBlocks(5, {5, 23})) {
    for (bool fix_boundary : {true, false}) {
      SCOPED_TRACE(named.name + (fix_boundary ? " fixed boundary" : " free boundary"));
      auto mesh = named.make();
      ASSERT_TRUE(mesh.ok()) << mesh.status();
      testing::FixSomeInteriorNodes(*mesh);
      SmoothingParams params;
      params.fix_boundary = fix_boundary;
      const testing::CoordinateSnapshot original(*mesh);
      const StageRun run = RunStage(*mesh, params, 2);
      ASSERT_TRUE(run.status.ok()) << run.status;
      ASSERT_EQ(run.before.invalid, 0);
      // Every distorted block's worst element has a free node here, so the stage must lift q_min,
      // not merely keep it.
      EXPECT_GT(run.after.q_min, run.before.q_min);
      EXPECT_GE(run.summary.iterations, 1);
      EXPECT_EQ(testing::CountInvalid(*mesh), 0);
      for (ElementId e = 0; e < mesh->element_count(); ++e) {
        ASSERT_EQ(run.quality[e], ElementQualityOrInvalid(*mesh, e)) << "element " << e;
      }
      testing::ExpectUnmoved(original, *mesh, testing::ImmovableNodes(*mesh, params));
    }
  }
}

TEST(WorstClusterTest, EndsAtOnceWhenTheWorstElementHasNoFreeNode) {
  auto mesh = meshgen::HybridBlock(5, 5, 4, 0.35, 5);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  ElementId worst = 0;
  for (ElementId e = 1; e < mesh->element_count(); ++e) {
    if (ElementQualityOrInvalid(*mesh, e) < ElementQualityOrInvalid(*mesh, worst)) worst = e;
  }
  for (NodeId node : mesh->element_nodes(worst)) mesh->set_fixed(node, true);
  const testing::CoordinateSnapshot original(*mesh);
  const StageRun run = RunStage(*mesh, SmoothingParams{}, 2);
  ASSERT_TRUE(run.status.ok()) << run.status;
  EXPECT_EQ(run.summary.iterations, 0);
  EXPECT_EQ(run.after.q_min, run.before.q_min);
  EXPECT_TRUE(testing::CoordinateSnapshot(*mesh) == original);
}

TEST(WorstClusterTest, SameCoordinatesForEveryThreadCount) {
  std::vector<testing::CoordinateSnapshot> results;
  std::vector<double> q_mins;
  for (int threads : {1, 2, 3}) {
    auto mesh = meshgen::DistortedHexBlock(6, 6, 6, 0.35, 41);
    ASSERT_TRUE(mesh.ok()) << mesh.status();
    const StageRun run = RunStage(*mesh, SmoothingParams{}, threads);
    ASSERT_TRUE(run.status.ok()) << run.status;
    ASSERT_GE(run.summary.iterations, 1) << "the stage must have moved something";
    results.emplace_back(*mesh);
    q_mins.push_back(run.after.q_min);
  }
  for (std::size_t i = 1; i < results.size(); ++i) {
    EXPECT_TRUE(results[i] == results[0]) << "thread count " << i + 1;
    EXPECT_EQ(q_mins[i], q_mins[0]);
  }
}

TEST(WorstClusterTest, TheTriggerDecidesWhetherTheRunUsesIt) {
  // A distorted hexahedral block after a short GETMe and polish: q_min is above a third of q_mean,
  // so the default trigger leaves the stage out; a trigger of 1 (any q_min below q_mean) runs it,
  // which must lift q_min further and keep every element valid.
  SmoothingParams params;
  params.threads = 2;
  params.simultaneous_max_iterations = 3;
  params.sequential_max_iterations = 200;
  params.polish_max_sweeps = 2;
  params.polish_worst_max_sweeps = 2;
  auto by_default = meshgen::DistortedHexBlock(6, 6, 6, 0.35, 41);
  auto triggered = meshgen::DistortedHexBlock(6, 6, 6, 0.35, 41);
  ASSERT_TRUE(by_default.ok() && triggered.ok());
  auto plain = Smooth(*by_default, params);
  ASSERT_TRUE(plain.ok()) << plain.status();
  ASSERT_GE(plain->after.q_min, params.polish_cluster_trigger * plain->after.q_mean);
  params.polish_cluster_trigger = 1.0;
  auto with_stage = Smooth(*triggered, params);
  ASSERT_TRUE(with_stage.ok()) << with_stage.status();
  EXPECT_GT(with_stage->after.q_min, plain->after.q_min);
  EXPECT_GT(with_stage->iterations_polish, plain->iterations_polish);
  EXPECT_EQ(with_stage->after.invalid, 0);
  EXPECT_EQ(testing::CountInvalid(*triggered), 0);
}

}  // namespace
}  // namespace getme
