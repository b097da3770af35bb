#include "quality_trace.h"

namespace getme::bench {

std::optional<double> TimeToReach(std::span<const ProgressEvent> trace, double q_mean_before,
                                  double target) {
  if (q_mean_before >= target) return 0.0;
  for (const ProgressEvent& event : trace) {
    if (event.q_mean >= target) return event.elapsed_seconds;
  }
  return std::nullopt;
}

std::optional<double> TimeToGainFraction(std::span<const ProgressEvent> trace, double q_mean_before,
                                         double q_mean_after, double fraction) {
  if (!(q_mean_after > q_mean_before)) return std::nullopt;
  return TimeToReach(trace, q_mean_before,
                     q_mean_before + fraction * (q_mean_after - q_mean_before));
}

}  // namespace getme::bench
