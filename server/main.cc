// getme-server: the getme.v1.Smoother gRPC service (plus grpc.health.v1 and server reflection),
// and an HTTP gateway with a live dashboard over the same jobs (--http_listen).
#include <pthread.h>
#include <signal.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "absl/flags/flag.h"
#include "absl/flags/parse.h"
#include "absl/flags/usage.h"
#include "absl/flags/usage_config.h"
#include "absl/strings/match.h"
#include "absl/time/time.h"
#include "getme_server/server.h"
#include "getme_server/server_options.h"
#include "spdlog/sinks/stdout_sinks.h"
#include "spdlog/spdlog.h"

ABSL_FLAG(std::string, listen, "127.0.0.1:50051",
          "host:port to listen on (gRPC; TLS with --tls_cert); port 0 picks a free port");
ABSL_FLAG(std::string, http_listen, "127.0.0.1:8080",
          "host:port of the HTTP gateway: dashboard at /, JSON jobs API under /v1/jobs, /healthz, "
          "/readyz, /metrics (docs/http.md); empty = no HTTP; port 0 picks a free port. When this "
          "default is busy the server warns and serves gRPC only; an address given here must bind");
ABSL_FLAG(int, workers, 2, "jobs smoothed at the same time (worker threads)");
ABSL_FLAG(int, threads_per_job, 1,
          "engine threads per job when the request leaves SmoothingParameters.threads unset; "
          "0 = all cores");
ABSL_FLAG(int, max_queued_jobs, 16,
          "jobs that may wait for a worker; one more is refused with RESOURCE_EXHAUSTED");
ABSL_FLAG(int64_t, max_elements, 20'000'000,
          "largest mesh accepted, in elements; larger ones are refused with INVALID_ARGUMENT");
ABSL_FLAG(int64_t, max_nodes, 30'000'000,
          "largest mesh accepted, in nodes (declared in SmoothHeader.expected_size or counted as "
          "chunks arrive); larger ones are refused with INVALID_ARGUMENT");
ABSL_FLAG(int64_t, max_message_bytes, 4 << 20,
          "largest gRPC message accepted, in bytes (clients send meshes in ~1 MiB chunks); a "
          "larger one is refused by gRPC with RESOURCE_EXHAUSTED");
ABSL_FLAG(int64_t, max_upload_bytes, int64_t{2} << 30,
          "largest upload per job, in encoded mesh-chunk bytes, counted as chunks arrive; one "
          "more chunk is refused with RESOURCE_EXHAUSTED before the rest is buffered");
ABSL_FLAG(int64_t, max_queued_bytes, int64_t{4} << 30,
          "upload bytes that all queued and running jobs may hold together (their meshes stay in "
          "memory); a job that would pass it is refused with RESOURCE_EXHAUSTED; must be >= "
          "--max_upload_bytes");
ABSL_FLAG(absl::Duration, max_job_time, absl::Hours(1),
          "a job running longer (time queued not counted) is stopped and fails with "
          "DEADLINE_EXCEEDED; 'inf' = no limit");
ABSL_FLAG(int, max_streams_per_client, 32,
          "open streaming calls (Smooth, SubmitJob, WatchJob, GetResult, EvaluateQuality) per "
          "client host; one more is refused with RESOURCE_EXHAUSTED");
ABSL_FLAG(absl::Duration, result_ttl, absl::Minutes(30),
          "how long a finished job's result is kept for GetResult if nobody fetches it (e.g. 30m)");
ABSL_FLAG(absl::Duration, progress_interval, absl::Milliseconds(100),
          "at most one intermediate progress event per watcher per this interval (phase ends and "
          "the final event always go out)");
ABSL_FLAG(
    std::string, job_store, "",
    "redis://[[user]:password@]host[:port][/db]: share jobs with every replica pointed at "
    "the same Redis (queue, progress, results, limits; docs/replicas.md); rediss:// for TLS, "
    "with ?cacert=PATH&cert=PATH&key=PATH&sni=NAME as needed; empty = jobs live in this process");
ABSL_FLAG(absl::Duration, job_lease, absl::Seconds(10),
          "with --job_store: a job whose replica has not renewed its lease for this long (it died) "
          "is queued again and restarted by another replica");
ABSL_FLAG(absl::Duration, shutdown_grace, absl::Seconds(30),
          "on SIGTERM/SIGINT: how long running jobs may finish before they are cancelled");

ABSL_FLAG(std::string, auth_tokens_file, "",
          "bearer tokens, one per line: TOKEN or NAME:TOKEN (# comments and blank lines allowed, "
          "tokens of at least 16 characters). When set, every getme.v1.Smoother call needs "
          "metadata 'authorization: Bearer <token>' and every /v1/ and /metrics request the "
          "header 'Authorization: Bearer <token>' (else UNAUTHENTICATED / 401), and each caller "
          "sees only the jobs its token's owner created (NAME, or line<N> for a bare token). "
          "Health checks, reflection, /healthz, /readyz and the dashboard page stay open. "
          "Empty = no authentication. Read at startup: changing tokens needs a restart");
