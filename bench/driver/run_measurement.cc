#include "run_measurement.h"

#include <algorithm>
#include <numeric>

namespace getme::bench {

const char* RunModeName(RunMode mode) {
  return mode == RunMode::kService ? "service" : "in-process";
}

Spread SpreadOf(std::vector<double> values) {
  if (values.empty()) return {};
  std::ranges::sort(values);
  const std::size_t middle = values.size() / 2;
  const double median =
      values.size() % 2 == 1 ? values[middle] : (values[middle - 1] + values[middle]) / 2.0;
  return {median, values.front(), values.back()};
}

std::size_t MedianRepeat(const Measurement& measurement) {
  std::vector<std::size_t> order(measurement.repeats.size());
  std::iota(order.begin(), order.end(), 0);
  std::ranges::sort(order, [&](std::size_t a, std::size_t b) {
    return measurement.repeats[a].wall_seconds < measurement.repeats[b].wall_seconds;
  });
  return order.empty() ? 0 : order[(order.size() - 1) / 2];
}

bool RepeatsAgree(const Measurement& measurement) {
  for (const RunMeasurement& repeat : measurement.repeats) {
    const MeshQuality& first = measurement.repeats.front().result.after;
    if (repeat.result.after.q_min != first.q_min || repeat.result.after.q_mean != first.q_mean) {
      return false;
    }
  }
  return true;
}

}  // namespace getme::bench
