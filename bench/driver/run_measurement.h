#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "getme/smoothing/progress.h"
#include "getme/smoothing/smoother.h"
#include "getme/smoothing/smoothing_params.h"

namespace getme::bench {

enum class RunMode { kInProcess, kService };

const char* RunModeName(RunMode mode);

// One smoothing run, as the driver saw it.
struct RunMeasurement {
  SmoothingResult result;
  // Every progress event, in order. elapsed_seconds is the engine's clock (it starts after the
  // initial quality evaluation); through the service, intermediate events are throttled by the
  // server's --progress_interval.
  std::vector<ProgressEvent> trace;
  // The driver's clock around the whole call: in-process, Smooth() including its thread pool
  // and the quality evaluations before and after; through the service, also the wire
  // conversion, upload, queueing, the server's mesh build, progress streaming and download.
  double wall_seconds = 0.0;
  std::optional<double> seconds_to_99_percent_gain;  // engine clock; none if q_mean did not rise
  std::optional<double> seconds_to_target;           // engine clock; none if never reached
  std::int64_t peak_rss_bytes = 0;                   // this process during the run
  bool peak_rss_reset = false;  // false: the peak may include the mesh loading before the run
  std::optional<std::int64_t> server_peak_rss_bytes;  // service: the server process, if known
  std::optional<double> first_event_wall_seconds;     // service: first progress event, client clock
};

// The repeats of one (mesh, method, threads, mode).
struct Measurement {
  std::string mesh;
  Method method = Method::kGetme;
  int threads = 1;
  RunMode mode = RunMode::kInProcess;
  std::optional<double> target_q_mean;
  // Further `getme smooth` options the runs used ("--free-boundary --max-iterations 50"), so a
  // run can be repeated with `getme smooth IN OUT --method M --threads T <these>`.
  std::string smoothing_options;
  std::vector<RunMeasurement> repeats;
  std::string error;  // why a repeat failed (then `repeats` is empty)
};

struct Spread {
  double median = 0.0;
  double min = 0.0;
  double max = 0.0;
};

// Median (mean of the middle two for an even count), min and max; all 0 for no values.
Spread SpreadOf(std::vector<double> values);

// The repeat whose wall time is the (lower) median: its trace stands for the measurement.
std::size_t MedianRepeat(const Measurement& measurement);

// Whether every repeat ended with the same q_min and q_mean (the engine is deterministic, so
// anything else is a finding worth printing).
bool RepeatsAgree(const Measurement& measurement);

}  // namespace getme::bench