ABSL_FLAG(std::string, tls_cert, "",
          "PEM certificate chain: serve TLS on both listeners (gRPC and HTTPS) with --tls_key; "
          "plaintext connections are then refused. Empty = plaintext");
ABSL_FLAG(std::string, tls_key, "", "PEM private key (unencrypted) of --tls_cert");
ABSL_FLAG(std::string, tls_client_ca, "",
          "PEM CA certificate(s): with --tls_cert, require every client (gRPC and HTTP) to present "
          "a certificate signed by one of them (mutual TLS)");

int main(int argc, char** argv) {
  absl::SetProgramUsageMessage(
      "getme-server [flags]: serves GETMe mesh smoothing over gRPC (service getme.v1.Smoother, "
      "see proto/getme/v1/smoother.proto), with grpc.health.v1 health checking and server "
      "reflection, and an HTTP/JSON gateway with a live dashboard (--http_listen). SIGTERM or "
      "SIGINT drains it: no new jobs, running jobs may finish within "
      "--shutdown_grace, queued ones are cancelled, exit code 0. Access control (off by default): "
      "TLS with --tls_cert/--tls_key (mutual TLS with --tls_client_ca), bearer tokens and "
      "per-owner jobs with --auth_tokens_file (docs/reliability.md).");
  // --help lists this file's flags (Abseil's default looks for a file named after the binary).
  absl::FlagsUsageConfig usage_config;
  usage_config.contains_help_flags = [](absl::string_view file) {
    return absl::EndsWith(file, "server/main.cc");
  };
  usage_config.contains_helpshort_flags = usage_config.contains_help_flags;
  absl::SetFlagsUsageConfig(usage_config);
  // Abseil does not tell whether a flag was given; its default may be busy, a given one must work.
  const bool http_listen_given = std::any_of(argv + 1, argv + argc, [](const char* arg) {
    return absl::StartsWith(arg, "--http_listen") || absl::StartsWith(arg, "-http_listen");
  });
  absl::ParseCommandLine(argc, argv);
  spdlog::set_default_logger(spdlog::stderr_logger_mt("getme-server"));

  // Block the signals before any thread starts, so every thread inherits the mask and only the
  // sigwait below receives them: no work in a signal handler.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGTERM);
  sigaddset(&stop_signals, SIGINT);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

  getme::server::ServerOptions options;
  options.listen = absl::GetFlag(FLAGS_listen);
  options.http_listen = absl::GetFlag(FLAGS_http_listen);
  options.http_listen_optional = !http_listen_given;
  options.workers = absl::GetFlag(FLAGS_workers);
  options.threads_per_job = absl::GetFlag(FLAGS_threads_per_job);
  options.max_queued_jobs = absl::GetFlag(FLAGS_max_queued_jobs);
  options.max_elements = absl::GetFlag(FLAGS_max_elements);
  options.max_nodes = absl::GetFlag(FLAGS_max_nodes);
  options.max_message_bytes = absl::GetFlag(FLAGS_max_message_bytes);
  options.max_upload_bytes = absl::GetFlag(FLAGS_max_upload_bytes);
  options.max_queued_bytes = absl::GetFlag(FLAGS_max_queued_bytes);
  options.max_job_time = absl::GetFlag(FLAGS_max_job_time);
  options.max_streams_per_client = absl::GetFlag(FLAGS_max_streams_per_client);
  options.result_ttl = absl::GetFlag(FLAGS_result_ttl);
  options.progress_interval = absl::GetFlag(FLAGS_progress_interval);
  options.shutdown_grace = absl::GetFlag(FLAGS_shutdown_grace);
  options.job_store = absl::GetFlag(FLAGS_job_store);
  options.job_lease = absl::GetFlag(FLAGS_job_lease);
  options.auth_tokens_file = absl::GetFlag(FLAGS_auth_tokens_file);
  options.tls_cert = absl::GetFlag(FLAGS_tls_cert);
  options.tls_key = absl::GetFlag(FLAGS_tls_key);
  options.tls_client_ca = absl::GetFlag(FLAGS_tls_client_ca);

  auto server = getme::server::SmootherServer::Start(options);
  if (!server.ok()) {
    spdlog::error("getme-server: {}", std::string(server.status().message()));
    return EXIT_FAILURE;
  }
  int signal_number = 0;
  sigwait(&stop_signals, &signal_number);
  spdlog::info("received {}", signal_number == SIGTERM ? "SIGTERM" : "SIGINT");
  (*server)->Shutdown(options.shutdown_grace);
  return EXIT_SUCCESS;
}
