#include "getme_server/prometheus_text.h"

#include <map>

#include "absl/strings/ascii.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_replace.h"

namespace getme::server {
namespace {

constexpr v1::JobState kStates[] = {v1::JOB_STATE_QUEUED, v1::JOB_STATE_RUNNING,
                                    v1::JOB_STATE_SUCCEEDED, v1::JOB_STATE_FAILED,
                                    v1::JOB_STATE_CANCELLED};

std::string StateLabel(v1::JobState state) {
  return absl::AsciiStrToLower(
      absl::string_view(v1::JobState_Name(state)).substr(sizeof("JOB_STATE_") - 1));
}

std::string LabelValue(absl::string_view value) {
  return absl::StrReplaceAll(value, {{"\\", "\\\\"}, {"\"", "\\\""}, {"\n", "\\n"}});
}

// Prometheus parses Go float syntax; integers and shortest round-trip doubles both qualify.
std::string Number(double value) { return absl::StrCat(value); }

void Header(std::string& out, absl::string_view name, absl::string_view type,
            absl::string_view help) {
  absl::StrAppend(&out, "# HELP ", name, " ", help, "\n# TYPE ", name, " ", type, "\n");
}

}  // namespace

std::string PrometheusText(const ServerMetrics::Snapshot& counters, const JobsNow& now) {
  std::map<v1::JobState, std::int64_t> by_state;
  std::int64_t running = 0;
  double rate = 0;
  for (const auto& job : now.jobs) {
    const v1::JobState state = job->state();
    ++by_state[state];
    if (state == v1::JOB_STATE_RUNNING) {
      ++running;
      rate += job->ElementIterationRate();
    }
  }

  std::string out;
  Header(out, "getme_ready", "gauge", "1 while the server accepts jobs, 0 while it drains.");
  absl::StrAppend(&out, "getme_ready ", now.ready ? 1 : 0, "\n");
  Header(out, "getme_jobs", "gauge",
         "Jobs the server knows, by state (finished ones are forgotten after twice "
         "--result_ttl).");
  for (v1::JobState state : kStates) {
    absl::StrAppend(&out, "getme_jobs{state=\"", StateLabel(state), "\"} ", by_state[state], "\n");
  }
  Header(out, "getme_jobs_finished_total", "counter",
         "Jobs that reached a final state since the server started, by state.");
  for (v1::JobState state :
       {v1::JOB_STATE_SUCCEEDED, v1::JOB_STATE_FAILED, v1::JOB_STATE_CANCELLED}) {
    const auto it = counters.finished_jobs.find(state);
    absl::StrAppend(&out, "getme_jobs_finished_total{state=\"", StateLabel(state), "\"} ",
                    it == counters.finished_jobs.end() ? 0 : it->second, "\n");
  }
  Header(out, "getme_queue_length", "gauge",
         "Jobs waiting for a worker (with --job_store: in the whole shared queue).");
  absl::StrAppend(&out, "getme_queue_length ", now.queued, "\n");
  if (now.live_replicas.has_value()) {
    Header(out, "getme_live_replicas", "gauge",
           "Replicas sharing the job store (--job_store) heard from in the last 5 seconds.");
    absl::StrAppend(&out, "getme_live_replicas ", *now.live_replicas, "\n");
  }
  Header(out, "getme_workers", "gauge", "Jobs that may run at the same time (--workers).");
  absl::StrAppend(&out, "getme_workers ", now.workers, "\n");
  Header(out, "getme_active_workers", "gauge", "Workers running a job now.");
  absl::StrAppend(&out, "getme_active_workers ", running, "\n");
  Header(out, "getme_element_iterations_total", "counter",
         "Element transforms done: a simultaneous-type iteration counts every element, a "
         "sequential pick one.");
  absl::StrAppend(&out, "getme_element_iterations_total ", counters.element_iterations, "\n");
  Header(out, "getme_element_iterations_per_second", "gauge",
         "Sum over running jobs of their element transforms per second since they started.");
  absl::StrAppend(&out, "getme_element_iterations_per_second ", Number(rate), "\n");

  Header(out, "getme_job_duration_seconds", "histogram",
         "Running time of the jobs that ran (started to final state).");
  for (std::size_t b = 0; b < ServerMetrics::kDurationBuckets.size(); ++b) {
    absl::StrAppend(&out, "getme_job_duration_seconds_bucket{le=\"",
                    Number(ServerMetrics::kDurationBuckets[b]), "\"} ",
                    counters.durations.cumulative[b], "\n");
  }
  absl::StrAppend(&out, "getme_job_duration_seconds_bucket{le=\"+Inf\"} ", counters.durations.count,
                  "\n");
  absl::StrAppend(&out, "getme_job_duration_seconds_sum ", Number(counters.durations.sum), "\n");
  absl::StrAppend(&out, "getme_job_duration_seconds_count ", counters.durations.count, "\n");

  if (now.memory.resident_bytes >= 0) {
    Header(out, "process_resident_memory_bytes", "gauge", "Resident memory size in bytes.");
    absl::StrAppend(&out, "process_resident_memory_bytes ", now.memory.resident_bytes, "\n");
  }
  if (now.memory.heap_in_use_bytes >= 0) {
    Header(out, "getme_heap_in_use_bytes", "gauge",
           "Bytes the allocator has handed out and not got back (glibc mallinfo2): what grows "
           "with a leak, unlike resident memory, which also holds freed memory kept for reuse.");
    absl::StrAppend(&out, "getme_heap_in_use_bytes ", now.memory.heap_in_use_bytes, "\n");
  }

  Header(out, "getme_rpcs_total", "counter", "gRPC calls finished, by method and status code.");
  for (const auto& [key, count] : counters.rpcs) {
    absl::StrAppend(&out, "getme_rpcs_total{method=\"", LabelValue(key.first), "\",code=\"",
                    LabelValue(key.second), "\"} ", count, "\n");
  }
  Header(out, "getme_http_requests_total", "counter",
         "HTTP gateway requests answered, by route and status.");
  for (const auto& [key, count] : counters.http) {
    absl::StrAppend(&out, "getme_http_requests_total{route=\"", LabelValue(key.first),
                    "\",status=\"", key.second, "\"} ", count, "\n");
  }
  return out;
}

}  // namespace getme::server
