#include "getme_server/worker_pool.h"

#include "getme_server/process_memory.h"

namespace getme::server {

WorkerPool::WorkerPool(JobRegistry& registry, int workers, absl::Duration max_job_time)
    : time_limit_(max_job_time) {
  for (int i = 0; i < workers; ++i) {
    threads_.emplace_back([this, &registry] {
      while (std::shared_ptr<Job> job = registry.TakeNextQueued()) {
        time_limit_.Run(job);
        ReleaseFreedHeapMemory();  // the engine's working copies of the mesh
      }
    });
  }
}

WorkerPool::~WorkerPool() { Join(); }

void WorkerPool::Join() {
  for (std::thread& thread : threads_) {
    if (thread.joinable()) thread.join();
  }
}

}  // namespace getme::server
