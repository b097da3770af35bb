#pragma once

#include <thread>
#include <vector>

#include "getme_server/job_registry.h"

namespace getme::server {

// `workers` threads, each running one job at a time from the registry's queue until the registry
// stops its workers. Each job uses its own engine thread pool (SmoothingParams.threads).
class WorkerPool {
 public:
  WorkerPool(JobRegistry& registry, int workers);
  ~WorkerPool();  // joins; call JobRegistry::StopWorkers first
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  void Join();

 private:
  std::vector<std::thread> threads_;
};

}  // namespace getme::server
