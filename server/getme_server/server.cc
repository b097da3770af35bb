#include "getme_server/server.h"

#include <unistd.h>

#include <condition_variable>
#include <limits>
#include <mutex>

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "getme_server/authenticator.h"
#include "getme_server/http_gateway.h"
#include "getme_server/job_registry.h"
#include "getme_server/rpc_metrics_interceptor.h"
#include "getme_server/server_metrics.h"
#include "getme_server/shared_job_store.h"
#include "getme_server/smoother_service.h"
#include "getme_server/store_workers.h"
#include "getme_server/tls_files.h"
#include "getme_server/worker_pool.h"
#include "grpcpp/ext/proto_server_reflection_plugin.h"
#include "grpcpp/health_check_service_interface.h"
#include "grpcpp/security/server_credentials.h"
#include "grpcpp/server.h"
#include "grpcpp/server_builder.h"
#include "redis/redis_address.h"
#include "redis/redis_client.h"
#include "spdlog/spdlog.h"

namespace getme::server {
namespace {

// HTTP/2 streams one connection may open at once: a client needing more waits (it is not
// refused); --max_streams_per_client is the limit with a status. Bounds per-connection buffers.
constexpr int kMaxStreamsPerConnection = 256;
// Pings on idle connections find clients that vanished without closing them (a crashed host, a
// dropped network), so their calls end and their stream slots free up.
constexpr absl::Duration kKeepaliveTime = absl::Minutes(1);
constexpr absl::Duration kKeepaliveTimeout = absl::Seconds(20);
// Connections without calls for this long are closed; clients reconnect transparently.
constexpr absl::Duration kMaxConnectionIdle = absl::Minutes(15);
// Clients may ping this often (e.g. their own keepalive) without being disconnected for it.
constexpr absl::Duration kMinClientPingInterval = absl::Seconds(10);
// After running jobs ended, handlers still streaming results get this long to finish.
constexpr absl::Duration kHandlerDrain = absl::Seconds(10);

int Milliseconds(absl::Duration duration) {
  return static_cast<int>(absl::ToInt64Milliseconds(duration));
}

absl::Status CheckOptions(const ServerOptions& options) {
  auto at_least = [](const char* flag, std::int64_t value, std::int64_t min) {
    return value >= min ? absl::OkStatus()
                        : absl::InvalidArgumentError(absl::StrCat(
                              "--", flag, " = ", value, " is out of range: must be >= ", min));
  };
  if (auto s = at_least("workers", options.workers, 1); !s.ok()) return s;
  if (auto s = at_least("threads_per_job", options.threads_per_job, 0); !s.ok()) return s;
  if (auto s = at_least("max_queued_jobs", options.max_queued_jobs, 0); !s.ok()) return s;
  if (auto s = at_least("max_elements", options.max_elements, 1); !s.ok()) return s;
  if (auto s = at_least("max_nodes", options.max_nodes, 1); !s.ok()) return s;
  // Below 64 KiB not even a small chunk fits; above 2 GiB gRPC cannot count.
  if (auto s = at_least("max_message_bytes", options.max_message_bytes, 64 << 10); !s.ok()) {
    return s;
  }
  if (options.max_message_bytes > std::numeric_limits<int>::max()) {
    return absl::InvalidArgumentError(absl::StrCat(
        "--max_message_bytes = ", options.max_message_bytes, " is out of range: must be < 2 GiB"));
  }
  if (auto s = at_least("max_upload_bytes", options.max_upload_bytes, 1); !s.ok()) return s;
  // Else a job the upload limit lets through could never be queued.
  if (auto s = at_least("max_queued_bytes", options.max_queued_bytes, options.max_upload_bytes);
      !s.ok()) {
    return absl::InvalidArgumentError(absl::StrCat(s.message(), " (--max_upload_bytes)"));
  }
  if (auto s = at_least("max_streams_per_client", options.max_streams_per_client, 1); !s.ok()) {
    return s;
  }
  if (options.max_job_time <= absl::ZeroDuration()) {
    return absl::InvalidArgumentError(absl::StrCat(
        "--max_job_time = ", absl::FormatDuration(options.max_job_time), " must be positive"));
  }
  if (options.job_lease < absl::Milliseconds(100)) {
    return absl::InvalidArgumentError(absl::StrCat(
        "--job_lease = ", absl::FormatDuration(options.job_lease), " must be at least 100ms"));
  }
  if (options.result_ttl <= absl::ZeroDuration()) {
    return absl::InvalidArgumentError(absl::StrCat(
        "--result_ttl = ", absl::FormatDuration(options.result_ttl), " must be positive"));
  }
  return absl::OkStatus();
}

// Loopback and Unix-socket listeners only reach this machine: tokens in plaintext stay on it.
bool IsLocalAddress(absl::string_view address) {
  if (absl::StartsWith(address, "unix:")) return true;
  const absl::string_view host = address.substr(0, address.rfind(':'));
  return absl::StartsWith(host, "127.") || host == "localhost" || host == "[::1]" || host == "::1";
}

std::shared_ptr<grpc::ServerCredentials> GrpcCredentials(const std::optional<TlsFiles>& tls) {
  if (!tls.has_value()) return grpc::InsecureServerCredentials();
  grpc::SslServerCredentialsOptions ssl(
      tls->client_ca_pem.empty() ? GRPC_SSL_DONT_REQUEST_CLIENT_CERTIFICATE
                                 : GRPC_SSL_REQUEST_AND_REQUIRE_CLIENT_CERTIFICATE_AND_VERIFY);
  ssl.pem_root_certs = tls->client_ca_pem;
  ssl.pem_key_cert_pairs.push_back({tls->private_key_pem, tls->cert_chain_pem});
  return grpc::SslServerCredentials(ssl);
}

class SmootherServerImpl final : public SmootherServer {
 public:
  // `store` null: jobs live in this process (the registry); else in the shared store.
  SmootherServerImpl(const ServerOptions& options, Authenticator authenticator,
                     std::optional<TlsFiles> tls, std::unique_ptr<SharedJobStore> store)
      : authenticator_(std::move(authenticator)),
        tls_(std::move(tls)),
        registry_(options.max_queued_jobs, options.result_ttl, options.max_queued_bytes,
                  options.progress_interval, &metrics_),
        store_(std::move(store)),
        max_message_bytes_(static_cast<int>(options.max_message_bytes)),
        service_(jobs(), options, authenticator_) {
    if (store_ != nullptr) {
      store_workers_ = std::make_unique<StoreWorkers>(*store_, registry_, options, &metrics_);
    } else {
      workers_ = std::make_unique<WorkerPool>(registry_, options.workers, options.max_job_time);
    }
  }

