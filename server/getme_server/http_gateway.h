#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <thread>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "getme_server/authenticator.h"
#include "getme_server/job_directory.h"
#include "getme_server/job_registry.h"
#include "getme_server/server_metrics.h"
#include "getme_server/server_options.h"

namespace httplib {
class Server;
struct Request;
}  // namespace httplib

namespace getme::server {

// The HTTP/JSON front end beside gRPC (docs/http.md): health, readiness, Prometheus metrics, the
// jobs API with Server-Sent Events progress, and the dashboard at "/". It works on the same
// job directory as the gRPC service and checks requests the same way (job_submission.h). With
// authentication on, /v1/ and /metrics need `Authorization: Bearer <token>` (401 otherwise) and
// a caller sees only its own jobs; the probes and the dashboard's files stay open. With
// options.tls_cert it serves HTTPS only (and with tls_client_ca, only to clients with a
// certificate that CA signed).
class HttpGateway {
 public:
  // `jobs` is where jobs are queued and found; `local_jobs` the ones this process runs (the
  // same registry without a shared job store), for /metrics.
  HttpGateway(JobDirectory& jobs, const JobRegistry& local_jobs, const ServerOptions& options,
              ServerMetrics& metrics, const Authenticator& authenticator);
  ~HttpGateway();  // Stop()
  HttpGateway(const HttpGateway&) = delete;
  HttpGateway& operator=(const HttpGateway&) = delete;

  // Binds `address` (host:port, port 0 = a free one) and serves on background threads.
  // INVALID_ARGUMENT when the TLS files do not load.
  absl::Status Start(const std::string& address);
  int port() const { return port_; }
  // Ends open event streams, stops listening and waits for the request threads. Idempotent.
  void Stop();

 private:
  void AddRoutes();
  // The owner of the request's bearer token (Authenticator::kAnonymous with authentication off).
  absl::StatusOr<std::string> CallerOf(const httplib::Request& req) const;
  // The job a /v1/jobs/{id}... request names, if it is the caller's: another owner's job is
  // NOT_FOUND, word for word like an unknown id.
  absl::StatusOr<std::shared_ptr<JobHandle>> FindOwnJob(const httplib::Request& req) const;

  JobDirectory& jobs_;
  const JobRegistry& local_jobs_;
  const ServerOptions options_;
  ServerMetrics& metrics_;
  const Authenticator& authenticator_;
  std::unique_ptr<httplib::Server> http_;
  std::thread listener_;
  std::atomic<bool> listener_done_{false};
  std::atomic<bool> stopping_{false};
  std::atomic<int> open_streams_{0};
  int port_ = 0;
};

}  // namespace getme::server
