// The polish stage (core/getme/smoothing/polish.h, issue 14 item 1), through Smooth(): on random
// valid meshes it never lowers q_min below what GETMe handed it, never inverts an element, leaves
// fixed nodes where they are, raises q_mean on distorted meshes, and gives bit-identical
// coordinates for every thread count. With the polish off (--no-polish, --literal, the other
// methods) the paper's algorithms run unchanged: the other smoothing tests cover that.

#include <gtest/gtest.h>

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

// GETMe cut short, so the polish works on a mesh that is still distorted, and a polish of many
// sweeps: the property must hold wherever the stage starts.
SmoothingParams ShortGetme(bool polish, bool fix_boundary) {
  SmoothingParams params;
  params.threads = 2;
  params.simultaneous_max_iterations = 3;
  params.sequential_max_iterations = 200;
  params.fix_boundary = fix_boundary;
  params.polish = polish;
  params.polish_max_sweeps = 20;
  return params;
}

TEST(PolishTest, NeverLowersQMinNeverInvertsKeepsFixedNodesAndRaisesQMean) {
  for (const testing::NamedMesh& named : testing::DistortedBlocks(6, {3, 17, 29})) {
    for (bool fix_boundary : {true, false}) {
      SCOPED_TRACE(named.name + (fix_boundary ? " fixed boundary" : " free boundary"));
      auto without = named.make();
      auto with = named.make();
      ASSERT_TRUE(without.ok() && with.ok());
      testing::FixSomeInteriorNodes(*without);
      testing::FixSomeInteriorNodes(*with);
      const testing::CoordinateSnapshot original(*with);
      auto plain = Smooth(*without, ShortGetme(false, fix_boundary));
      auto polished = Smooth(*with, ShortGetme(true, fix_boundary));
      ASSERT_TRUE(plain.ok()) << plain.status();
      ASSERT_TRUE(polished.ok()) << polished.status();
      EXPECT_EQ(plain->iterations_polish, 0);
      EXPECT_GE(polished->iterations_polish, 1);
      // The same phases ran before the polish (deterministic), so `plain` is the state the polish
      // started from.
      EXPECT_GE(polished->after.q_min, plain->after.q_min);
      EXPECT_GT(polished->after.q_mean, plain->after.q_mean + 1e-3);
      EXPECT_EQ(polished->after.invalid, 0);
      EXPECT_EQ(testing::CountInvalid(*with), 0);
      testing::ExpectUnmoved(original, *with,
                             testing::ImmovableNodes(*with, ShortGetme(true, fix_boundary)));
    }
  }
}

TEST(PolishTest, PolishAfterFullGetmeKeepsQMinAndRaisesQMean) {
  auto mesh = meshgen::HybridBlock(8, 8, 6, 0.3, 13);
  ASSERT_TRUE(mesh.ok());
  SmoothingParams params;
  params.threads = 2;
  auto polished = Smooth(*mesh, params);
  ASSERT_TRUE(polished.ok()) << polished.status();
  // With the polish on, the substeps before it stop by the hand-on rules, so a run without it is
  // not its starting state: the sequential substep's summary is.
  ASSERT_EQ(polished->phases.size(), 3u);
  const PhaseSummary& handed_on = polished->phases[1];
  ASSERT_EQ(handed_on.phase, Phase::kSequential);
  ASSERT_EQ(polished->phases[2].phase, Phase::kPolish);
  EXPECT_GE(polished->after.q_min, handed_on.q_min);
  EXPECT_GT(polished->after.q_mean, handed_on.q_mean + 1e-3);
  EXPECT_EQ(testing::CountInvalid(*mesh), 0);
}