  ~SmootherServerImpl() override { Shutdown(absl::ZeroDuration()); }

  absl::Status Listen(const std::string& address) {
    grpc::EnableDefaultHealthCheckService(true);
    grpc::reflection::InitProtoReflectionServerBuilderPlugin();
    grpc::ServerBuilder builder;
    builder.AddListeningPort(address, GrpcCredentials(tls_), &port_);
    // gRPC sets SO_REUSEPORT by default: a second server on a taken port would start and silently
    // take half its connections. One port, one server; the second one is refused.
    builder.AddChannelArgument(GRPC_ARG_ALLOW_REUSEPORT, 0);
    // Requests arrive in chunks, so this bounds one message, not a mesh; gRPC itself refuses a
    // larger one with RESOURCE_EXHAUSTED.
    builder.SetMaxReceiveMessageSize(max_message_bytes_);
    builder.AddChannelArgument(GRPC_ARG_MAX_CONCURRENT_STREAMS, kMaxStreamsPerConnection);
    builder.AddChannelArgument(GRPC_ARG_KEEPALIVE_TIME_MS, Milliseconds(kKeepaliveTime));
    builder.AddChannelArgument(GRPC_ARG_KEEPALIVE_TIMEOUT_MS, Milliseconds(kKeepaliveTimeout));
    builder.AddChannelArgument(GRPC_ARG_KEEPALIVE_PERMIT_WITHOUT_CALLS, 1);
    builder.AddChannelArgument(GRPC_ARG_MAX_CONNECTION_IDLE_MS, Milliseconds(kMaxConnectionIdle));
    builder.AddChannelArgument(GRPC_ARG_HTTP2_MIN_RECV_PING_INTERVAL_WITHOUT_DATA_MS,
                               Milliseconds(kMinClientPingInterval));
    builder.RegisterService(&service_);
    std::vector<std::unique_ptr<grpc::experimental::ServerInterceptorFactoryInterface>> counters;
    counters.push_back(RpcMetricsInterceptor(metrics_));
    builder.experimental().SetInterceptorCreators(std::move(counters));
    server_ = builder.BuildAndStart();
    if (server_ == nullptr || port_ == 0) {
      return absl::UnavailableError(absl::StrCat("cannot listen on '", address,
                                                 "' (address in use or malformed host:port?)"));
    }
    server_->GetHealthCheckService()->SetServingStatus(true);
    server_->GetHealthCheckService()->SetServingStatus(v1::Smoother::service_full_name(), true);
    return absl::OkStatus();
  }

