#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "getme/v1/mesh.pb.h"
#include "getme/v1/quality.pb.h"
#include "getme/v1/smoother.grpc.pb.h"
#include "getme/v1/smoother.pb.h"
#include "grpcpp/channel.h"
#include "remote/call_options.h"
#include "remote/channel_security.h"

namespace getme::remote {

// The result of a smoothing job: the report and the smoothed mesh as received (coordinates, plus
// the topology unless ResultOptions.coordinates_only was asked for). The coordinates are checked
// to number 3 × result.nodes().
struct RemoteSmoothResult {
  v1::SmoothResult result;
  v1::Mesh mesh;
};

// A client of the getme.v1.Smoother service, for any C++ program. Meshes are uploaded as a header
// plus ~1 MB MeshChunk messages and results downloaded the same way, so mesh size is not bounded
// by gRPC's message limit. Every method returns the server's status code and message unchanged
// (UNAVAILABLE when the server cannot be reached, after the retries of CallOptions.retry).
// Thread-safe: calls may run concurrently.
class SmootherClient {
 public:
  explicit SmootherClient(std::shared_ptr<grpc::ChannelInterface> channel);

  // An insecure channel to "host:port" (the service listens on loopback or a trusted network).
  static std::shared_ptr<grpc::Channel> CreateChannel(const std::string& target);
  // A channel with TLS and/or a bearer token, for a server with access control on.
  static std::shared_ptr<grpc::Channel> CreateChannel(const std::string& target,
                                                      const ChannelSecurity& security);

  // One call: uploads `mesh`, calls `on_progress` for each progress event while it is smoothed,
  // and returns the result. Cancelling (CallOptions.cancel) or the timeout stops the job.
  absl::StatusOr<RemoteSmoothResult> Smooth(const v1::Mesh& mesh, const SmoothJobOptions& job,
                                            const ProgressHandler& on_progress,
                                            const CallOptions& call = {});

  // Queues a job that outlives this connection; returns it (state QUEUED or later) at once.
  absl::StatusOr<v1::Job> SubmitJob(const v1::Mesh& mesh, const SmoothJobOptions& job,
                                    const CallOptions& call = {});
  // Streams the job's progress events until its final one. Returns OK once the final event has
  // arrived (whatever state the job ended in; GetJob tells it).
  absl::Status WatchJob(const std::string& job_id, const ProgressHandler& on_progress,
                        const CallOptions& call = {});
  absl::StatusOr<v1::Job> GetJob(const std::string& job_id, const CallOptions& call = {});
  absl::StatusOr<v1::Job> CancelJob(const std::string& job_id, const CallOptions& call = {});
  absl::StatusOr<std::vector<v1::Job>> ListJobs(const CallOptions& call = {});
  // The result of a SUCCEEDED job (which the server then drops).
  absl::StatusOr<RemoteSmoothResult> GetResult(const std::string& job_id,
                                               const CallOptions& call = {});

  // Quality statistics of a mesh without smoothing it. `histogram_bins` 0 = the server's 20.
  absl::StatusOr<v1::QualityReport> EvaluateQuality(const v1::Mesh& mesh,
                                                    std::uint32_t histogram_bins,
                                                    const CallOptions& call = {});

 private:
  std::unique_ptr<v1::Smoother::Stub> stub_;
};

}  // namespace getme::remote
