#include "in_process_run.h"

#include <chrono>

#include "getme/smoothing/smoother.h"
#include "peak_memory.h"
#include "quality_trace.h"

namespace getme::bench {

void DeriveTraceTimes(RunMeasurement& run, std::optional<double> target_q_mean) {
  const double before = run.result.before.q_mean;
  run.seconds_to_99_percent_gain =
      TimeToGainFraction(run.trace, before, run.result.after.q_mean, 0.99);
  if (target_q_mean.has_value()) {
    run.seconds_to_target = TimeToReach(run.trace, before, *target_q_mean);
  }
}

absl::StatusOr<RunMeasurement> RunInProcess(BenchmarkMesh& mesh, const SmoothingParams& params,
                                            std::optional<double> target_q_mean) {
  mesh.RestoreInitialCoordinates();
  RunMeasurement run;
  run.trace.reserve(4096);  // appending during the run should not reallocate in the hot phase
  run.peak_rss_reset = ResetPeakRss();
  const auto start = std::chrono::steady_clock::now();
  absl::StatusOr<SmoothingResult> result =
      Smooth(mesh.mesh, params, [&run](const ProgressEvent& event) { run.trace.push_back(event); });
  run.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.peak_rss_bytes = PeakRssBytes();
  if (!result.ok()) return result.status();
  run.result = *std::move(result);
  DeriveTraceTimes(run, target_q_mean);
  return run;
}

}  // namespace getme::bench
