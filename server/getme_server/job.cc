#include "getme_server/job.h"

#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "getme/smoothing/smoother.h"
#include "getme_server/job_result_stream.h"
#include "getme_wire/enums.h"
#include "getme_wire/progress.h"
#include "getme_wire/status.h"
#include "spdlog/spdlog.h"

namespace getme::server {
namespace {

double UnixSeconds(absl::Time t) {
  return t == absl::InfinitePast() ? 0.0 : absl::ToDoubleSeconds(t - absl::UnixEpoch());
}

const char* StateName(v1::JobState state) {
  return v1::JobState_Name(state).c_str() + sizeof("JOB_STATE_") - 1;
}

}  // namespace

Job::Job(std::string id, wire::UploadedMesh mesh, std::int64_t upload_bytes, SmoothingParams params,
         v1::ResultOptions options, absl::Duration progress_interval, ServerMetrics* metrics)
    : id_(std::move(id)),
      upload_bytes_(upload_bytes),
      params_(params),
      nodes_(static_cast<std::uint64_t>(mesh.mesh.node_count())),
      elements_(static_cast<std::uint64_t>(mesh.mesh.element_count())),
      created_(absl::Now()),
      metrics_(metrics),
      fanout_(progress_interval),
      trace_(elements_),
      result_(std::make_unique<JobResult>()) {
  result_->mesh = std::move(mesh.mesh);
  result_->ids = std::move(mesh.ids);
  result_->surface_groups = std::move(mesh.surface_groups);
  result_->options = std::move(options);
}

void Job::Publish(v1::ProgressEvent event) {
  std::lock_guard lock(mutex_);
  PublishLocked(std::move(event));
}

void Job::PublishLocked(v1::ProgressEvent event) {
  event.set_job_id(id_);
  event.set_sequence(++sequence_);
  if (attempt_ > 0) event.set_attempt(attempt_);
  const std::uint64_t element_iterations = trace_.Record(event);
  if (metrics_ != nullptr && element_iterations > 0) {
    metrics_->AddElementIterations(element_iterations);
  }
  fanout_.Publish(event);
  if (event_sink_ != nullptr) event_sink_(event);
}

void Job::ContinueStoredJob(std::uint64_t last_sequence, std::uint32_t attempt,
                            std::function<void(const v1::ProgressEvent&)> sink) {
  std::lock_guard lock(mutex_);
  sequence_ = last_sequence;
  attempt_ = attempt;
  event_sink_ = std::move(sink);
}

void Job::Run(absl::Time start) {
  JobResult* work = nullptr;
  {
    std::lock_guard lock(mutex_);
    if (state_ != v1::JOB_STATE_QUEUED) return;
    state_ = v1::JOB_STATE_RUNNING;
    started_ = start;
    work = result_.get();
  }
  spdlog::info("job={} phase=start nodes={} elements={} method={} threads={}", id_, nodes_,
               elements_, MethodName(params_.method), params_.threads);

  // Only the worker touches `work` until the job is final (cancellation uses the token).
  absl::Status outcome = RunSmoothing(
      *work, params_, [this](const ProgressEvent& event) { Publish(wire::ToWireEvent(event)); },
      &cancel_);

  v1::ProgressEvent final_event;
  {
    std::lock_guard lock(mutex_);
    if (trace_.latest().has_value()) {
      final_event = *trace_.latest();
      final_event.set_phase_done(false);
    }
  }
  if (outcome.ok()) {
    work->summary.set_job_id(id_);
    final_event.set_q_min(work->summary.after().q_min());
    final_event.set_q_mean(work->summary.after().q_mean());
    final_event.set_invalid_elements(work->summary.after().invalid_elements());
  }
  double seconds = 0;
  {
    std::lock_guard lock(mutex_);
    if (outcome.code() == absl::StatusCode::kCancelled && time_limit_hit_.has_value()) {
      outcome = absl::DeadlineExceededError(
          absl::StrCat("job ", id_, " stopped: it ran longer than the server's limit of ",
                       absl::FormatDuration(*time_limit_hit_), " per job (--max_job_time)"));
    } else if (outcome.code() == absl::StatusCode::kCancelled && !cancel_reason_.empty()) {
      outcome = absl::CancelledError(absl::StrCat("job ", id_, " cancelled: ", cancel_reason_));
    }
    FinishLocked(outcome);
    seconds = absl::ToDoubleSeconds(finished_ - started_);
    // In the same critical section as the final state: whoever sees the job final also sees its
    // final event as the latest progress.
    final_event.set_elapsed_seconds(seconds);
    final_event.set_final(true);
    PublishLocked(std::move(final_event));
  }
  if (outcome.code() == absl::StatusCode::kInternal) {
    // An engine fault (e.g. the result check refused the mesh): never a silent failure.
    spdlog::error("job={} phase=result-check error={}", id_, std::string(outcome.message()));
  }
  spdlog::info("job={} phase=done nodes={} elements={} method={} seconds={:.3f} outcome={}{}{}",
               id_, nodes_, elements_, MethodName(params_.method), seconds, StateName(state()),
               outcome.ok() ? "" : " error=", outcome.ok() ? "" : std::string(outcome.message()));
}

void Job::FinishLocked(absl::Status outcome) {
  finished_ = absl::Now();
  outcome_ = std::move(outcome);
  if (outcome_.ok()) {
    state_ = v1::JOB_STATE_SUCCEEDED;
    summary_ = result_->summary;
  } else {
    state_ = outcome_.code() == absl::StatusCode::kCancelled ? v1::JOB_STATE_CANCELLED
                                                             : v1::JOB_STATE_FAILED;
    result_.reset();
  }
  if (metrics_ != nullptr) {
    const bool ran = started_ != absl::InfinitePast();
    metrics_->CountFinishedJob(state_, ran ? absl::ToDoubleSeconds(finished_ - started_) : -1.0);
  }
}

void Job::Cancel(absl::string_view reason) {
  bool cancelled_while_queued = false;
  {
    std::lock_guard lock(mutex_);
    if (state_ != v1::JOB_STATE_QUEUED && state_ != v1::JOB_STATE_RUNNING) return;
    if (cancel_reason_.empty()) cancel_reason_ = std::string(reason);
    if (state_ == v1::JOB_STATE_QUEUED) {
      FinishLocked(absl::CancelledError(absl::StrCat("job ", id_, " cancelled: ", reason)));
      v1::ProgressEvent final_event;
      final_event.set_final(true);
      PublishLocked(std::move(final_event));
      cancelled_while_queued = true;
    }
  }
  cancel_.Cancel();
  if (cancelled_while_queued) {
    spdlog::info(
        "job={} phase=done nodes={} elements={} method={} seconds=0 outcome=CANCELLED "
        "reason=\"{}\" (while queued)",
        id_, nodes_, elements_, MethodName(params_.method), std::string(reason));
  } else {
    spdlog::info("job={} cancel requested: {}", id_, std::string(reason));
  }
}

void Job::StopForTimeLimit(absl::Duration limit) {
  {
    std::lock_guard lock(mutex_);
    // A cancel that came first keeps its reason.
    if (state_ != v1::JOB_STATE_RUNNING || !cancel_reason_.empty()) return;
    time_limit_hit_ = limit;
  }
  cancel_.Cancel();
  spdlog::warn("job={} stopping: running longer than --max_job_time={}", id_,
               absl::FormatDuration(limit));
}

v1::JobState Job::state() const {
  std::lock_guard lock(mutex_);
  return state_;
}

bool Job::final() const {
  const v1::JobState s = state();
  return s != v1::JOB_STATE_QUEUED && s != v1::JOB_STATE_RUNNING;
}

absl::Status Job::outcome() const {
  std::lock_guard lock(mutex_);
  return outcome_;
}

std::vector<v1::ProgressEvent> Job::Trace() const {
  std::lock_guard lock(mutex_);
  return trace_.events();
}

std::optional<v1::SmoothResult> Job::Summary() const {
  std::lock_guard lock(mutex_);
  return summary_;
}

double Job::ElementIterationRate() const {
  std::lock_guard lock(mutex_);
  if (state_ != v1::JOB_STATE_RUNNING) return 0.0;
  const double seconds = absl::ToDoubleSeconds(absl::Now() - started_);
  return seconds > 0 ? static_cast<double>(trace_.element_iterations()) / seconds : 0.0;
}

v1::Job Job::Describe() const {
  std::lock_guard lock(mutex_);
  v1::Job job;
  job.set_job_id(id_);
  job.set_state(state_);
  job.set_method(wire::ToWireMethod(params_.method));
  job.set_nodes(nodes_);
  job.set_elements(elements_);
  job.set_created_unix_seconds(UnixSeconds(created_));
  job.set_started_unix_seconds(UnixSeconds(started_));
  job.set_finished_unix_seconds(UnixSeconds(finished_));
  if (trace_.latest().has_value()) *job.mutable_latest_progress() = *trace_.latest();
  if (!outcome_.ok()) wire::ToWireJobError(outcome_, job);
  job.set_result_available(state_ == v1::JOB_STATE_SUCCEEDED && result_ != nullptr);
  return job;
}

absl::StatusOr<JobResult> Job::TakeResult() {
  std::lock_guard lock(mutex_);
  switch (state_) {
    case v1::JOB_STATE_QUEUED:
    case v1::JOB_STATE_RUNNING:
      return absl::FailedPreconditionError(
          absl::StrCat("job ", id_, " is ", StateName(state_), ": it has no result yet"));
    case v1::JOB_STATE_SUCCEEDED:
      break;
    default:
      return outcome_;
  }
  if (result_ == nullptr) {
    return absl::NotFoundError(absl::StrCat(
        "the result of job ", id_,
        " is gone: ", result_expired_ ? "its time to live passed" : "it was already fetched"));
  }
  JobResult taken = std::move(*result_);
  result_.reset();
  result_taken_ = true;
  return taken;
}

absl::StatusOr<std::unique_ptr<ResultStream>> Job::TakeResultStream() {
  absl::StatusOr<JobResult> result = TakeResult();
  if (!result.ok()) return result.status();
  // The stream lives no longer than the call that fetches it; the job outlives that call (the
  // handler holds it).
  return std::make_unique<JobResultStream>(
      *std::move(result), [this](JobResult back) { RestoreResult(std::move(back)); });
}

void Job::RestoreResult(JobResult result) {
  std::lock_guard lock(mutex_);
  if (state_ != v1::JOB_STATE_SUCCEEDED || result_ != nullptr || result_expired_) return;
  result_ = std::make_unique<JobResult>(std::move(result));
  result_taken_ = false;
}

bool Job::ExpireIfOlderThan(absl::Time now, absl::Duration ttl) {
  std::lock_guard lock(mutex_);
  if (state_ == v1::JOB_STATE_QUEUED || state_ == v1::JOB_STATE_RUNNING) return false;
  if (now - finished_ < ttl || result_holds_ > 0) return false;
  if (result_ != nullptr) {
    result_.reset();
    result_expired_ = true;
    spdlog::info("job={} result expired after {}", id_, absl::FormatDuration(ttl));
  }
  // The record outlives its result for a while, so GetResult can say why the result is gone.
  return now - finished_ >= 2 * ttl;
}

ResultHold Job::HoldResult() {
  {
    std::lock_guard lock(mutex_);
    ++result_holds_;
  }
  return ResultHold([job = shared_from_this()] {
    std::lock_guard lock(job->mutex_);
    --job->result_holds_;
  });
}

}  // namespace getme::server
