#include "getme_server/job_registry.h"

#include <algorithm>
#include <chrono>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/time/clock.h"
#include "getme_server/process_memory.h"

namespace getme::server {

JobRegistry::JobRegistry(int max_queued_jobs, absl::Duration result_ttl,
                         std::int64_t max_queued_bytes, absl::Duration progress_interval,
                         ServerMetrics* metrics)
    : max_queued_jobs_(max_queued_jobs),
      max_queued_bytes_(max_queued_bytes),
      result_ttl_(result_ttl),
      progress_interval_(progress_interval),
      metrics_(metrics) {
  sweeper_ = std::thread([this] { SweepLoop(); });
}

JobRegistry::~JobRegistry() {
  {
    std::lock_guard lock(mutex_);
    sweeper_stop_ = true;
  }
  sweeper_wake_.notify_all();
  sweeper_.join();
}

std::string JobRegistry::NewJobId() {
  std::lock_guard lock(mutex_);
  std::string id;
  do {
    id = absl::StrFormat("%012x", absl::Uniform<std::uint64_t>(random_, 0, std::uint64_t{1} << 48));
  } while (jobs_.contains(id));
  return id;
}

std::int64_t JobRegistry::QueuedCountLocked() const {
  return std::count_if(queue_.begin(), queue_.end(),
                       [](const auto& job) { return job->state() == v1::JOB_STATE_QUEUED; });
}

std::int64_t JobRegistry::HeldBytesLocked() const {
  // Every QUEUED or RUNNING job is in submission_order_ (the sweeper forgets only final ones).
  std::int64_t bytes = 0;
  for (const auto& job : submission_order_) {
    if (!job->final()) bytes += job->upload_bytes();
  }
  return bytes;
}

std::int64_t JobRegistry::HeldBytes() const {
  std::lock_guard lock(mutex_);
  return HeldBytesLocked();
}

absl::Status JobRegistry::Submit(std::shared_ptr<Job> job, std::string owner) {
  {
    std::lock_guard lock(mutex_);
    if (!accepting_) {
      return absl::UnavailableError("the server is shutting down and accepts no new jobs");
    }
    // Jobs cancelled while queued leave the queue here (or when a worker reaches them).
    std::erase_if(queue_, [](const auto& queued) { return queued->final(); });
    if (QueuedCountLocked() >= max_queued_jobs_) {
      return absl::ResourceExhaustedError(
          absl::StrCat("the job queue is full: ", max_queued_jobs_,
                       " jobs are waiting for a worker (--max_queued_jobs); retry later"));
    }
    if (const std::int64_t held = HeldBytesLocked();
        held + job->upload_bytes() > max_queued_bytes_) {
      return absl::ResourceExhaustedError(
          absl::StrCat("queued and running jobs hold ", held, " bytes of meshes; this job's ",
                       job->upload_bytes(), " bytes would pass the server's limit of ",
                       max_queued_bytes_, " bytes (--max_queued_bytes); retry later"));
    }
    jobs_[job->id()] = {job, std::move(owner)};
    submission_order_.push_back(job);
    queue_.push_back(std::move(job));
  }
  queue_changed_.notify_one();
  return absl::OkStatus();
}

absl::StatusOr<SubmittedJob> JobRegistry::Submit(JobSubmission submission, std::string owner) {
  auto job = std::make_shared<Job>(NewJobId(), std::move(submission.mesh), submission.upload_bytes,
                                   submission.params, submission.header.result_options(),
                                   progress_interval_, metrics_);
  // Watching before queueing: the caller sees every event from the first one.
  std::shared_ptr<EventSource> events = job->Watch();
  ResultHold hold = submission.submitter_fetches_result ? job->HoldResult() : ResultHold();
  if (auto s = Submit(job, std::move(owner)); !s.ok()) return s;
  return SubmittedJob{std::move(job), std::move(events), std::move(hold)};
}

void JobRegistry::Adopt(std::shared_ptr<Job> job, std::string owner) {
  std::lock_guard lock(mutex_);
  jobs_[job->id()] = {job, std::move(owner)};
  submission_order_.push_back(std::move(job));
}

absl::StatusOr<std::shared_ptr<JobHandle>> JobRegistry::FindJob(const std::string& id,
                                                                absl::string_view owner) const {
  absl::StatusOr<std::shared_ptr<Job>> job = Find(id, owner);
  if (!job.ok()) return job.status();
  return std::shared_ptr<JobHandle>(*std::move(job));
}

std::vector<v1::Job> JobRegistry::DescribeJobs(absl::string_view owner) const {
  std::vector<v1::Job> described;
  for (const auto& job : List(owner)) described.push_back(job->Describe());
  return described;
}

absl::StatusOr<std::shared_ptr<Job>> JobRegistry::Find(const std::string& id,
                                                       absl::string_view owner) const {
  std::lock_guard lock(mutex_);
  auto it = jobs_.find(id);
  if (it == jobs_.end() || it->second.owner != owner) {
    return absl::NotFoundError(
        absl::StrCat("no job with id '", id, "' (unknown, or forgotten after its result expired)"));
  }
  return it->second.job;
}

std::vector<std::shared_ptr<Job>> JobRegistry::List(absl::string_view owner) const {
  std::lock_guard lock(mutex_);
  std::vector<std::shared_ptr<Job>> jobs;
  for (auto it = submission_order_.rbegin(); it != submission_order_.rend(); ++it) {
    auto entry = jobs_.find((*it)->id());
    if (entry != jobs_.end() && entry->second.owner == owner) jobs.push_back(*it);
  }
  return jobs;
}

std::vector<std::shared_ptr<Job>> JobRegistry::ListAllOwners() const {
  std::lock_guard lock(mutex_);
  return {submission_order_.rbegin(), submission_order_.rend()};
}

std::int64_t JobRegistry::QueuedCount() const {
  std::lock_guard lock(mutex_);
  return QueuedCountLocked();
}

bool JobRegistry::accepting() const {
  std::lock_guard lock(mutex_);
  return accepting_;
}

std::shared_ptr<Job> JobRegistry::TakeNextQueued() {
  std::unique_lock lock(mutex_);
  while (true) {
    queue_changed_.wait(lock, [this] { return workers_stopped_ || !queue_.empty(); });
    if (workers_stopped_) return nullptr;
    std::shared_ptr<Job> job = std::move(queue_.front());
    queue_.pop_front();
    if (job->state() == v1::JOB_STATE_QUEUED) return job;
  }
}

void JobRegistry::StopAccepting(absl::string_view reason) {
  std::deque<std::shared_ptr<Job>> queued;
  {
    std::lock_guard lock(mutex_);
    accepting_ = false;
    queued.swap(queue_);
  }
  for (const auto& job : queued) job->Cancel(reason);
}

bool JobRegistry::WaitUntilNoneRunning(absl::Time deadline) const {
  while (true) {
    bool running = false;
    {
      std::lock_guard lock(mutex_);
      running = std::any_of(submission_order_.begin(), submission_order_.end(),
                            [](const auto& j) { return j->state() == v1::JOB_STATE_RUNNING; });
    }
    if (!running) return true;
    if (absl::Now() >= deadline) return false;
    absl::SleepFor(absl::Milliseconds(10));
  }
}

void JobRegistry::CancelAll(absl::string_view reason) {
  for (const auto& job : ListAllOwners()) job->Cancel(reason);
}

void JobRegistry::StopWorkers() {
  {
    std::lock_guard lock(mutex_);
    workers_stopped_ = true;
  }
  queue_changed_.notify_all();
}

void JobRegistry::SweepLoop() {
  const absl::Duration period =
      std::clamp(result_ttl_ / 4, absl::Milliseconds(10), absl::Seconds(5));
  std::unique_lock lock(mutex_);
  while (!sweeper_wake_.wait_for(lock, absl::ToChronoNanoseconds(period),
                                 [this] { return sweeper_stop_; })) {
    const absl::Time now = absl::Now();
    std::vector<std::string> forget;
    for (const auto& job : submission_order_) {
      if (job->ExpireIfOlderThan(now, result_ttl_)) forget.push_back(job->id());
    }
    for (const std::string& id : forget) jobs_.erase(id);
    std::erase_if(submission_order_,
                  [this](const auto& job) { return !jobs_.contains(job->id()); });
    if (!forget.empty()) {
      lock.unlock();
      ReleaseFreedHeapMemory();
      lock.lock();
    }
  }
}

}  // namespace getme::server
