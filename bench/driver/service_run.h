#pragma once

#include <sys/types.h>

#include <optional>
#include <string>

#include "absl/status/statusor.h"
#include "benchmark_mesh.h"
#include "getme/smoothing/smoothing_params.h"
#include "remote/smoother_client.h"
#include "run_measurement.h"

namespace getme::bench {

// Runs measurements through a getme-server: the same mesh and parameters as in-process, timed
// from the engine mesh in this process to the smoothed coordinates back in it.
class ServiceSession {
 public:
  // `server_pid`: the server's process when this program started it (its peak RSS is then
  // measured per run), 0 for a server started elsewhere.
  ServiceSession(const std::string& target, pid_t server_pid);

  absl::StatusOr<RunMeasurement> Run(BenchmarkMesh& mesh, const SmoothingParams& params,
                                     std::optional<double> target_q_mean);

 private:
  remote::SmootherClient client_;
  pid_t server_pid_;
};

}  // namespace getme::bench
