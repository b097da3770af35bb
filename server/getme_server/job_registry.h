#pragma once

#include <condition_variable>
#include <deque>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "absl/container/flat_hash_map.h"
#include "absl/random/random.h"
#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "getme_server/job.h"

namespace getme::server {

// All jobs of the server by id, and the bounded queue the workers take them from. A background
// sweeper drops results nobody fetched within the time to live.
class JobRegistry {
 public:
  // max_queued_bytes bounds the upload bytes of all QUEUED and RUNNING jobs together.
  JobRegistry(int max_queued_jobs, absl::Duration result_ttl,
              std::int64_t max_queued_bytes = std::numeric_limits<std::int64_t>::max());
  ~JobRegistry();
  JobRegistry(const JobRegistry&) = delete;
  JobRegistry& operator=(const JobRegistry&) = delete;

  std::string NewJobId();
  // Queues the job: RESOURCE_EXHAUSTED at once when max_queued_jobs are already waiting or its
  // upload bytes would pass max_queued_bytes, UNAVAILABLE once the server stopped accepting.
  absl::Status Submit(std::shared_ptr<Job> job);
  // NOT_FOUND for ids the registry does not know (never issued, or forgotten after the TTL).
  absl::StatusOr<std::shared_ptr<Job>> Find(const std::string& id) const;
  std::vector<std::shared_ptr<Job>> List() const;  // newest first
  std::int64_t QueuedCount() const;                // jobs waiting for a worker
  std::int64_t HeldBytes() const;                  // upload bytes of the QUEUED and RUNNING jobs
  bool accepting() const;                          // false once shutdown started

  // Blocks until a queued job is available (returned) or the workers are stopped (nullptr).
  std::shared_ptr<Job> TakeNextQueued();

  // Shutdown, in this order: refuse new jobs and cancel the queued ones; wait (up to a deadline)
  // for running ones; cancel what still runs; release the workers.
  void StopAccepting(absl::string_view reason);
  bool WaitUntilNoneRunning(absl::Time deadline) const;
  void CancelAll(absl::string_view reason);
  void StopWorkers();

 private:
  void SweepLoop();
  std::int64_t QueuedCountLocked() const;
  std::int64_t HeldBytesLocked() const;

  const int max_queued_jobs_;
  const std::int64_t max_queued_bytes_;
  const absl::Duration result_ttl_;

  mutable std::mutex mutex_;
  std::condition_variable queue_changed_;
  absl::flat_hash_map<std::string, std::shared_ptr<Job>> jobs_;
  std::vector<std::shared_ptr<Job>> submission_order_;
  std::deque<std::shared_ptr<Job>> queue_;
  bool accepting_ = true;
  bool workers_stopped_ = false;
  absl::BitGen random_;

  std::condition_variable sweeper_wake_;
  bool sweeper_stop_ = false;
  std::thread sweeper_;
};

}  // namespace getme::server
