// The sequential substep's stops before the polish (issue 14, item 2; sequential_smoother.h) on
// shared meshes whose picks show them: a working set far smaller than the mesh
// (cub_wedge_like.vtk), and a worst element no pick can change (tire.vtk).

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <vector>

#include "getme/mesh/mesh_quality.h"
#include "getme/parallel/thread_pool.h"
#include "getme/smoothing/smoother.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

struct SequentialRun {
  SmoothingResult result;
  std::vector<ProgressEvent> events;  // the sequential substep's, one per pick
};

SequentialRun RunRecordingPicks(Mesh& mesh, SmoothingParams params) {
  params.threads = 2;
  params.sequential_cycle = 1;
  SequentialRun run;
  auto result = Smooth(mesh, params, [&](const ProgressEvent& event) {
    if (!event.phase_done && event.phase == Phase::kSequential) run.events.push_back(event);
  });
  EXPECT_TRUE(result.ok()) << result.status();
  if (result.ok()) run.result = *result;
  return run;
}

// cub_wedge_like.vtk has 112,393 elements, and its picks cycle among a few hundred of them. The
// default window (8 picks per distinct element picked, at least 1,000, at most elements / 4)
// stops far sooner after the best q_min's last rise than the mesh-sized window, and hands on the
// same best q_min.
TEST(SequentialStopSharedTest, WindowFollowsTheWorkingSetNotTheMeshSize) {
  Mesh mesh = testing::LoadSharedMesh("cub_wedge_like.vtk");
  const std::int64_t mesh_window = mesh.element_count() / 4;
  const SequentialRun run = RunRecordingPicks(mesh, SmoothingParams{});
  ASSERT_FALSE(run.events.empty());
  ASSERT_EQ(run.events.back().iteration, run.result.iterations_sequential);
  ASSERT_GE(run.result.phases.size(), 2u);

  // The sliding rule's last rise by the tolerance, recomputed from the events.
  const double tolerance = SmoothingParams{}.sequential_improvement_tolerance;
  double best = run.result.phases[0].q_min;
  double risen = best;
  std::int64_t risen_pick = 0;
  for (const ProgressEvent& event : run.events) {
    best = std::max(best, event.q_min);
    if (best - risen >= tolerance) {
      risen = best;
      risen_pick = event.iteration;
    }
  }
  const std::int64_t stalled_for = run.result.iterations_sequential - risen_pick;
  EXPECT_GT(risen_pick, 0);
  EXPECT_GE(stalled_for, 1000) << "the window is at least 1,000 picks";
  EXPECT_LT(stalled_for, mesh_window / 2) << "elements / 4 is " << mesh_window;
  EXPECT_EQ(run.result.phases[1].q_min, best) << "the best state is handed on";

  // The mesh-sized window, asked for explicitly, runs its whole length after that rise and finds
  // no better state.
  Mesh again = testing::LoadSharedMesh("cub_wedge_like.vtk");
  SmoothingParams mesh_sized;
  mesh_sized.sequential_handoff_window = mesh_window;
  const SequentialRun longer = RunRecordingPicks(again, mesh_sized);
  EXPECT_GE(longer.result.iterations_sequential, risen_pick + mesh_window);
  EXPECT_EQ(longer.result.phases[1].q_min, run.result.phases[1].q_min);
}

// tire.vtk's worst element after smoothing has only boundary (fixed) nodes. Once the mesh's
// minimum is that element's quality, no pick can give a new best state, so the substep stops at
// that pick rather than a window later.
TEST(SequentialStopSharedTest, StopsWhereTheMinimumIsAnElementNoPickMoves) {
  Mesh mesh = testing::LoadSharedMesh("tire.vtk");
  const SmoothingParams params;
  const std::vector<NodeId> immovable = testing::ImmovableNodes(mesh, params);
  std::vector<std::uint8_t> fixed(mesh.node_count(), 0);
  for (NodeId node : immovable) fixed[node] = 1;
  ThreadPool pool(1);
  const std::vector<double> quality = ComputeElementQualities(mesh, pool);
  double pinned = std::numeric_limits<double>::infinity();
  for (ElementId e = 0; e < mesh.element_count(); ++e) {
    const auto nodes = mesh.element_nodes(e);
    if (std::all_of(nodes.begin(), nodes.end(), [&](NodeId n) { return fixed[n] != 0; })) {
      pinned = std::min(pinned, quality[e]);
    }
  }
  ASSERT_LT(pinned, 1.0) << "tire.vtk has elements with every node on the boundary";

  const SequentialRun run = RunRecordingPicks(mesh, params);
  ASSERT_FALSE(run.events.empty());
  ASSERT_LT(run.result.phases[0].q_min, pinned);
  std::int64_t reached = -1;
  for (const ProgressEvent& event : run.events) {
    if (event.q_min >= pinned) {
      reached = event.iteration;
      break;
    }
  }
  EXPECT_EQ(run.result.iterations_sequential, reached);
  EXPECT_LT(run.result.iterations_sequential, 1000) << "before any window could end";
  EXPECT_EQ(run.result.phases[1].q_min, pinned);
  EXPECT_EQ(run.result.after.q_min, pinned);
}

}  // namespace
}  // namespace getme
