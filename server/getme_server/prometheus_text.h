#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "getme_server/job.h"
#include "getme_server/process_memory.h"
#include "getme_server/server_metrics.h"

namespace getme::server {

// What GET /metrics shows besides the counters: the registry's jobs and the process's memory at
// scrape time.
struct JobsNow {
  std::vector<std::shared_ptr<Job>> jobs;
  std::int64_t queued = 0;  // with a shared job store: the cluster's queue
  int workers = 0;
  // With a shared job store: replicas heard from in the last seconds (for an autoscaler).
  std::optional<std::int64_t> live_replicas;
  bool ready = true;
  ProcessMemory memory;
};

// Prometheus text exposition format 0.0.4 (docs/http.md lists every metric).
std::string PrometheusText(const ServerMetrics::Snapshot& counters, const JobsNow& now);

}  // namespace getme::server