TEST(PolishTest, WorstElementStageEndsWhenItsFirstSweepLowersQMin) {
  // On this block the worst-element stage's first sweep lowers q_min below what the sequential
  // substep handed on (checked first, from the events). The stage must then end after that one
  // sweep and hand the sequential substep's state on unchanged: the run equals a run without the
  // stage in every coordinate, one sweep longer.
  SmoothingParams params;
  params.threads = 2;
  auto with_stage = meshgen::HybridBlock(8, 8, 6, 0.3, 13);
  auto without_stage = meshgen::HybridBlock(8, 8, 6, 0.3, 13);
  ASSERT_TRUE(with_stage.ok() && without_stage.ok());
  std::vector<ProgressEvent> events;
  auto result = Smooth(*with_stage, params, [&](const ProgressEvent& event) {
    if (!event.phase_done) events.push_back(event);
  });
  ASSERT_TRUE(result.ok()) << result.status();
  double handed_on_q_min = -1.0;
  double first_sweep_q_min = -1.0;
  for (const ProgressEvent& event : events) {
    if (event.phase == Phase::kSequential) handed_on_q_min = event.q_min;
    if (event.phase == Phase::kPolish && event.iteration == 1) first_sweep_q_min = event.q_min;
  }
  ASSERT_GE(first_sweep_q_min, 0.0);
  ASSERT_LT(first_sweep_q_min, handed_on_q_min);

  params.polish_worst_exponent = 0.0;
  auto plain = Smooth(*without_stage, params);
  ASSERT_TRUE(plain.ok()) << plain.status();
  EXPECT_EQ(result->iterations_polish, plain->iterations_polish + 1);
  EXPECT_TRUE(testing::CoordinateSnapshot(*with_stage) ==
              testing::CoordinateSnapshot(*without_stage));
  EXPECT_EQ(result->after.q_min, plain->after.q_min);
  EXPECT_EQ(result->after.q_mean, plain->after.q_mean);
}

TEST(PolishTest, WorstElementStageIsSkippedWhereTheMinimumIsPinned) {
  // An element of middling quality has all its nodes fixed; GETMe lifts every worse element up to
  // it, so the polish starts with q_min equal to that element's quality, which no step can change.
  // The worst-element stage, whose goal is q_min, must not run: the run equals a run without the
  // stage in every coordinate and in its sweep count.
  auto with_stage = meshgen::HybridBlock(8, 8, 6, 0.3, 31);
  auto without_stage = meshgen::HybridBlock(8, 8, 6, 0.3, 31);
  ASSERT_TRUE(with_stage.ok() && without_stage.ok());
  const double pinned_quality = testing::PinElementOfQualityAtLeast(*with_stage, 0.4);
  ASSERT_EQ(testing::PinElementOfQualityAtLeast(*without_stage, 0.4), pinned_quality);
  SmoothingParams params;
  params.threads = 2;
  auto result = Smooth(*with_stage, params);
  ASSERT_TRUE(result.ok()) << result.status();
  ASSERT_GE(result->phases.size(), 3u);
  ASSERT_EQ(result->phases[1].q_min, pinned_quality) << "the polish starts at the pinned minimum";

  params.polish_worst_exponent = 0.0;
  auto plain = Smooth(*without_stage, params);
  ASSERT_TRUE(plain.ok()) << plain.status();
  EXPECT_EQ(result->iterations_polish, plain->iterations_polish);
  EXPECT_TRUE(testing::CoordinateSnapshot(*with_stage) ==
              testing::CoordinateSnapshot(*without_stage));
  EXPECT_EQ(result->after.q_min, pinned_quality);
}

