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

  // Access control (docs/reliability.md); empty strings = off.
  // Bearer tokens (AccessTokens' file format); each job belongs to the owner of its token.
  std::string auth_tokens_file;
  // TLS on both listeners: PEM certificate chain and its unencrypted private key, both or neither.
  std::string tls_cert;
  std::string tls_key;
  // PEM CA certificate(s): clients must present a certificate one of them signed (mTLS).
  std::string tls_client_ca;
  // Resource limits (docs/reliability.md explains the defaults and the memory they bound).
  // Largest gRPC message accepted; the clients' chunks are about 1 MiB. More: RESOURCE_EXHAUSTED.
  std::int64_t max_message_bytes = 4 << 20;
  // Encoded bytes of one job's mesh chunks, counted as they arrive. More: RESOURCE_EXHAUSTED.
  std::int64_t max_upload_bytes = std::int64_t{2} << 30;
  std::int64_t max_nodes = 30'000'000;  // larger meshes: INVALID_ARGUMENT
  // Upload bytes of all QUEUED and RUNNING jobs together; a job that would pass it:
  // RESOURCE_EXHAUSTED. Must be at least max_upload_bytes, so that any accepted upload can run.
  std::int64_t max_queued_bytes = std::int64_t{4} << 30;
  // A job running longer is stopped and FAILED with DEADLINE_EXCEEDED; InfiniteDuration = none.
  absl::Duration max_job_time = absl::Hours(1);
  // Open Smooth/SubmitJob/WatchJob/GetResult/EvaluateQuality calls per client host; one more:
  // RESOURCE_EXHAUSTED.
  int max_streams_per_client = 32;

  // Replicas (docs/replicas.md): a redis://[[user]:password@]host[:port][/db] URL makes every
  // replica pointed at it share jobs, queue, progress and results; empty = this process's own
  // registry. A job running on a replica that stops renewing its lease for job_lease is restarted
  // by another.
  std::string job_store;
  absl::Duration job_lease = absl::Seconds(10);
};

}  // namespace getme::server
