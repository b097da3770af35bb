#pragma once

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "absl/strings/str_cat.h"
#include "getme_server/server.h"

namespace getme::remote::testing {

// An in-process getme-server on an ephemeral loopback port, shut down with the test. Every
// progress event is delivered (no throttling) so streams can be compared with the local engine.
inline std::unique_ptr<server::SmootherServer> StartTestServer(int workers = 2) {
  server::ServerOptions options;
  options.listen = "127.0.0.1:0";
  options.workers = workers;
  options.threads_per_job = 1;
  options.progress_interval = absl::ZeroDuration();
  options.shutdown_grace = absl::Seconds(1);
  absl::StatusOr<std::unique_ptr<server::SmootherServer>> started =
      server::SmootherServer::Start(options);
  EXPECT_TRUE(started.ok()) << started.status();
  return started.ok() ? *std::move(started) : nullptr;
}

inline std::string TargetOf(const server::SmootherServer& server) {
  return absl::StrCat("127.0.0.1:", server.port());
}

}  // namespace getme::remote::testing