// The mean stage stops at polish_final_tolerance where its end is the result, and runs on to
// polish_tolerance where the worst-cluster stage starts from it (polish.cc, RunPolish).
TEST(PolishTest, MeanStageStopsAtTheFinalToleranceWhereNoClusterStageFollows) {
  struct Run {
    SmoothingResult result;
    testing::CoordinateSnapshot coordinates;
  };
  auto run = [](double cluster_trigger, double tolerance, double final_tolerance) {
    auto mesh = meshgen::HybridBlock(8, 8, 6, 0.3, 13);
    EXPECT_TRUE(mesh.ok());
    SmoothingParams params;
    params.threads = 2;
    params.polish_cluster_trigger = cluster_trigger;
    params.polish_tolerance = tolerance;
    params.polish_final_tolerance = final_tolerance;
    auto result = Smooth(*mesh, params);
    EXPECT_TRUE(result.ok()) << result.status();
    return Run{*result, testing::CoordinateSnapshot(*mesh)};
  };
  const SmoothingParams defaults;
  // No cluster stage: polish_tolerance plays no part, polish_final_tolerance stops the stage.
  const Run loose = run(0.0, defaults.polish_tolerance, defaults.polish_final_tolerance);
  const Run tight_unused = run(0.0, 1e-12, defaults.polish_final_tolerance);
  const Run tight = run(0.0, defaults.polish_tolerance, 1e-12);
  EXPECT_TRUE(loose.coordinates == tight_unused.coordinates);
  EXPECT_EQ(loose.result.iterations_polish, tight_unused.result.iterations_polish);
  EXPECT_LT(loose.result.iterations_polish, tight.result.iterations_polish);
  EXPECT_GE(tight.result.after.q_mean, loose.result.after.q_mean);
  // What the looser rule gives up is what it predicted: less than its tolerance.
  EXPECT_LT(tight.result.after.q_mean - loose.result.after.q_mean, defaults.polish_final_tolerance);

  // A cluster stage that may follow (trigger 1: any worst element with a free node): the mean
  // stage before it runs to polish_tolerance, so that tolerance now changes the result (were the
  // stage stopped by polish_final_tolerance, the same in both runs, they would be the same bits).
  ASSERT_LT(loose.result.after.q_min, loose.result.after.q_mean);
  const Run before_cluster = run(1.0, defaults.polish_tolerance, 1e-12);
  const Run before_cluster_tight = run(1.0, 1e-12, 1e-12);
  EXPECT_FALSE(before_cluster.coordinates == before_cluster_tight.coordinates);
}

TEST(PolishTest, OnlyGetmePolishes) {
  for (Method method :
       {Method::kSimultaneous, Method::kSequential, Method::kWarpage, Method::kSmartLaplace}) {
    auto without = meshgen::HybridBlock(5, 5, 4, 0.3, 5);
    auto with = meshgen::HybridBlock(5, 5, 4, 0.3, 5);
    ASSERT_TRUE(without.ok() && with.ok());
    SmoothingParams params = ShortGetme(false, true);
    params.method = method;
    ASSERT_TRUE(Smooth(*without, params).ok());
    params.polish = true;
    auto result = Smooth(*with, params);
    ASSERT_TRUE(result.ok()) << result.status();
    EXPECT_EQ(result->iterations_polish, 0) << MethodName(method);
    EXPECT_TRUE(testing::CoordinateSnapshot(*with) == testing::CoordinateSnapshot(*without))
        << MethodName(method);
  }
}

TEST(PolishTest, SameCoordinatesForAnyThreadCount) {
  const std::vector<testing::ThreadCountRun> runs = testing::SmoothAtThreadCounts(
      [] { return meshgen::HybridBlock(10, 10, 8, 0.3, 7); }, ShortGetme(true, true), {1, 2, 3});
  ASSERT_EQ(runs.size(), 3u);
  testing::ExpectSameForEveryThreadCount(runs, {1, 2, 3});
  for (std::size_t i = 1; i < runs.size(); ++i) {
    EXPECT_EQ(runs[i].result.iterations_polish, runs[0].result.iterations_polish);
  }
  // The polish did move nodes, so the comparison is not vacuous.
  auto unpolished = meshgen::HybridBlock(10, 10, 8, 0.3, 7);
  ASSERT_TRUE(unpolished.ok());
  SmoothingParams params = ShortGetme(false, true);
  params.threads = 1;
  ASSERT_TRUE(Smooth(*unpolished, params).ok());
  EXPECT_FALSE(testing::CoordinateSnapshot(*unpolished) == runs[0].coordinates);
}

