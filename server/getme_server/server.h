#pragma once

#include <memory>

#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "getme_server/server_options.h"

namespace getme::server {

// A running getme.v1.Smoother service (plus grpc.health.v1 and server reflection) with its job
// registry and worker pool, and the HTTP gateway over the same jobs when asked for. Tests start
// it in-process on 127.0.0.1:0.
class SmootherServer {
 public:
  static absl::StatusOr<std::unique_ptr<SmootherServer>> Start(const ServerOptions& options);
  virtual ~SmootherServer() = default;

  // The port actually bound (useful with port 0).
  virtual int port() const = 0;
  // The HTTP gateway's port; 0 when it is off.
  virtual int http_port() const = 0;
  // Stops accepting calls and new jobs, lets running jobs finish for up to `grace`, cancels the
  // rest, and returns when everything has stopped. Idempotent.
  virtual void Shutdown(absl::Duration grace) = 0;
  // Blocks until Shutdown has completed.
  virtual void Wait() = 0;
};

}  // namespace getme::server
