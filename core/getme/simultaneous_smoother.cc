#include "getme/simultaneous_smoother.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "getme/simultaneous_iteration.h"

namespace getme {
namespace {

struct Coordinates {
  std::vector<double> x, y, z;

  void CopyFrom(const Mesh& mesh) {
    x.assign(mesh.x().begin(), mesh.x().end());
    y.assign(mesh.y().begin(), mesh.y().end());
    z.assign(mesh.z().begin(), mesh.z().end());
  }
  void CopyTo(Mesh& mesh) const {
    std::copy(x.begin(), x.end(), mesh.x().begin());
    std::copy(y.begin(), y.end(), mesh.y().begin());
    std::copy(z.begin(), z.end(), mesh.z().begin());
  }
};

}  // namespace

absl::StatusOr<PhaseSummary> RunSimultaneous(SmoothingContext& context) {
  Mesh& mesh = context.mesh;
  const SmoothingParams& params = context.params;
  const double phase_start = context.ElapsedSeconds();
  SimultaneousIteration step(mesh);
  Coordinates best_position;

  SmoothingContext::Summary current = context.Summarize();
  PhaseSummary summary{Phase::kSimultaneous, 0, 0.0, current.q_min, current.q_mean, 0};
  double best_q_mean = current.q_mean;
  std::int64_t best_iteration = 0;
  best_position.CopyFrom(mesh);
  bool cancelled = false;

  for (std::int64_t iteration = 1; iteration <= params.simultaneous_max_iterations; ++iteration) {
    if (context.Cancelled()) {
      cancelled = true;
      break;
    }
    const SimultaneousIteration::Outcome outcome = step.Run(context);
    summary.reverted_nodes += outcome.reverted_nodes;

    const double previous_q_mean = current.q_mean;
    current = outcome.summary;
    summary.iterations = iteration;
    if (current.q_mean > best_q_mean) {
      best_q_mean = current.q_mean;
      best_iteration = iteration;
      best_position.CopyFrom(mesh);
    }
    const bool converged =
        std::abs(current.q_mean - previous_q_mean) < params.simultaneous_tolerance;
    const bool last = converged || iteration == params.simultaneous_max_iterations;
    context.Report({Phase::kSimultaneous, iteration, current.q_min, current.q_mean, current.invalid,
                    outcome.reverted_nodes, context.ElapsedSeconds(), false});
    if (last) break;
  }

  // Hand on the best-q_mean state, not merely the last one (NOTES.md §5).
  if (best_iteration != summary.iterations) {
    best_position.CopyTo(mesh);
    context.RefreshQuality();
    current = context.Summarize();
  }
  context.FinishPhase(summary, current, phase_start);
  if (cancelled) return absl::CancelledError("smoothing cancelled during the simultaneous substep");
  return summary;
}

}  // namespace getme
