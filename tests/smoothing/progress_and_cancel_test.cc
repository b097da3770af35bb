#include <gtest/gtest.h>

#include "getme/meshgen/hybrid_block.h"
#include "getme/smoothing/smoother.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

Mesh ProgressTestMesh() {
  auto mesh = meshgen::HybridBlock(8, 8, 6, 0.3, 21);
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  return std::move(*mesh);
}

TEST(ProgressTest, OneEventPerIterationThenAFinalEventPerPhase) {
  Mesh mesh = ProgressTestMesh();
  SmoothingParams params;
  params.sequential_cycle = 500;
  std::vector<ProgressEvent> events;
  auto result = Smooth(mesh, params, [&](const ProgressEvent& event) { events.push_back(event); });
  ASSERT_TRUE(result.ok()) << result.status();

  std::vector<ProgressEvent> simultaneous, sequential, polish;
  for (const ProgressEvent& event : events) {
    switch (event.phase) {
      case Phase::kSimultaneous:
        simultaneous.push_back(event);
        break;
      case Phase::kSequential:
        sequential.push_back(event);
        break;
      case Phase::kPolish:
        polish.push_back(event);
        break;
      default:
        ADD_FAILURE() << "unexpected phase " << PhaseName(event.phase);
    }
  }
  ASSERT_EQ(events.size(), simultaneous.size() + sequential.size() + polish.size());
  // Phases in order: all simultaneous events come before the sequential ones.
  ASSERT_FALSE(simultaneous.empty());
  ASSERT_FALSE(sequential.empty());
  EXPECT_EQ(events[simultaneous.size() - 1].phase, Phase::kSimultaneous);
  EXPECT_TRUE(events[simultaneous.size() - 1].phase_done);

  // Simultaneous: iterations 1, 2, ..., n, then the phase-done event for the handed-on state.
  const std::int64_t n = result->iterations_simultaneous;
  ASSERT_EQ(static_cast<std::int64_t>(simultaneous.size()), n + 1);
  for (std::int64_t i = 0; i < n; ++i) {
    EXPECT_EQ(simultaneous[i].iteration, i + 1);
    EXPECT_FALSE(simultaneous[i].phase_done);
  }
  EXPECT_EQ(simultaneous.back().iteration, n);
  EXPECT_EQ(simultaneous.back().q_mean, result->phases[0].q_mean);

  // Sequential: one event per cycle of picks, the last one marked done and matching the result.
  for (std::size_t i = 0; i + 1 < sequential.size(); ++i) {
    EXPECT_FALSE(sequential[i].phase_done);
    EXPECT_LT(sequential[i].iteration, sequential[i + 1].iteration + (i + 2 == sequential.size()));
  }
  EXPECT_EQ(sequential[0].iteration, 500);
  EXPECT_TRUE(sequential.back().phase_done);
  EXPECT_EQ(sequential.back().iteration, result->iterations_sequential);
  EXPECT_EQ(sequential.back().q_min, result->phases[1].q_min);
  EXPECT_EQ(sequential.back().q_mean, result->phases[1].q_mean);
  // Sequential events all come before the polish's.
  EXPECT_EQ(events[simultaneous.size() + sequential.size() - 1].phase, Phase::kSequential);

  // Polish: sweeps 1, 2, ..., n, then the phase-done event whose state is the result.
  const std::int64_t sweeps = result->iterations_polish;
  ASSERT_GE(sweeps, 1);
  ASSERT_EQ(static_cast<std::int64_t>(polish.size()), sweeps + 1);
  for (std::int64_t i = 0; i < sweeps; ++i) {
    EXPECT_EQ(polish[i].iteration, i + 1);
    EXPECT_FALSE(polish[i].phase_done);
  }
  EXPECT_TRUE(polish.back().phase_done);
  EXPECT_EQ(polish.back().q_min, result->after.q_min);
  EXPECT_EQ(polish.back().q_mean, result->after.q_mean);
  ASSERT_EQ(result->phases.size(), 3u);
  EXPECT_EQ(result->phases[2].phase, Phase::kPolish);
  EXPECT_EQ(result->phases[2].iterations, sweeps);

  for (std::size_t i = 1; i < events.size(); ++i) {
    EXPECT_GE(events[i].elapsed_seconds, events[i - 1].elapsed_seconds);
  }
}

TEST(CancelTest, CancellingDuringSimultaneousStopsWithinOneIteration) {
  Mesh mesh = ProgressTestMesh();
  CancellationToken cancel;
  std::int64_t last_iteration = 0;
  auto result = Smooth(
      mesh, SmoothingParams{},
      [&](const ProgressEvent& event) {
        if (event.phase_done) return;
        last_iteration = event.iteration;
        if (event.iteration == 3) cancel.Cancel();
      },
      &cancel);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.status().code(), absl::StatusCode::kCancelled);
  EXPECT_EQ(last_iteration, 3);
  EXPECT_EQ(testing::CountInvalid(mesh), 0);
}

TEST(CancelTest, CancellingDuringSequentialStopsWithinOneCycle) {
  Mesh mesh = ProgressTestMesh();
  CancellationToken cancel;
  SmoothingParams params;
  params.sequential_cycle = 200;
  std::int64_t sequential_events = 0;
  auto result = Smooth(
      mesh, params,
      [&](const ProgressEvent& event) {
        if (event.phase == Phase::kSequential && !event.phase_done) {
          ++sequential_events;
          cancel.Cancel();
        }
      },
      &cancel);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.status().code(), absl::StatusCode::kCancelled);
  EXPECT_EQ(sequential_events, 1);
  EXPECT_EQ(testing::CountInvalid(mesh), 0);
}

TEST(ParamsTest, InvalidParametersAreRefusedNamingTheField) {
  Mesh mesh = ProgressTestMesh();
  const testing::CoordinateSnapshot before(mesh);
  SmoothingParams params;
  params.simultaneous_rho = 1.5;
  auto result = Smooth(mesh, params);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(result.status().message().find("simultaneous_rho"), std::string::npos)
      << result.status();
  EXPECT_TRUE(testing::CoordinateSnapshot(mesh) == before);

  params = SmoothingParams{};
  params.sequential_sigma[TypeIndex(ElementType::kPrism)] = -1.0;
  result = Smooth(mesh, params);
  ASSERT_FALSE(result.ok());
  EXPECT_NE(result.status().message().find("sequential_sigma[prism]"), std::string::npos)
      << result.status();
}

}  // namespace
}  // namespace getme
