#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "absl/status/statusor.h"

namespace getme::cli {

// One progress event of a recorded trace (the JSON lines of `getme smooth --json / --trace`).
struct TracePoint {
  std::string phase;
  std::int64_t iteration = 0;
  double q_min = 0.0;
  double q_mean = 0.0;
  double elapsed_seconds = 0.0;
  bool phase_done = false;
};

// The progress events of a trace in file order. Lines of other events ("result", "error") are
// skipped; a line that is not JSON, or a progress event missing a field, is InvalidArgument
// naming the path and line.
absl::StatusOr<std::vector<TracePoint>> ReadTrace(const std::string& path);

}  // namespace getme::cli
