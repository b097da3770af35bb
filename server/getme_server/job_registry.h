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

// All jobs of the server by id with the owner that created each, and the bounded queue the
// workers take them from. A background sweeper drops results nobody fetched within the time to
// live. Callers see only their own jobs: another owner's job id is answered exactly like an
// unknown one, so ids do not leak (with authentication off everyone is the same owner).
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
  absl::Status Submit(std::shared_ptr<Job> job, std::string owner = {});
  // NOT_FOUND for ids the registry does not know (never issued, or forgotten after the TTL) and
  // for jobs of another owner, with the same message.
  absl::StatusOr<std::shared_ptr<Job>> Find(const std::string& id, absl::string_view owner) const;
  std::vector<std::shared_ptr<Job>> List(absl::string_view owner) const;  // newest first
  // Every owner's jobs, for server-wide figures (metrics) and shutdown.
  std::vector<std::shared_ptr<Job>> ListAllOwners() const;
  std::int64_t QueuedCount() const;  // jobs waiting for a worker
  std::int64_t HeldBytes() const;    // upload bytes of the QUEUED and RUNNING jobs
  bool accepting() const;            // false once shutdown started

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
  struct OwnedJob {
    std::shared_ptr<Job> job;
    std::string owner;
  };
  absl::flat_hash_map<std::string, OwnedJob> jobs_;
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
