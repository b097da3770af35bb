#include "getme/smoothing/simultaneous_smoother.h"

#include <cmath>
#include <vector>

#include "getme/smoothing/simultaneous_iteration.h"

namespace getme {

absl::StatusOr<PhaseSummary> RunSimultaneous(SmoothingContext& context, SimultaneousStop stop) {
  Mesh& mesh = context.mesh;
  const SmoothingParams& params = context.params;
  const double phase_start = context.ElapsedSeconds();
  SimultaneousIteration step(mesh);

  SmoothingContext::Summary current = context.Summarize();
  PhaseSummary summary{Phase::kSimultaneous, 0, 0.0, current.q_min, current.q_mean, 0};
  double best_q_mean = current.q_mean;
  // The best state is copied only once an iteration fails to improve on it: until then it is
  // the mesh itself, and one iteration later the step's previous positions (q_mean mostly rises,
  // so copying the mesh after every improvement would cost a full copy per iteration).
  std::int64_t best_iteration = 0;
  NodePositions best_position;
  bool cancelled = false;
  // q_mean after each iteration, index 0 the input: the hand-on rule looks a window back.
  std::vector<double> q_mean_history = {current.q_mean};
  const std::int64_t window = params.simultaneous_handoff_window;

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
    } else if (best_iteration == iteration - 1) {
      best_position = step.previous_positions();
    }
    q_mean_history.push_back(current.q_mean);
    bool converged = std::abs(current.q_mean - previous_q_mean) < params.simultaneous_tolerance;
    if (stop == SimultaneousStop::kHandOnToPolish && window > 0 && iteration >= window) {
      const double gain = current.q_mean - q_mean_history[iteration - window];
      converged |= gain < params.simultaneous_handoff_gain * static_cast<double>(window);
    }
    const bool last = converged || iteration == params.simultaneous_max_iterations;
    context.Report({Phase::kSimultaneous, iteration, current.q_min, current.q_mean, current.invalid,
                    outcome.reverted_nodes, context.ElapsedSeconds(), false});
    if (last) break;
  }

  // Hand on the best-q_mean state, not merely the last one
  // (docs/paper-notes.md#simultaneous-stop-rule).
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
