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
#include "getme_server/job_directory.h"
#include "getme_server/server_metrics.h"

namespace getme::server {

// All jobs of the server by id with the owner that created each, and the bounded queue the
// workers take them from. A background sweeper drops results nobody fetched within the time to
// live. Callers see only their own jobs: another owner's job id is answered exactly like an
// unknown one, so ids do not leak (with authentication off everyone is the same owner).
// With a shared job store (--job_store) it holds only the jobs this replica runs (Adopt), for
// the time limit, metrics and shutdown; the store is then the front ends' JobDirectory.
class JobRegistry : public JobDirectory {
 public:
  // max_queued_bytes bounds the upload bytes of all QUEUED and RUNNING jobs together. Jobs made
  // from a JobSubmission publish progress at most every `progress_interval` per watcher and count
  // into `metrics` (may be null; must outlive the jobs).
  JobRegistry(int max_queued_jobs, absl::Duration result_ttl,
              std::int64_t max_queued_bytes = std::numeric_limits<std::int64_t>::max(),
              absl::Duration progress_interval = absl::Milliseconds(100),
              ServerMetrics* metrics = nullptr);
  ~JobRegistry();
  JobRegistry(const JobRegistry&) = delete;
  JobRegistry& operator=(const JobRegistry&) = delete;

  std::string NewJobId();
  // Queues the job: RESOURCE_EXHAUSTED at once when max_queued_jobs are already waiting or its
  // upload bytes would pass max_queued_bytes, UNAVAILABLE once the server stopped accepting.
  absl::Status Submit(std::shared_ptr<Job> job, std::string owner = {});
  // A job another replica queued in the shared store, which this one runs now: tracked like a
  // submitted job, never queued here.
  void Adopt(std::shared_ptr<Job> job, std::string owner);

  // JobDirectory: the same queue and jobs as above.
  bool keeps_uploads() const override { return false; }
  absl::StatusOr<SubmittedJob> Submit(JobSubmission submission, std::string owner) override;
  absl::StatusOr<std::shared_ptr<JobHandle>> FindJob(const std::string& id,
                                                     absl::string_view owner) const override;
  std::vector<v1::Job> DescribeJobs(absl::string_view owner) const override;
  // NOT_FOUND for ids the registry does not know (never issued, or forgotten after the TTL) and
  // for jobs of another owner, with the same message.
  absl::StatusOr<std::shared_ptr<Job>> Find(const std::string& id, absl::string_view owner) const;
  std::vector<std::shared_ptr<Job>> List(absl::string_view owner) const;  // newest first
  // Every owner's jobs, for server-wide figures (metrics) and shutdown.
  std::vector<std::shared_ptr<Job>> ListAllOwners() const;
  std::int64_t QueuedCount() const override;  // jobs waiting for a worker
  std::int64_t HeldBytes() const override;    // upload bytes of the QUEUED and RUNNING jobs
  bool accepting() const override;            // false once shutdown started

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
  const absl::Duration progress_interval_;
  ServerMetrics* const metrics_;

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
