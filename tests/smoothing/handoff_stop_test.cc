// The stop rules the substeps use when the polish follows (issue 14, item 2;
// simultaneous_smoother.h, sequential_smoother.h), re-computed from the progress events: each
// substep must stop exactly where its rule says, not earlier and not later. With the polish off
// the paper's rule alone applies and runs longer.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "getme/meshgen/hybrid_block.h"
#include "getme/smoothing/smoother.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

Mesh TestMesh() {
  auto mesh = meshgen::HybridBlock(8, 8, 6, 0.3, 31);
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  return std::move(*mesh);
}

struct RecordedRun {
  SmoothingResult result;
  std::vector<ProgressEvent> events;  // without the phase-done events

  std::vector<ProgressEvent> Of(Phase phase) const {
    std::vector<ProgressEvent> selected;
    for (const ProgressEvent& event : events) {
      if (event.phase == phase) selected.push_back(event);
    }
    return selected;
  }
};

RecordedRun SmoothRecording(const SmoothingParams& params) {
  Mesh mesh = TestMesh();
  RecordedRun run;
  auto result = Smooth(mesh, params, [&](const ProgressEvent& event) {
    if (!event.phase_done) run.events.push_back(event);
  });
  EXPECT_TRUE(result.ok()) << result.status();
  if (result.ok()) run.result = *result;
  return run;
}

TEST(HandOnStopTest, SimultaneousStopsAtTheFirstIterationWhoseWindowGainIsTooSmall) {
  SmoothingParams params;
  params.threads = 2;
  ASSERT_TRUE(params.polish);
  const RecordedRun run = SmoothRecording(params);
  const std::vector<ProgressEvent> simultaneous = run.Of(Phase::kSimultaneous);
  const auto n = static_cast<std::int64_t>(simultaneous.size());
  ASSERT_EQ(n, run.result.iterations_simultaneous);
  const std::int64_t window = params.simultaneous_handoff_window;
  ASSERT_GT(n, window);  // the windows below are all inside the events
  // q_mean after iteration k is simultaneous[k - 1].q_mean.
  auto stops_at = [&](std::int64_t k) {
    const double q = simultaneous[k - 1].q_mean;
    const bool settled = std::abs(q - simultaneous[k - 2].q_mean) < params.simultaneous_tolerance;
    const bool handed_on =
        k > window && q - simultaneous[k - 1 - window].q_mean <
                          params.simultaneous_handoff_gain * static_cast<double>(window);
    return settled || handed_on;
  };
  for (std::int64_t k = 2; k < n; ++k) EXPECT_FALSE(stops_at(k)) << "iteration " << k;
  EXPECT_TRUE(stops_at(n));

  // The paper's rule alone (no polish) runs on past that point.
  params.polish = false;
  const RecordedRun paper = SmoothRecording(params);
  EXPECT_GT(paper.result.iterations_simultaneous, n);
}

// One pick at a time (the paper's), and batches of independent picks (issue 16): with batches
// the rule is checked after each batch, whose event carries the picks done so far.
class SequentialHandOnTest : public ::testing::TestWithParam<std::int64_t> {};

TEST_P(SequentialHandOnTest, StopsOneWindowAfterTheLastRiseOfTheBestMinimum) {
  SmoothingParams params;
  params.threads = 2;
  params.sequential_batch = GetParam();
  params.sequential_batch_elements = 1;  // batches of sequential_batch picks on this small mesh
  params.sequential_cycle = 1;           // an event per batch, with the mesh's q_min after it
  params.sequential_handoff_window = 300;
  const RecordedRun run = SmoothRecording(params);
  const std::vector<ProgressEvent> sequential = run.Of(Phase::kSequential);
  ASSERT_FALSE(sequential.empty());
  ASSERT_EQ(sequential.back().iteration, run.result.iterations_sequential);
  ASSERT_GE(run.result.phases.size(), 2u);

  // The rule, independently: the best q_min so far (from the state the simultaneous substep
  // handed on) must rise by the tolerance within every window of picks.
  double best = run.result.phases[0].q_min;
  double risen = best;
  std::int64_t risen_pick = 0;
  std::int64_t expected_stop = -1;
  std::int64_t previous_pick = 0;
  for (const ProgressEvent& event : sequential) {
    const std::int64_t pick = event.iteration;
    ASSERT_GT(pick, previous_pick);
    ASSERT_LE(pick - previous_pick, params.sequential_batch) << "a batch has at most this many";
    previous_pick = pick;
    best = std::max(best, event.q_min);
    if (best - risen >= params.sequential_improvement_tolerance) {
      risen = best;
      risen_pick = pick;
    }
    if (pick - risen_pick >= params.sequential_handoff_window) {
      expected_stop = pick;
      break;
    }
  }
  EXPECT_EQ(run.result.iterations_sequential, expected_stop);
  EXPECT_GT(risen_pick, 0);  // q_min did rise: the window was not trivially the first one
  // The state handed on is the best one seen.
  EXPECT_EQ(run.result.phases[1].q_min, best);

  // Without the polish the windows are mesh-sized and taken one after another: more picks.
  params.polish = false;
  params.sequential_cycle = 1000;
  const RecordedRun paper = SmoothRecording(params);
  EXPECT_GT(paper.result.iterations_sequential, run.result.iterations_sequential);
}

// Once the mesh's minimum is an element with no movable node, no pick can give a new best state,
// and the state handed on is the last best one: the substep stops at that pick instead of running
// a window of picks that would all be undone.
TEST(SequentialPinnedMinimumTest, StopsAtThePickThatReachesTheWorstUnmovableElement) {
  // Pin an element of middling quality: GETMe's substeps leave worse ones at first, and the
  // sequential substep lifts them to it.
  Mesh mesh = TestMesh();
  const double pinned = testing::PinElementOfQualityAtLeast(mesh, 0.4);
  ASSERT_GT(pinned, 0.0);

  SmoothingParams params;
  params.threads = 2;
  params.sequential_cycle = 1;
  std::vector<ProgressEvent> sequential;
  auto result = Smooth(mesh, params, [&](const ProgressEvent& event) {
    if (!event.phase_done && event.phase == Phase::kSequential) sequential.push_back(event);
  });
  ASSERT_TRUE(result.ok()) << result.status();
  ASSERT_GE(result->phases.size(), 2u);
  ASSERT_LT(result->phases[0].q_min, pinned) << "the simultaneous substep leaves a worse element";
  // The first pick after which the mesh's minimum is the pinned element's quality.
  std::int64_t reached = -1;
  for (const ProgressEvent& event : sequential) {
    if (event.q_min >= pinned) {
      reached = event.iteration;
      break;
    }
  }
  ASSERT_GT(reached, 0);
  EXPECT_EQ(result->iterations_sequential, reached);
  EXPECT_LT(result->iterations_sequential, 1000) << "before any window could end";
  EXPECT_EQ(result->phases[1].q_min, pinned);
  EXPECT_EQ(result->after.q_min, pinned) << "nothing after the substep moves it either";
}

INSTANTIATE_TEST_SUITE_P(OneAtATimeAndBatches, SequentialHandOnTest, ::testing::Values(1, 64),
                         [](const auto& info) { return "batch" + std::to_string(info.param); });

}  // namespace
}  // namespace getme