TEST(PolishTest, CancelledBeforeThePolishLeavesAValidMesh) {
  auto mesh = meshgen::HybridBlock(6, 6, 5, 0.3, 9);
  ASSERT_TRUE(mesh.ok());
  CancellationToken cancel;
  SmoothingParams params = ShortGetme(true, true);
  // Cancel at the sequential substep's final event, i.e. just before the polish starts.
  auto result = Smooth(
      *mesh, params,
      [&](const ProgressEvent& event) {
        if (event.phase == Phase::kSequential && event.phase_done) cancel.Cancel();
      },
      &cancel);
  EXPECT_EQ(result.status().code(), absl::StatusCode::kCancelled) << result.status();
  EXPECT_NE(result.status().message().find("polish"), std::string::npos) << result.status();
  EXPECT_EQ(testing::CountInvalid(*mesh), 0);
}

TEST(PolishTest, ParametersAreValidated) {
  SmoothingParams params;
  EXPECT_TRUE(params.polish);  // on by default for Method::kGetme (issue 14)
  params.UseLiteralPaperAlgorithm();
  EXPECT_FALSE(params.polish);  // not part of the paper

  // Each out-of-range value is refused with its field's name.
  struct BadValue {
    const char* field;
    std::function<void(SmoothingParams&)> set;
  };
  const std::vector<BadValue> bad = {
      {"polish_node_tolerance", [](SmoothingParams& p) { p.polish_node_tolerance = -1.0; }},
      {"simultaneous_handoff_window",
       [](SmoothingParams& p) { p.simultaneous_handoff_window = -1; }},
      {"polish_worst_exponent", [](SmoothingParams& p) { p.polish_worst_exponent = 40.0; }},
      {"polish_over_relaxation", [](SmoothingParams& p) { p.polish_over_relaxation = 2.0; }},
      {"sequential_handoff_window", [](SmoothingParams& p) { p.sequential_handoff_window = -1; }},
      {"simultaneous_handoff_gain", [](SmoothingParams& p) { p.simultaneous_handoff_gain = -1.0; }},
      {"polish_tolerance", [](SmoothingParams& p) { p.polish_tolerance = -1.0; }},
      {"polish_final_tolerance", [](SmoothingParams& p) { p.polish_final_tolerance = -1.0; }},
      {"polish_max_sweeps", [](SmoothingParams& p) { p.polish_max_sweeps = -1; }},
      {"polish_backtracking_steps", [](SmoothingParams& p) { p.polish_backtracking_steps = 31; }},
      {"polish_cluster_trigger", [](SmoothingParams& p) { p.polish_cluster_trigger = -0.1; }},
      {"polish_cluster_band", [](SmoothingParams& p) { p.polish_cluster_band = -1.0; }},
      {"polish_cluster_exponent", [](SmoothingParams& p) { p.polish_cluster_exponent = 65.0; }},
      {"polish_cluster_exponent", [](SmoothingParams& p) { p.polish_cluster_exponent = 0.5; }},
      {"polish_cluster_tolerance", [](SmoothingParams& p) { p.polish_cluster_tolerance = -1e-3; }},
      {"polish_cluster_max_rounds", [](SmoothingParams& p) { p.polish_cluster_max_rounds = -1; }},
      {"polish_cluster_iterations", [](SmoothingParams& p) { p.polish_cluster_iterations = -1; }},
      {"polish_cluster_ascent_iterations",
       [](SmoothingParams& p) { p.polish_cluster_ascent_iterations = -1; }},
  };
  for (const BadValue& value : bad) {
    SmoothingParams changed;
    value.set(changed);
    const absl::Status status = changed.Validate();
    EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument) << value.field;
    EXPECT_NE(status.message().find(value.field), std::string::npos) << value.field;
  }
  params = SmoothingParams();
  params.polish_backtracking_steps = 0;
  EXPECT_TRUE(params.Validate().ok());
}

}  // namespace
}  // namespace getme
