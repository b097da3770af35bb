#include "getme_server/job_time_limit.h"

#include "absl/time/clock.h"

namespace getme::server {

JobTimeLimit::JobTimeLimit(absl::Duration limit) : limit_(limit) {
  if (limit_ != absl::InfiniteDuration()) watcher_ = std::thread([this] { WatchLoop(); });
}

JobTimeLimit::~JobTimeLimit() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  if (watcher_.joinable()) watcher_.join();
}

void JobTimeLimit::Run(const std::shared_ptr<Job>& job) {
  const absl::Time start = absl::Now();
  if (limit_ == absl::InfiniteDuration()) {
    job->Run(start);
    return;
  }
  std::uint64_t run = 0;
  {
    std::lock_guard lock(mutex_);
    run = ++runs_;
    running_.emplace(run, Running{start + limit_, job});
  }
  changed_.notify_all();
  job->Run(start);
  std::lock_guard lock(mutex_);
  running_.erase(run);
}

void JobTimeLimit::WatchLoop() {
  std::unique_lock lock(mutex_);
  while (!stop_) {
    Running* earliest = nullptr;
    for (auto& [run, entry] : running_) {
      if (!entry.stopped && (earliest == nullptr || entry.deadline < earliest->deadline)) {
        earliest = &entry;
      }
    }
    if (earliest == nullptr) {
      changed_.wait(lock);
    } else if (absl::Now() < earliest->deadline) {
      changed_.wait_until(lock, absl::ToChronoTime(earliest->deadline));
    } else {
      // Stays listed until Run returns, which is when the job has stopped.
      earliest->stopped = true;
      std::shared_ptr<Job> job = earliest->job;
      lock.unlock();
      job->StopForTimeLimit(limit_);
      lock.lock();
    }
  }
}

}  // namespace getme::server
