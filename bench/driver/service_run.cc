#include "service_run.h"

#include <chrono>

#include "getme_wire/engine_mesh.h"
#include "getme_wire/params.h"
#include "getme_wire/progress.h"
#include "getme_wire/reports.h"
#include "in_process_run.h"
#include "peak_memory.h"
#include "remote/grid_upload.h"

namespace getme::bench {

ServiceSession::ServiceSession(const std::string& target, pid_t server_pid)
    : client_(remote::SmootherClient::CreateChannel(target)), server_pid_(server_pid) {}

absl::StatusOr<RunMeasurement> ServiceSession::Run(BenchmarkMesh& mesh,
                                                   const SmoothingParams& params,
                                                   std::optional<double> target_q_mean) {
  mesh.RestoreInitialCoordinates();
  RunMeasurement run;
  run.trace.reserve(4096);
  run.peak_rss_reset = ResetPeakRss();
  const bool server_reset = server_pid_ > 0 && ResetPeakRss(server_pid_);
  remote::SmoothJobOptions job;
  job.parameters = wire::ToWireParameters(params);
  job.result_options.set_coordinates_only(true);

  const auto start = std::chrono::steady_clock::now();
  const auto seconds_since_start = [&start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const v1::Mesh wire_mesh = wire::ToWireMesh(mesh.mesh);
  const remote::ProgressHandler on_progress = [&](const v1::ProgressEvent& event) {
    // The job's closing marker repeats the last phase end; it is not an engine event.
    if (event.final() && !event.phase_done()) return;
    if (run.trace.empty()) run.first_event_wall_seconds = seconds_since_start();
    run.trace.push_back(wire::FromWireProgress(event));
  };
  absl::StatusOr<remote::RemoteSmoothResult> result = client_.Smooth(wire_mesh, job, on_progress);
  if (!result.ok()) return result.status();
  if (absl::Status status = wire::ApplyCoordinates(wire::CoordinatesOf(result->mesh), mesh.mesh);
      !status.ok()) {
    return status;
  }
  run.wall_seconds = seconds_since_start();
  run.peak_rss_bytes = PeakRssBytes();
  if (server_reset) run.server_peak_rss_bytes = ProcessPeakRssBytes(server_pid_);
  run.result = wire::FromWireResult(result->result);
  DeriveTraceTimes(run, target_q_mean);
  return run;
}

}  // namespace getme::bench
