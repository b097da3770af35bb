#pragma once

#include <cstdint>
#include <string>

#include "absl/time/time.h"

namespace getme::server {

// Everything getme-server's flags set (server/main.cc documents each flag).
struct ServerOptions {
  std::string listen = "127.0.0.1:50051";  // host:port; port 0 picks a free one
  // The HTTP gateway and dashboard (host:port); empty = off. The flag's default is
  // 127.0.0.1:8080; in-process servers (tests) have none unless they ask.
  std::string http_listen;
  // True when http_listen is only the flag's default: a busy port then leaves the server without
  // HTTP (a warning) instead of refusing to start, so several servers can run side by side.
  bool http_listen_optional = false;
  int workers = 2;           // jobs smoothed at the same time
  int threads_per_job = 1;   // engine threads per job (SmoothingParameters.threads)
  int max_queued_jobs = 16;  // queued (not yet running) jobs; more: RESOURCE_EXHAUSTED
  std::int64_t max_elements = 20'000'000;         // larger meshes: INVALID_ARGUMENT
  absl::Duration result_ttl = absl::Minutes(30);  // unfetched results are dropped after this
  // Progress fan-out: at most one intermediate event per watcher per this interval (the final
  // event of every phase and of the job always goes out).
  absl::Duration progress_interval = absl::Milliseconds(100);
  absl::Duration shutdown_grace = absl::Seconds(30);  // SIGTERM: running jobs may finish this long

  // Access control (docs/reliability-access.md); empty strings = off.
  // Bearer tokens (AccessTokens' file format); each job belongs to the owner of its token.
  std::string auth_tokens_file;
  // TLS on both listeners: PEM certificate chain and its unencrypted private key, both or neither.
  std::string tls_cert;
  std::string tls_key;
  // PEM CA certificate(s): clients must present a certificate one of them signed (mTLS).
  std::string tls_client_ca;
};

}  // namespace getme::server
