#pragma once

#include <thread>
#include <vector>

#include "absl/time/time.h"
#include "getme_server/job_registry.h"
#include "getme_server/job_time_limit.h"

namespace getme::server {

// `workers` threads, each running one job at a time from the registry's queue until the registry
// stops its workers. Each job uses its own engine thread pool (SmoothingParams.threads) and is
// stopped once it has run for max_job_time.
class WorkerPool {
 public:
  WorkerPool(JobRegistry& registry, int workers,
             absl::Duration max_job_time = absl::InfiniteDuration());
  ~WorkerPool();  // joins; call JobRegistry::StopWorkers first
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  void Join();

 private:
  JobTimeLimit time_limit_;  // before the threads that use it
  std::vector<std::thread> threads_;
};

}  // namespace getme::server
