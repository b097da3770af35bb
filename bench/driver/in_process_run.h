#pragma once

#include <optional>

#include "absl/status/statusor.h"
#include "benchmark_mesh.h"
#include "getme/smoothing/smoothing_params.h"
#include "run_measurement.h"

namespace getme::bench {

// Restores the mesh's initial coordinates, smooths it in this process, and measures the run.
absl::StatusOr<RunMeasurement> RunInProcess(BenchmarkMesh& mesh, const SmoothingParams& params,
                                            std::optional<double> target_q_mean);

// The times the trace gives (99 % of the gain, the target q_mean), once the result is known.
void DeriveTraceTimes(RunMeasurement& run, std::optional<double> target_q_mean);

}  // namespace getme::bench
