#include "getme_server/server_metrics.h"

namespace getme::server {

void ServerMetrics::CountRpc(std::string method, std::string code) {
  std::lock_guard lock(mutex_);
  ++rpcs_[{std::move(method), std::move(code)}];
}

void ServerMetrics::CountHttpRequest(std::string route, int status) {
  std::lock_guard lock(mutex_);
  ++http_[{std::move(route), status}];
}

void ServerMetrics::CountFinishedJob(v1::JobState state, double ran_seconds) {
  std::lock_guard lock(mutex_);
  ++finished_jobs_[state];
  if (ran_seconds < 0) return;
  for (std::size_t b = 0; b < kDurationBuckets.size(); ++b) {
    if (ran_seconds <= kDurationBuckets[b]) ++durations_.cumulative[b];
  }
  ++durations_.count;
  durations_.sum += ran_seconds;
}

ServerMetrics::Snapshot ServerMetrics::Read() const {
  Snapshot snapshot;
  {
    std::lock_guard lock(mutex_);
    snapshot.rpcs = rpcs_;
    snapshot.http = http_;
    snapshot.finished_jobs = finished_jobs_;
    snapshot.durations = durations_;
  }
  snapshot.element_iterations = element_iterations_.load(std::memory_order_relaxed);
  return snapshot;
}

}  // namespace getme::server
