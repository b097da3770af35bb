#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "getme/smoothing/progress.h"
#include "getme/smoothing/smoothing_params.h"
#include "getme/v1/smoother.pb.h"
#include "getme_server/job_handle.h"
#include "getme_server/job_run.h"
#include "getme_server/job_trace.h"
#include "getme_server/progress_fanout.h"
#include "getme_server/result_hold.h"
#include "getme_server/server_metrics.h"
#include "getme_wire/mesh_upload.h"

namespace getme::server {

// One smoothing job's state machine: QUEUED → RUNNING → SUCCEEDED | FAILED | CANCELLED (QUEUED →
// CANCELLED when cancelled before a worker takes it). Thread-safe; shared by the registry, a worker
// and the handlers watching it.
class Job : public JobHandle, public std::enable_shared_from_this<Job> {
 public:
  // `upload_bytes` is the encoded size of the uploaded mesh. `metrics` (may be null) counts the
  // job's work and outcome; it must outlive the job.
  Job(std::string id, wire::UploadedMesh mesh, std::int64_t upload_bytes, SmoothingParams params,
      v1::ResultOptions options, absl::Duration progress_interval,
      ServerMetrics* metrics = nullptr);

  const std::string& id() const override { return id_; }
  // Encoded size of the uploaded mesh: what the job counts against --max_queued_bytes.
  std::int64_t upload_bytes() const { return upload_bytes_; }

  // Runs the engine on the calling (worker) thread (job_run.h); returns at once unless the job is
  // QUEUED.
  // `start` is the start time the job reports; --max_job_time counts from the same instant.
  void Run(absl::Time start);
  // Queued: CANCELLED at once. Running: the engine stops within one iteration. Final: no-op.
  void Cancel(absl::string_view reason) override;
  // Running: the engine stops within one iteration and the job FAILS with DEADLINE_EXCEEDED
  // naming the limit. Otherwise a no-op.
  void StopForTimeLimit(absl::Duration limit);
  // For a job a shared store handed to this replica (store_worker.h), before Run: its events
  // continue the stored sequence after `last_sequence`, carry `attempt`, and go to `sink` as well
  // (called with the job's mutex held, in order: it must not block).
  void ContinueStoredJob(std::uint64_t last_sequence, std::uint32_t attempt,
                         std::function<void(const v1::ProgressEvent&)> sink);

  v1::JobState state() const;
  bool final() const override;
  v1::Job Describe() const override;
  // A watcher of the progress events, starting with the latest one.
  std::shared_ptr<ProgressFanout::Watcher> Watch() { return fanout_.Watch(); }
  std::shared_ptr<EventSource> WatchEvents() override { return Watch(); }
  // The job's outcome: OK for SUCCEEDED, else the status it failed or was cancelled with.
  absl::Status outcome() const override;
  // The summary of a SUCCEEDED job (quality before/after with histograms, phases), kept after
  // the result itself was fetched or expired; nullopt for other states.
  std::optional<v1::SmoothResult> Summary() const override;
  // The job's events so far, thinned to at most about kMaxTrace (every phase_done and the final
  // event kept), so a dashboard opened late or reloaded can draw the whole run.
  std::vector<v1::ProgressEvent> Trace() const override;
  static constexpr std::size_t kMaxTrace = JobTrace::kMaxEvents;
  // Element transforms per second since the job started running (0 unless RUNNING): a
  // simultaneous-type iteration transforms every element, a sequential pick one.
  double ElementIterationRate() const;

  // Hands the result out once. FAILED/CANCELLED jobs give their outcome, unfinished ones
  // FAILED_PRECONDITION, fetched or expired results NOT_FOUND.
  absl::StatusOr<JobResult> TakeResult();
  // TakeResult as the messages GetResult sends; GiveBack restores the result.
  absl::StatusOr<std::unique_ptr<ResultStream>> TakeResultStream() override;
  // Gives back a result TakeResult handed out whose download did not complete, so the caller can
  // fetch it again (until the time to live passes).
  void RestoreResult(JobResult result);
  // Drops an unfetched result `ttl` after the job finished; true once the job is final for
  // twice that (the registry then forgets it). A held result neither expires nor is forgotten.
  bool ExpireIfOlderThan(absl::Time now, absl::Duration ttl);
  // Keeps the result until the returned hold is destroyed (result_hold.h), for the
  // Smooth call that waits on the job. The hold shares the job (made by std::make_shared).
  ResultHold HoldResult();

 private:
  void Publish(v1::ProgressEvent event);        // stamps job id and sequence
  void PublishLocked(v1::ProgressEvent event);  // the same, with mutex_ held
  void FinishLocked(absl::Status outcome);

  const std::string id_;
  const std::int64_t upload_bytes_;
  const SmoothingParams params_;
  const std::uint64_t nodes_;
  const std::uint64_t elements_;
  const absl::Time created_;
  ServerMetrics* const metrics_;
  CancellationToken cancel_;
  ProgressFanout fanout_;

  mutable std::mutex mutex_;
  v1::JobState state_ = v1::JOB_STATE_QUEUED;
  absl::Time started_ = absl::InfinitePast();
  absl::Time finished_ = absl::InfinitePast();
  absl::Status outcome_;
  std::string cancel_reason_;
  std::optional<absl::Duration> time_limit_hit_;  // set by StopForTimeLimit
  std::uint64_t sequence_ = 0;
  std::uint32_t attempt_ = 0;                                 // 0: not from a shared store
  std::function<void(const v1::ProgressEvent&)> event_sink_;  // shared store only
  std::optional<v1::SmoothResult> summary_;
  JobTrace trace_;
  bool result_taken_ = false;
  bool result_expired_ = false;
  int result_holds_ = 0;
  std::unique_ptr<JobResult> result_;  // input mesh while queued/running, result once SUCCEEDED
};

}  // namespace getme::server