  // After Listen: the gateway serves the registry the gRPC service already works on.
  absl::Status ListenHttp(const ServerOptions& options) {
    if (options.http_listen.empty()) return absl::OkStatus();
    auto gateway =
        std::make_unique<HttpGateway>(jobs(), registry_, options, metrics_, authenticator_);
    absl::Status status = gateway->Start(options.http_listen);
    if (!status.ok()) {
      if (!options.http_listen_optional) return status;
      spdlog::warn("{}; serving gRPC only (pass --http_listen to choose another address)",
                   std::string(status.message()));
      return absl::OkStatus();
    }
    http_ = std::move(gateway);
    return absl::OkStatus();
  }

  JobDirectory& jobs() {
    return store_ != nullptr ? static_cast<JobDirectory&>(*store_) : registry_;
  }
  int port() const override { return port_; }
  int http_port() const override { return http_ == nullptr ? 0 : http_->port(); }
  bool tls() const { return tls_.has_value(); }

  void Shutdown(absl::Duration grace) override {
    std::unique_lock lock(mutex_);
    if (shutdown_started_) {
      shutdown_done_cv_.wait(lock, [this] { return shutdown_done_; });
      return;
    }
    shutdown_started_ = true;
    lock.unlock();
    Drain(grace);
    lock.lock();
    shutdown_done_ = true;
    shutdown_done_cv_.notify_all();
  }

  void Wait() override {
    std::unique_lock lock(mutex_);
    shutdown_done_cv_.wait(lock, [this] { return shutdown_done_; });
  }

 private:
  void Drain(absl::Duration grace) {
    // Refusing first: whoever sees the log line or NOT_SERVING can rely on new jobs being refused.
    registry_.StopAccepting("the server is shutting down");
    if (store_ != nullptr) {
      // Jobs queued in the shared store stay there for the other replicas.
      store_->StopAccepting();
      store_workers_->StopTaking();
    }
    if (server_ != nullptr)
      server_->GetHealthCheckService()->SetServingStatus(false);  // all services
    spdlog::info("shutting down: no new calls or jobs; running jobs may finish within {}",
                 absl::FormatDuration(grace));
    const absl::Time jobs_deadline = absl::Now() + grace;
    // gRPC keeps taking calls while jobs run out their grace: new jobs are refused with
    // UNAVAILABLE by the handlers (a call arriving during gRPC's own shutdown would be
    // CANCELLED instead), and clients can still watch and fetch their jobs.
    bool finished = registry_.WaitUntilNoneRunning(jobs_deadline);
    // With a store, a job taken just before the drain may not be in the registry yet (its mesh
    // is still being rebuilt): the workers know it, and it gets the same grace.
    if (store_ != nullptr)
      finished = store_workers_->WaitUntilNoneRunning(jobs_deadline) && finished;
    if (store_ != nullptr) {
      if (!finished) {
        spdlog::warn("grace period over: handing the jobs still running back to the job store");
        store_workers_->ReleaseRunning(
            "the replica running it shut down; another replica starts it again");
      }
      store_workers_->Join();
    } else {
      if (!finished) spdlog::warn("grace period over: cancelling the jobs still running");
      registry_.CancelAll("the server is shutting down");
    }
    registry_.StopWorkers();
    if (workers_ != nullptr) workers_->Join();
    // Handlers still streaming (progress of ended jobs, results) get kHandlerDrain to finish.
    if (server_ != nullptr) {
      server_->Shutdown(absl::ToChronoTime(absl::Now() + kHandlerDrain));
      server_->Wait();
    }
    // Last, so that /readyz answered "draining" and event streams saw their jobs' final events.
    if (http_ != nullptr) http_->Stop();
    spdlog::info("shutdown complete");
  }

