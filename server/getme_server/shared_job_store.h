#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "getme/v1/smoother.pb.h"
#include "getme_server/job_directory.h"
#include "getme_server/server_options.h"
#include "redis/redis_client.h"

namespace getme::server {

// A job as the store hands it to the replica that runs it (SharedJobStore::Take).
struct TakenJob {
  std::string id;
  std::string owner;
  v1::SmoothHeader header;
  std::int64_t upload_bytes = 0;
  std::uint32_t attempt = 1;
  std::uint64_t last_sequence = 0;  // the events so far; the run continues after it
  double created_unix_seconds = 0;
  std::string cancel_reason;  // asked while it was being requeued: stop at once
  // Submitted by a Smooth call, which fetches the result itself: Finish keeps it at least one
  // job lease, however short --result_ttl is.
  bool submitter_fetches_result = false;
  ReceivedUpload upload;
};

// What renewing a lease found (SharedJobStore::Renew).
struct LeaseState {
  bool held = false;          // false: the lease expired and the job went to another replica
  std::string cancel_reason;  // non-empty: a replica was asked to cancel the job
};

// The job directory every replica shares through one Redis (--job_store, issue 18;
// docs/replicas.md): job records, the queue, progress streams and results live in Redis, so any
// replica queues, finds, watches, cancels and fetches any job, and limits hold for the cluster.
// The replica that runs a job holds a lease on it (StoreWorkers renews it); a job whose lease
// expires is queued again and restarted from the beginning by another replica.
class SharedJobStore : public JobDirectory {
 public:
  // `replica` names this process in leases and logs (unique per replica).
  SharedJobStore(std::unique_ptr<redis::RedisClient> redis, const ServerOptions& options,
                 std::string replica);

  // JobDirectory.
  bool accepting() const override { return accepting_.load(); }
  bool keeps_uploads() const override { return true; }
  std::int64_t QueuedCount() const override;
  std::int64_t HeldBytes() const override;
  absl::StatusOr<SubmittedJob> Submit(JobSubmission submission, std::string owner) override;
  absl::StatusOr<std::shared_ptr<JobHandle>> FindJob(const std::string& id,
                                                     absl::string_view owner) const override;
  std::vector<v1::Job> DescribeJobs(absl::string_view owner) const override;

  // This replica stops queueing new jobs (SIGTERM); jobs already queued stay for the others.
  void StopAccepting() { accepting_.store(false); }

  // For StoreWorkers, the replica's side of a job's lease.
  // Waits up to `wait` for a queued job and takes it under a lease; nullopt when none came.
  absl::StatusOr<std::optional<TakenJob>> Take(absl::Duration wait);
  absl::StatusOr<LeaseState> Renew(const std::string& id);
  // Appends events (serialized v1::ProgressEvent) and the job's description; false if the job
  // is no longer this replica's.
  absl::StatusOr<bool> Append(const std::string& id, const v1::Job& describe,
                              std::uint64_t last_sequence, const std::vector<std::string>& events);
  // Stores the result messages (serialized v1::SmoothResponse) under a key of this attempt,
  // then ends the job with its final event; false if the job is no longer this replica's.
  absl::StatusOr<bool> Finish(const TakenJob& taken, const v1::Job& describe,
                              const std::optional<v1::SmoothResult>& summary,
                              const std::vector<std::string>& result_messages,
                              const v1::ProgressEvent& final_event);
  // Requeues the jobs whose lease expired, each after a `restarted` event; returns how many.
  absl::StatusOr<int> RequeueExpired();
  // Ends this replica's lease on `id` now, so the job is requeued (a drain that ran out of time).
  absl::Status ReleaseLease(const std::string& id);
  // Records that this replica is alive; LiveReplicas counts those heard from recently.
  absl::Status Heartbeat();
  std::optional<std::int64_t> LiveReplicas() const override;

  redis::RedisClient& redis() const { return *redis_; }
  const std::string& prefix() const { return prefix_; }
  const std::string& replica() const { return replica_; }
  absl::Duration result_ttl() const { return options_.result_ttl; }

  std::string JobKey(absl::string_view id) const;

 private:
  absl::StatusOr<std::optional<TakenJob>> TakeQueued();

  const std::unique_ptr<redis::RedisClient> redis_;
  const ServerOptions options_;
  const std::string replica_;
  const std::string prefix_;
  std::atomic<bool> accepting_{true};
};

}  // namespace getme::server
