#include "getme_server/http_gateway.h"

#include <regex>
#include <string>
#include <utility>

#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "absl/time/clock.h"
#include "getme_server/dashboard_assets.h"
#include "getme_server/http_json.h"
#include "getme_server/job_submission.h"
#include "getme_server/prometheus_text.h"
#include "httplib.h"
#include "spdlog/spdlog.h"

namespace getme::server {
namespace {

// POST /v1/jobs is for trying the service from a browser; the gRPC upload streams meshes of any
// size in chunks. 8 MiB of JSON is roughly a 40k-element tetrahedral mesh.
constexpr std::size_t kMaxJsonBodyBytes = 8 << 20;
// httplib serves each connection on a thread of this pool; an open event stream holds one, so
// streams are capped below it to keep threads for API calls and probes.
constexpr int kRequestThreads = 32;
constexpr int kMaxEventStreams = 24;
// How often an event stream checks for shutdown, and how long it may stay silent: the keep-alive
// comment also finds browsers that went away without closing the connection.
constexpr absl::Duration kStreamPoll = absl::Milliseconds(100);
constexpr absl::Duration kStreamKeepAlive = absl::Seconds(2);

const char kJson[] = "application/json";
// EventSource cannot send headers: the dashboard's event streams carry the token in this query
// parameter (RFC 6750's name), accepted on /events only. Logs show paths without query strings.
const char kTokenParameter[] = "access_token";
const std::regex kJobPath(R"(/v1/jobs/([^/:]+)(:cancel|/events|/report|/trace)?)");

void ReplyError(httplib::Response& res, const absl::Status& status) {
  res.status = HttpStatusFromCode(status.code());
  res.set_content(ErrorJson(status.code(), status.message()), kJson);
}

void ReplyJson(httplib::Response& res, const google::protobuf::Message& message) {
  res.status = 200;
  res.set_content(ToJson(message), kJson);
}

// The metrics label of a request: its route, never the raw path (job ids would make the number
// of series grow without bound).
std::string RouteOf(const std::string& path, std::string& job_id) {
  std::smatch match;
  if (std::regex_match(path, match, kJobPath)) {
    job_id = match[1];
    return absl::StrCat("/v1/jobs/{id}", match[2].str());
  }
  if (path == "/v1/jobs" || path == "/healthz" || path == "/readyz" || path == "/metrics") {
    return path;
  }
  return FindDashboardAsset(path) != nullptr ? "/dashboard" : "other";
}

bool SendEvent(httplib::DataSink& sink, absl::string_view name, const std::string& data) {
  const std::string frame = absl::StrCat("event: ", name, "\ndata: ", data, "\n\n");
  return sink.write(frame.data(), frame.size());
}

// One call per stream: forwards the job's progress events (the same fan-out as gRPC WatchJob, so a
// slow browser only skips intermediate events and never holds the job up), then the result
// summary of a SUCCEEDED job and the job's final description. False (connection dropped) when a
// write fails: the browser went away.
bool WriteJobEvents(const JobHandle& job, EventSource& watcher, const std::atomic<bool>& stopping,
                    httplib::DataSink& sink) {
  const std::string retry = "retry: 2000\n\n";  // EventSource reconnects after 2 s
  if (!sink.write(retry.data(), retry.size())) return false;
  absl::Time last_write = absl::Now();
  v1::ProgressEvent event;
  bool ended = false;
  while (!ended && !stopping.load()) {
    switch (watcher.Next(kStreamPoll, event)) {
      case EventSource::NextResult::kEvent:
        if (!SendEvent(sink, "progress", ToJson(event))) return false;
        last_write = absl::Now();
        ended = event.final();
        break;
      case EventSource::NextResult::kEnded:
        ended = true;
        break;
      case EventSource::NextResult::kTimeout:
        if (absl::Now() - last_write >= kStreamKeepAlive) {
          const std::string comment = ": keep-alive\n\n";
          if (!sink.write(comment.data(), comment.size())) return false;
          last_write = absl::Now();
        }
        break;
    }
  }
  if (ended) {
    if (std::optional<v1::SmoothResult> summary = job.Summary()) {
      if (!SendEvent(sink, "result", ToJson(*summary))) return false;
    }
  }
  // Also on shutdown: the browser learns the job's state and does not reconnect to a dead server.
  if (!SendEvent(sink, "end", ToJson(job.Describe()))) return false;
  sink.done();
  return true;
}

// Routes that need a caller when authentication is on; probes and dashboard files stay open (the
// dashboard asks for a token itself).
bool NeedsCaller(const std::string& path) {
  return absl::StartsWith(path, "/v1/") || path == "/metrics";
}

std::unique_ptr<httplib::Server> MakeHttpServer(const ServerOptions& options) {
  if (options.tls_cert.empty()) return std::make_unique<httplib::Server>();
  return std::make_unique<httplib::SSLServer>(
      options.tls_cert.c_str(), options.tls_key.c_str(),
      options.tls_client_ca.empty() ? nullptr : options.tls_client_ca.c_str());
}

absl::StatusOr<std::pair<std::string, int>> SplitHostPort(const std::string& address) {
  const std::size_t colon = address.rfind(':');
  int port = -1;
  if (colon == std::string::npos || colon == 0 ||
      !absl::SimpleAtoi(absl::string_view(address).substr(colon + 1), &port) || port < 0 ||
      port > 65535) {
    return absl::InvalidArgumentError(
        absl::StrCat("--http_listen '", address, "' is not host:port (e.g. 127.0.0.1:8080)"));
  }
  std::string host = address.substr(0, colon);
  if (host.size() > 2 && host.front() == '[' && host.back() == ']') {
    host = host.substr(1, host.size() - 2);
  }
  return std::make_pair(host, port);
}

}  // namespace

HttpGateway::HttpGateway(JobDirectory& jobs, const JobRegistry& local_jobs,
                         const ServerOptions& options, ServerMetrics& metrics,
                         const Authenticator& authenticator)
    : jobs_(jobs),
      local_jobs_(local_jobs),
      options_(options),
      metrics_(metrics),
      authenticator_(authenticator),
      http_(MakeHttpServer(options)) {
  AddRoutes();
}

absl::StatusOr<std::string> HttpGateway::CallerOf(const httplib::Request& req) const {
  if (req.has_header("Authorization")) {
    return authenticator_.Authenticate(req.get_header_value("Authorization"));
  }
  if (absl::EndsWith(req.path, "/events") && req.has_param(kTokenParameter)) {
    return authenticator_.AuthenticateToken(req.get_param_value(kTokenParameter));
  }
  return authenticator_.Authenticate(std::nullopt);
}

HttpGateway::~HttpGateway() { Stop(); }

absl::Status HttpGateway::Start(const std::string& address) {
  absl::StatusOr<std::pair<std::string, int>> host_port = SplitHostPort(address);
  if (!host_port.ok()) return host_port.status();
  const auto& [host, port] = *host_port;
  if (!http_->is_valid()) {
    return absl::InvalidArgumentError(
        "the HTTP gateway cannot load --tls_cert, --tls_key or --tls_client_ca");
  }
  http_->new_task_queue = [] { return new httplib::ThreadPool(kRequestThreads); };
  if (port == 0) {
    port_ = http_->bind_to_any_port(host);
  } else if (http_->bind_to_port(host, port)) {
    port_ = port;
  }
  if (port_ <= 0) {
    port_ = 0;
    return absl::UnavailableError(absl::StrCat("cannot listen on '", address,
                                               "' for HTTP (address in use or unknown host?)"));
  }
  listener_ = std::thread([this] {
    http_->listen_after_bind();
    listener_done_.store(true);
  });
  // httplib's stop() does nothing before the accept loop runs: wait for it, so Stop never hangs.
  while (!http_->is_running() && !listener_done_.load()) absl::SleepFor(absl::Milliseconds(1));
  return absl::OkStatus();
}

void HttpGateway::Stop() {
  stopping_.store(true);
  if (listener_.joinable()) {
    http_->stop();
    listener_.join();
  }
}

absl::StatusOr<std::shared_ptr<JobHandle>> HttpGateway::FindOwnJob(
    const httplib::Request& req) const {
  absl::StatusOr<std::string> caller = CallerOf(req);
  if (!caller.ok()) return caller.status();
  return jobs_.FindJob(req.matches[1], *caller);
}

void HttpGateway::AddRoutes() {
  http_->set_payload_max_length(kMaxJsonBodyBytes);
  http_->set_error_handler(
      httplib::Server::HandlerWithResponse([](const httplib::Request& req, httplib::Response& res) {
        if (!res.body.empty()) return httplib::Server::HandlerResponse::Unhandled;
        absl::Status status;
        if (res.status == 413) {
          status = absl::ResourceExhaustedError(absl::StrCat(
              "request body over ", kMaxJsonBodyBytes >> 20,
              " MiB: POST /v1/jobs takes small meshes; send big ones over gRPC (SubmitJob streams "
              "them in chunks, e.g. with the getme CLI)"));
        } else if (res.status == 400) {
          status = absl::InvalidArgumentError(
              "malformed HTTP request (a POST without a body still needs Content-Length: 0)");
        } else if (res.status == 404) {
          status = absl::NotFoundError(absl::StrCat("no route for ", req.method, " ", req.path));
        } else {
          status = absl::UnknownError(absl::StrCat("HTTP ", res.status));
        }
        res.set_content(ErrorJson(status.code(), status.message()), kJson);
        return httplib::Server::HandlerResponse::Handled;
      }));
  http_->set_exception_handler(
      [](const httplib::Request&, httplib::Response& res, std::exception_ptr error) {
        std::string what = "unknown exception";
        try {
          std::rethrow_exception(error);
        } catch (const std::exception& e) {
          what = e.what();
        } catch (...) {
        }
        ReplyError(res, absl::InternalError(what));
      });
  // Counted before the response is written (httplib's logger runs after it): a client that scrapes
  // /metrics right after its reply arrived must find that reply counted.
  http_->set_post_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    std::string job_id;
    metrics_.CountHttpRequest(RouteOf(req.path, job_id), res.status);
  });
  http_->set_logger([](const httplib::Request& req, const httplib::Response& res) {
    std::string job_id;
    const std::string route = RouteOf(req.path, job_id);
    // Probes and scrapes come every few seconds: keep them out of the info log.
    const bool routine =
        route == "/healthz" || route == "/readyz" || route == "/metrics" || route == "/dashboard";
    spdlog::log(routine ? spdlog::level::debug : spdlog::level::info,
                "http method={} path={} status={}{}{} from {}", req.method, req.path, res.status,
                job_id.empty() ? "" : " job=", job_id, req.remote_addr);
  });

  // Before routing, so no handler (present or future) under /v1/ runs for an unknown caller.
  http_->set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
    if (!NeedsCaller(req.path)) return httplib::Server::HandlerResponse::Unhandled;
    absl::StatusOr<std::string> caller = CallerOf(req);
    if (caller.ok()) return httplib::Server::HandlerResponse::Unhandled;
    res.set_header("WWW-Authenticate", "Bearer");
    ReplyError(res, caller.status());
    return httplib::Server::HandlerResponse::Handled;
  });

  http_->Get("/healthz", [](const httplib::Request&, httplib::Response& res) {
    res.set_content("{\"status\": \"SERVING\"}", kJson);
  });
  http_->Get("/readyz", [this](const httplib::Request&, httplib::Response& res) {
    if (jobs_.accepting()) {
      res.set_content("{\"status\": \"READY\"}", kJson);
    } else {
      ReplyError(res, absl::UnavailableError("draining: the server is shutting down and accepts "
                                             "no new jobs"));
    }
  });
  http_->Get("/metrics", [this](const httplib::Request&, httplib::Response& res) {
    JobsNow now{local_jobs_.ListAllOwners(), jobs_.QueuedCount(), options_.workers,
                jobs_.LiveReplicas(),        jobs_.accepting(),   ReadProcessMemory()};
    res.set_content(PrometheusText(metrics_.Read(), now), "text/plain; version=0.0.4");
  });

  http_->Get("/v1/jobs", [this](const httplib::Request& req, httplib::Response& res) {
    absl::StatusOr<std::string> caller = CallerOf(req);
    if (!caller.ok()) return ReplyError(res, caller.status());
    v1::ListJobsResponse list;
    for (v1::Job& job : jobs_.DescribeJobs(*caller)) *list.add_jobs() = std::move(job);
    ReplyJson(res, list);
  });
  http_->Post("/v1/jobs", [this](const httplib::Request& req, httplib::Response& res) {
    absl::StatusOr<std::string> caller = CallerOf(req);
    if (!caller.ok()) return ReplyError(res, caller.status());
    absl::StatusOr<JobSubmission> submission =
        SubmissionFromJson(req.body, options_, jobs_.keeps_uploads());
    if (!submission.ok()) return ReplyError(res, submission.status());
    absl::StatusOr<SubmittedJob> submitted = jobs_.Submit(*std::move(submission), *caller);
    if (!submitted.ok()) return ReplyError(res, submitted.status());
    spdlog::info("job={} queued by HTTP POST /v1/jobs from {}{}{}", submitted->job->id(),
                 req.remote_addr, caller->empty() ? "" : " owner=", *caller);
    ReplyJson(res, submitted->job->Describe());
  });
  http_->Get(R"(/v1/jobs/([^/:]+))", [this](const httplib::Request& req, httplib::Response& res) {
    absl::StatusOr<std::shared_ptr<JobHandle>> job = FindOwnJob(req);
    if (!job.ok()) return ReplyError(res, job.status());
    ReplyJson(res, (*job)->Describe());
  });
  http_->Post(R"(/v1/jobs/([^/:]+):cancel)",
              [this](const httplib::Request& req, httplib::Response& res) {
                absl::StatusOr<std::shared_ptr<JobHandle>> job = FindOwnJob(req);
                if (!job.ok()) return ReplyError(res, job.status());
                (*job)->Cancel(absl::StrCat("HTTP cancel from ", req.remote_addr));
                ReplyJson(res, (*job)->Describe());
              });
  http_->Get(R"(/v1/jobs/([^/:]+)/report)", [this](const httplib::Request& req,
                                                   httplib::Response& res) {
    absl::StatusOr<std::shared_ptr<JobHandle>> job = FindOwnJob(req);
    if (!job.ok()) return ReplyError(res, job.status());
    std::optional<v1::SmoothResult> summary = (*job)->Summary();
    if (!summary.has_value()) {
      const absl::Status outcome = (*job)->outcome();
      return ReplyError(res, (*job)->final() && !outcome.ok()
                                 ? outcome
                                 : absl::FailedPreconditionError(absl::StrCat(
                                       "job ", (*job)->id(), " has not finished: no report yet")));
    }
    ReplyJson(res, *summary);
  });
  http_->Get(
      R"(/v1/jobs/([^/:]+)/trace)", [this](const httplib::Request& req, httplib::Response& res) {
        absl::StatusOr<std::shared_ptr<JobHandle>> job = FindOwnJob(req);
        if (!job.ok()) return ReplyError(res, job.status());
        std::vector<std::string> events;
        for (const v1::ProgressEvent& event : (*job)->Trace()) {
          events.push_back(ToJson(event));
        }
        res.set_content(absl::StrCat("{\"events\":[", absl::StrJoin(events, ","), "]}"), kJson);
      });
  http_->Get(R"(/v1/jobs/([^/:]+)/events)",
             [this](const httplib::Request& req, httplib::Response& res) {
               absl::StatusOr<std::shared_ptr<JobHandle>> job = FindOwnJob(req);
               if (!job.ok()) return ReplyError(res, job.status());
               if (open_streams_.fetch_add(1) >= kMaxEventStreams) {
                 open_streams_.fetch_sub(1);
                 return ReplyError(
                     res, absl::ResourceExhaustedError(absl::StrCat(
                              kMaxEventStreams, " event streams are open already; retry later")));
               }
               std::shared_ptr<EventSource> watcher = (*job)->WatchEvents();
               res.set_header("Cache-Control", "no-cache");
               res.set_chunked_content_provider(
                   "text/event-stream",
                   [this, job = *job, watcher](std::size_t, httplib::DataSink& sink) {
                     return WriteJobEvents(*job, *watcher, stopping_, sink);
                   },
                   [this](bool) { open_streams_.fetch_sub(1); });
             });

  http_->Get(R"(/[A-Za-z0-9_.-]*)", [](const httplib::Request& req, httplib::Response& res) {
    const DashboardAsset* asset = FindDashboardAsset(req.path);
    if (asset == nullptr) {
      return ReplyError(res, absl::NotFoundError(absl::StrCat("no page ", req.path)));
    }
    res.set_content(asset->content.data(), asset->content.size(),
                    std::string(asset->content_type).c_str());
  });
}

}  // namespace getme::server
