#pragma once

#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

#include "absl/time/time.h"
#include "getme_server/job.h"

namespace getme::server {

// Stops jobs that run longer than --max_job_time. The engine cannot watch the clock itself (an
// iteration of a huge mesh may take long, and it only checks its cancellation token), so one
// thread sleeps until the earliest deadline of the running jobs and stops the job it belongs to.
// There are as many running jobs as workers, so a scan for the earliest deadline is cheap.
class JobTimeLimit {
 public:
  // InfiniteDuration: no limit and no thread.
  explicit JobTimeLimit(absl::Duration limit);
  ~JobTimeLimit();
  JobTimeLimit(const JobTimeLimit&) = delete;
  JobTimeLimit& operator=(const JobTimeLimit&) = delete;

  // Runs the job on the calling thread under the limit (from now, i.e. from when it starts
  // running: time spent queued does not count).
  void Run(const std::shared_ptr<Job>& job);

 private:
  struct Running {
    absl::Time deadline;
    std::shared_ptr<Job> job;
    bool stopped = false;
  };
  void WatchLoop();

  const absl::Duration limit_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::map<std::uint64_t, Running> running_;  // by run number
  std::uint64_t runs_ = 0;
  bool stop_ = false;
  std::thread watcher_;
};

}  // namespace getme::server
