#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <thread>

#include "absl/status/status.h"
#include "getme_server/job_registry.h"
#include "getme_server/server_metrics.h"
#include "getme_server/server_options.h"

namespace httplib {
class Server;
}

namespace getme::server {

// The HTTP/JSON front end beside gRPC (docs/http.md): health, readiness, Prometheus metrics, the
// jobs API with Server-Sent Events progress, and the dashboard at "/". It works on the same
// registry and jobs as the gRPC service and creates jobs through the same CreateJob.
class HttpGateway {
 public:
  HttpGateway(JobRegistry& registry, const ServerOptions& options, ServerMetrics& metrics);
  ~HttpGateway();  // Stop()
  HttpGateway(const HttpGateway&) = delete;
  HttpGateway& operator=(const HttpGateway&) = delete;

  // Binds `address` (host:port, port 0 = a free one) and serves on background threads.
  absl::Status Start(const std::string& address);
  int port() const { return port_; }
  // Ends open event streams, stops listening and waits for the request threads. Idempotent.
  void Stop();

 private:
  void AddRoutes();

  JobRegistry& registry_;
  const ServerOptions options_;
  ServerMetrics& metrics_;
  std::unique_ptr<httplib::Server> http_;
  std::thread listener_;
  std::atomic<bool> listener_done_{false};
  std::atomic<bool> stopping_{false};
  std::atomic<int> open_streams_{0};
  int port_ = 0;
};

}  // namespace getme::server