  const Authenticator authenticator_;  // before the front ends, which keep a reference
  const std::optional<TlsFiles> tls_;
  ServerMetrics metrics_;  // before the registry: jobs count into it until they are destroyed
  JobRegistry registry_;   // with a shared store: the jobs running here
  std::unique_ptr<SharedJobStore> store_;        // null without --job_store
  std::unique_ptr<WorkerPool> workers_;          // without a shared store
  std::unique_ptr<StoreWorkers> store_workers_;  // with one
  const int max_message_bytes_;
  SmootherService service_;
  std::unique_ptr<grpc::Server> server_;
  int port_ = 0;
  std::unique_ptr<HttpGateway> http_;  // null when off

  std::mutex mutex_;
  std::condition_variable shutdown_done_cv_;
  bool shutdown_started_ = false;
  bool shutdown_done_ = false;
};

}  // namespace

absl::StatusOr<std::unique_ptr<SmootherServer>> SmootherServer::Start(
    const ServerOptions& options) {
  if (auto s = CheckOptions(options); !s.ok()) return s;
  absl::StatusOr<std::optional<TlsFiles>> tls = LoadTlsFiles(options);
  if (!tls.ok()) return tls.status();
  Authenticator authenticator;
  if (!options.auth_tokens_file.empty()) {
    absl::StatusOr<AccessTokens> tokens = AccessTokens::ReadFile(options.auth_tokens_file);
    if (!tokens.ok()) return tokens.status();
    spdlog::info("authentication on: {} bearer token(s) from --auth_tokens_file", tokens->size());
    authenticator = Authenticator(*std::move(tokens));
  }
  std::unique_ptr<SharedJobStore> store;
  if (!options.job_store.empty()) {
    absl::StatusOr<redis::RedisAddress> address = redis::ParseRedisUrl(options.job_store);
    if (!address.ok()) {
      return absl::Status(address.status().code(),
                          absl::StrCat("--job_store: ", address.status().message()));
    }
    absl::StatusOr<std::unique_ptr<redis::RedisClient>> redis =
        redis::RedisClient::Connect(*address);
    if (!redis.ok()) {
      return absl::Status(redis.status().code(),
                          absl::StrCat("--job_store: ", redis.status().message()));
    }
    char host[256] = {};
    gethostname(host, sizeof(host) - 1);
    const std::string replica = absl::StrCat(host, ":", getpid());
    spdlog::info("shared job store at {} (replica {}, lease {})", redis::RedactedUrl(*address),
                 replica, absl::FormatDuration(options.job_lease));
    store = std::make_unique<SharedJobStore>(*std::move(redis), options, replica);
  }
  auto server = std::make_unique<SmootherServerImpl>(options, std::move(authenticator),
                                                     *std::move(tls), std::move(store));
  if (auto s = server->Listen(options.listen); !s.ok()) return s;
  if (auto s = server->ListenHttp(options); !s.ok()) return s;
  if (!options.auth_tokens_file.empty() && !server->tls()) {
    for (const std::string& address : {options.listen, options.http_listen}) {
      if (!address.empty() && !IsLocalAddress(address)) {
        spdlog::warn(
            "bearer tokens are on without TLS and {} is not a loopback address: tokens and "
            "meshes cross the network in plaintext (add --tls_cert and --tls_key)",
            address);
      }
    }
  }
  spdlog::info(
      "getme-server listening on port {} (workers={} threads_per_job={} "
      "max_queued_jobs={} max_elements={} max_nodes={} max_message_bytes={} "
      "max_upload_bytes={} max_queued_bytes={} max_job_time={} max_streams_per_client={} "
      "result_ttl={} tls={} auth={})",
      server->port(), options.workers, options.threads_per_job, options.max_queued_jobs,
      options.max_elements, options.max_nodes, options.max_message_bytes, options.max_upload_bytes,
      options.max_queued_bytes, absl::FormatDuration(options.max_job_time),
      options.max_streams_per_client, absl::FormatDuration(options.result_ttl),
      !server->tls()                  ? "off"
      : options.tls_client_ca.empty() ? "on"
                                      : "mtls",
      options.auth_tokens_file.empty() ? "off" : "tokens");
  if (server->http_port() != 0) {
    // Not "listening on port": scripts find the gRPC port by that phrase.
    spdlog::info("HTTP gateway and dashboard at {}://{}/ (port {})",
                 server->tls() ? "https" : "http",
                 options.http_listen.substr(0, options.http_listen.rfind(':')) + ":" +
                     std::to_string(server->http_port()),
                 server->http_port());
  }
  return server;
}

}  // namespace getme::server
