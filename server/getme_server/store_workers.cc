#include "getme_server/store_workers.h"

#include <algorithm>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "getme_server/job_result_stream.h"
#include "getme_server/job_submission.h"
#include "getme_server/process_memory.h"
#include "getme_wire/enums.h"
#include "getme_wire/mesh_upload.h"
#include "getme_wire/status.h"
#include "spdlog/spdlog.h"

namespace getme::server {
namespace {

// How long an idle worker waits on the store's doorbell before it looks again.
constexpr absl::Duration kTakeWait = absl::Seconds(1);
// A worker that cannot reach the store waits this long before it tries again.
constexpr absl::Duration kStoreRetry = absl::Seconds(1);
constexpr absl::Duration kHeartbeat = absl::Seconds(1);

absl::StatusOr<wire::UploadedMesh> RebuildMesh(const ReceivedUpload& upload,
                                               std::int64_t max_elements) {
  wire::MeshUpload builder(max_elements);
  for (const std::string& bytes : upload.chunks) {
    v1::MeshChunk chunk;
    if (!chunk.ParseFromString(bytes)) {
      return absl::DataLossError("a stored upload chunk does not parse as a MeshChunk");
    }
    if (auto s = builder.Add(chunk); !s.ok()) return s;
  }
  if (!upload.whole_mesh.empty()) {
    v1::Mesh mesh;
    if (!mesh.ParseFromString(upload.whole_mesh)) {
      return absl::DataLossError("a stored upload does not parse as a Mesh");
    }
    if (auto s = builder.Add(mesh); !s.ok()) return s;
  }
  return std::move(builder).Finish();
}

}  // namespace

StoreWorkers::StoreWorkers(SharedJobStore& store, JobRegistry& local, const ServerOptions& options,
                           ServerMetrics* metrics)
    : store_(store),
      local_(local),
      options_(options),
      metrics_(metrics),
      time_limit_(options.max_job_time) {
  for (int i = 0; i < options.workers; ++i) workers_.emplace_back([this] { WorkLoop(); });
  keeper_ = std::thread([this] { KeeperLoop(); });
}

StoreWorkers::~StoreWorkers() {
  StopTaking();
  Join();
}

void StoreWorkers::StopTaking() {
  std::lock_guard lock(mutex_);
  taking_.store(false);
}

bool StoreWorkers::WaitUntilNoneRunning(absl::Time deadline) {
  std::unique_lock lock(mutex_);
  return none_running_.wait_until(lock, absl::ToChronoTime(deadline),
                                  [this] { return running_.empty(); });
}

std::shared_ptr<StoreWorkers::Running> StoreWorkers::Register(const TakenJob& taken) {
  std::lock_guard lock(mutex_);
  if (!taking_.load()) return nullptr;
  auto running = std::make_shared<Running>();
  running->id = taken.id;
  running_[taken.id] = running;
  return running;
}

void StoreWorkers::Unregister(const std::string& id) {
  {
    std::lock_guard lock(mutex_);
    running_.erase(id);
  }
  none_running_.notify_all();
}

void StoreWorkers::Join() {
  for (std::thread& worker : workers_) {
    if (worker.joinable()) worker.join();
  }
  {
    std::lock_guard lock(mutex_);
    keeper_stop_ = true;
  }
  keeper_wake_.notify_all();
  if (keeper_.joinable()) keeper_.join();
}

std::vector<std::shared_ptr<StoreWorkers::Running>> StoreWorkers::RunningNow() const {
  std::lock_guard lock(mutex_);
  std::vector<std::shared_ptr<Running>> running;
  for (const auto& entry : running_) running.push_back(entry.second);
  return running;
}

void StoreWorkers::ReleaseRunning(absl::string_view reason) {
  for (const std::shared_ptr<Running>& running : RunningNow()) {
    {
      std::lock_guard lock(running->mutex);
      running->lost = true;
    }
    if (auto s = store_.ReleaseLease(running->id); !s.ok()) {
      spdlog::warn("job={} could not release its lease: {}", running->id, s.ToString());
    }
    spdlog::info("job={} handed back to the job store: {}", running->id, std::string(reason));
    // Read after `lost` was set: a job whose mesh is still being rebuilt is not there yet, and
    // RunTaken, which checks `lost` after it sets the job, cancels it itself.
    std::shared_ptr<Job> job;
    {
      std::lock_guard lock(mutex_);
      job = running->job;
    }
    if (job != nullptr) job->Cancel(reason);
  }
}

void StoreWorkers::WorkLoop() {
  while (taking_.load()) {
    absl::StatusOr<std::optional<TakenJob>> taken = store_.Take(kTakeWait);
    if (!taken.ok()) {
      spdlog::warn("job store: taking a job failed: {}", taken.status().ToString());
      absl::SleepFor(kStoreRetry);
      continue;
    }
    if (!taken->has_value()) continue;
    std::shared_ptr<Running> running = Register(**taken);
    if (running == nullptr) {
      // Taken just as this replica began to drain: give it straight back.
      (void)store_.ReleaseLease((*taken)->id);
      break;
    }
    RunTaken(**std::move(taken), std::move(running));
    ReleaseFreedHeapMemory();
  }
}

v1::Job StoreWorkers::DescribeForStore(const Job& job, const Running& running) const {
  v1::Job describe = job.Describe();
  describe.set_created_unix_seconds(running.created_unix_seconds);
  describe.set_result_available(false);  // the store knows; readers ask it
  return describe;
}

void StoreWorkers::Flush(Running& running) {
  std::shared_ptr<Job> job;
  {
    std::lock_guard lock(mutex_);
    job = running.job;
  }
  if (job == nullptr) return;
  std::vector<std::string> events;
  std::uint64_t last_sequence = 0;
  {
    std::lock_guard lock(running.mutex);
    if (running.lost) return;
    events = std::move(running.pending);
    running.pending.clear();
    if (running.latest.has_value()) {
      events.push_back(running.latest->SerializeAsString());
      running.latest.reset();
    }
    last_sequence = running.last_sequence;
    if (events.empty() && last_sequence == running.flushed_sequence) return;
  }
  // Sent without the lock: the job's sink must never wait for the store.
  absl::StatusOr<bool> appended =
      store_.Append(running.id, DescribeForStore(*job, running), last_sequence, events);
  if (!appended.ok()) {
    spdlog::warn("job={} events not written to the job store: {}", running.id,
                 appended.status().ToString());
    return;
  }
  std::lock_guard lock(running.mutex);
  if (!*appended) {
    running.lost = true;
  } else {
    running.flushed_sequence = std::max(running.flushed_sequence, last_sequence);
  }
}

// `running` was registered (Register) before the mesh is rebuilt: the keeper renews its lease
// meanwhile, so a large upload does not outlast it, and a drain waits for it.
void StoreWorkers::RunTaken(TakenJob taken, std::shared_ptr<Running> running) {
  spdlog::info("job={} phase=taken attempt={} replica={}", taken.id, taken.attempt,
               store_.replica());
  absl::StatusOr<wire::UploadedMesh> mesh = RebuildMesh(taken.upload, options_.max_elements);
  absl::StatusOr<SmoothingParams> params =
      mesh.ok() ? CheckJobRequest(taken.header, options_) : mesh.status();
  if (!mesh.ok() || !params.ok()) {
    // The queueing replica checked the same upload: only a store that lost data, or replicas
    // with different limits, get here. The job fails with the reason instead of being dropped.
    const absl::Status why = mesh.ok() ? params.status() : mesh.status();
    v1::Job describe;
    describe.set_job_id(taken.id);
    describe.set_state(v1::JOB_STATE_FAILED);
    describe.set_created_unix_seconds(taken.created_unix_seconds);
    wire::ToWireJobError(why, describe);
    v1::ProgressEvent final_event;
    final_event.set_job_id(taken.id);
    final_event.set_sequence(taken.last_sequence + 1);
    final_event.set_attempt(taken.attempt);
    final_event.set_final(true);
    spdlog::error("job={} phase=done outcome=FAILED error={}", taken.id,
                  std::string(why.message()));
    (void)store_.Finish(taken, describe, std::nullopt, {}, final_event);
    Unregister(taken.id);
    return;
  }

  auto job =
      std::make_shared<Job>(taken.id, *std::move(mesh), taken.upload_bytes, *params,
                            taken.header.result_options(), options_.progress_interval, metrics_);
  taken.upload = {};
  running->attempt = taken.attempt;
  running->created_unix_seconds = taken.created_unix_seconds;
  running->last_sequence = taken.last_sequence;
  running->flushed_sequence = taken.last_sequence;
  // Called with the job's mutex held: it only files the event for the keeper's next flush.
  job->ContinueStoredJob(taken.last_sequence, taken.attempt,
                         [sink = running.get()](const v1::ProgressEvent& event) {
                           std::lock_guard lock(sink->mutex);
                           sink->last_sequence = event.sequence();
                           if (event.final()) {
                             sink->final_event = event;
                           } else if (event.phase_done()) {
                             if (sink->latest.has_value()) {
                               sink->pending.push_back(sink->latest->SerializeAsString());
                               sink->latest.reset();
                             }
                             sink->pending.push_back(event.SerializeAsString());
                           } else {
                             sink->latest = event;  // throttled: the newest wins
                           }
                         });
  {
    std::lock_guard lock(mutex_);
    running->job = job;
  }
  // The local registry's sweeper counts --result_ttl too: without the hold, a short one dropped
  // the result before it was copied to the store below, and the job ended SUCCEEDED with none.
  ResultHold until_stored = job->HoldResult();
  local_.Adopt(job, taken.owner);
  std::string cancel = taken.cancel_reason;
  {
    // What the keeper learnt while the mesh was rebuilt.
    std::lock_guard lock(running->mutex);
    if (running->lost) cancel = "its lease went to another replica";
    if (cancel.empty()) cancel = running->cancel_applied;
  }
  if (!cancel.empty()) {
    job->Cancel(cancel);
  } else {
    time_limit_.Run(job);
  }

  Flush(*running);
  Unregister(taken.id);
  bool lost = false;
  std::optional<v1::ProgressEvent> final_event;
  {
    std::lock_guard lock(running->mutex);
    lost = running->lost;
    final_event = running->final_event;
  }
  if (lost) {
    spdlog::warn("job={} phase=abandoned attempt={}: its lease went to another replica", taken.id,
                 taken.attempt);
    return;
  }
  std::vector<std::string> messages;
  if (job->state() == v1::JOB_STATE_SUCCEEDED) {
    absl::StatusOr<JobResult> result = job->TakeResult();
    if (result.ok()) {
      JobResultStream stream(*std::move(result), nullptr);
      v1::SmoothResponse message;
      while (stream.Next(message)) {
        messages.push_back(message.SerializeAsString());
        message.Clear();
      }
    }
  }
  if (!final_event.has_value()) {
    final_event.emplace();
    final_event->set_job_id(taken.id);
    final_event->set_sequence(running->last_sequence + 1);
    final_event->set_final(true);
  }
  const v1::Job described = DescribeForStore(*job, *running);
  absl::StatusOr<bool> finished =
      store_.Finish(taken, described, job->Summary(), messages, *final_event);
  if (!finished.ok() && !messages.empty()) {
    // The result did not fit (a full Redis refuses writes): the job fails saying so, rather than
    // expiring, being requeued and failing the same way again.
    spdlog::error("job={} result not written to the job store: {}", taken.id,
                  finished.status().ToString());
    v1::Job failed = described;
    failed.set_state(v1::JOB_STATE_FAILED);
    wire::ToWireJobError(
        absl::ResourceExhaustedError(absl::StrCat(
            "job ", taken.id, " succeeded but the shared job store could not keep its result (",
            finished.status().message(), "); submit it again once results were fetched")),
        failed);
    finished = store_.Finish(taken, failed, std::nullopt, {}, *final_event);
  }
  if (!finished.ok()) {
    spdlog::error("job={} end not written to the job store: {}", taken.id,
                  finished.status().ToString());
  } else if (!*finished) {
    spdlog::warn("job={} phase=abandoned attempt={}: its lease went to another replica", taken.id,
                 taken.attempt);
  }
}

void StoreWorkers::KeeperLoop() {
  const absl::Duration flush_every =
      std::clamp(options_.progress_interval, absl::Milliseconds(20), absl::Seconds(1));
  const absl::Duration renew_every = options_.job_lease / 3;
  const absl::Duration reap_every = options_.job_lease / 2;
  absl::Time next_renew = absl::Now();
  absl::Time next_reap = absl::Now();
  absl::Time next_heartbeat = absl::Now();
  std::unique_lock lock(mutex_);
  while (!keeper_stop_) {
    lock.unlock();
    const absl::Time now = absl::Now();
    const std::vector<std::shared_ptr<Running>> running = RunningNow();
    for (const std::shared_ptr<Running>& job : running) Flush(*job);
    if (now >= next_renew) {
      next_renew = now + renew_every;
      for (const std::shared_ptr<Running>& job : running) {
        absl::StatusOr<LeaseState> lease = store_.Renew(job->id);
        if (!lease.ok()) {
          spdlog::warn("job={} lease not renewed: {}", job->id, lease.status().ToString());
          continue;
        }
        std::string cancel;
        {
          std::lock_guard job_lock(job->mutex);
          if (!lease->held) job->lost = true;
          if (!lease->cancel_reason.empty() && job->cancel_applied.empty()) {
            job->cancel_applied = lease->cancel_reason;
            cancel = lease->cancel_reason;
          }
        }
        std::shared_ptr<Job> local;
        {
          std::lock_guard running_lock(mutex_);
          local = job->job;
        }
        if (local == nullptr) continue;  // still rebuilding: it checks `lost` when it starts
        if (!lease->held) {
          local->Cancel("its lease went to another replica");
        } else if (!cancel.empty()) {
          local->Cancel(cancel);
        }
      }
    }
    if (now >= next_reap) {
      next_reap = now + reap_every;
      if (absl::StatusOr<int> requeued = store_.RequeueExpired(); !requeued.ok()) {
        spdlog::warn("job store: requeueing expired jobs failed: {}", requeued.status().ToString());
      }
    }
    if (now >= next_heartbeat) {
      next_heartbeat = now + kHeartbeat;
      if (auto s = store_.Heartbeat(); !s.ok()) {
        spdlog::warn("job store: heartbeat failed: {}", s.ToString());
      }
    }
    lock.lock();
    keeper_wake_.wait_for(lock, absl::ToChronoNanoseconds(flush_every),
                          [this] { return keeper_stop_; });
  }
}

}  // namespace getme::server
