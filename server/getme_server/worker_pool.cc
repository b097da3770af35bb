#include "getme_server/worker_pool.h"

namespace getme::server {

WorkerPool::WorkerPool(JobRegistry& registry, int workers) {
  for (int i = 0; i < workers; ++i) {
    threads_.emplace_back([&registry] {
      while (std::shared_ptr<Job> job = registry.TakeNextQueued()) job->Run();
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
