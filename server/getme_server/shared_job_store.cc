#include "getme_server/shared_job_store.h"

#include <algorithm>
#include <utility>

#include "absl/random/random.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/time/clock.h"
#include "getme_server/job_store_scripts.h"
#include "getme_server/stored_job.h"
#include "getme_wire/enums.h"
#include "spdlog/spdlog.h"

namespace getme::server {
namespace {

constexpr char kKeyPrefix[] = "getme:";
// List elements per RPUSH/LRANGE round trip when an upload or a result moves.
constexpr std::size_t kPartsPerCommand = 64;
// An upload written but never queued (its replica died between the two) expires after this.
constexpr absl::Duration kUnqueuedUploadLife = absl::Hours(1);
// Jobs listed per owner (newest first).
constexpr int kMaxListed = 500;
// A replica not heard from for this long no longer counts as live.
constexpr absl::Duration kReplicaSilence = absl::Seconds(5);
// Upload parts carry their kind in the first byte: a gRPC chunk, or an HTTP body's whole mesh.
constexpr char kChunkPart = 'c';
constexpr char kMeshPart = 'm';

std::string NewJobId() {
  thread_local absl::BitGen random;
  return absl::StrFormat("%012x", absl::Uniform<std::uint64_t>(random, 0, std::uint64_t{1} << 48));
}

std::int64_t NowMs() { return absl::ToUnixMillis(absl::Now()); }

std::string Ms(absl::Duration d) { return absl::StrCat(absl::ToInt64Milliseconds(d)); }

// Sends `values` to `key` in RPUSHes of kPartsPerCommand, in one pipeline.
absl::Status PushAll(redis::RedisClient& redis, const std::string& key,
                     const std::vector<std::string>& values, absl::Duration life) {
  std::vector<std::vector<std::string>> commands;
  commands.push_back({"DEL", key});
  for (std::size_t i = 0; i < values.size(); i += kPartsPerCommand) {
    std::vector<std::string> push = {"RPUSH", key};
    for (std::size_t j = i; j < std::min(values.size(), i + kPartsPerCommand); ++j) {
      push.push_back(values[j]);
    }
    commands.push_back(std::move(push));
  }
  commands.push_back({"PEXPIRE", key, Ms(life)});
  absl::StatusOr<std::vector<redis::RedisReply>> replies = redis.Pipeline(commands);
  return replies.status();
}

}  // namespace

SharedJobStore::SharedJobStore(std::unique_ptr<redis::RedisClient> redis,
                               const ServerOptions& options, std::string replica)
    : redis_(std::move(redis)),
      options_(options),
      replica_(std::move(replica)),
      prefix_(kKeyPrefix) {}

std::string SharedJobStore::JobKey(absl::string_view id) const {
  return absl::StrCat(prefix_, "job:", id);
}

std::int64_t SharedJobStore::QueuedCount() const {
  absl::StatusOr<redis::RedisReply> length = redis_->Command({"LLEN", prefix_ + "queue"});
  return length.ok() ? length->integer() : 0;
}

std::int64_t SharedJobStore::HeldBytes() const {
  absl::StatusOr<redis::RedisReply> held = redis_->Command({"GET", prefix_ + "held_bytes"});
  std::int64_t bytes = 0;
  if (held.ok() && !held->is_nil()) (void)absl::SimpleAtoi(held->str(), &bytes);
  return bytes;
}

absl::StatusOr<SubmittedJob> SharedJobStore::Submit(JobSubmission submission, std::string owner) {
  if (!accepting()) {
    return absl::UnavailableError("the server is shutting down and accepts no new jobs");
  }
  std::vector<std::string> parts;
  parts.reserve(submission.received.chunks.size() + 1);
  for (std::string& chunk : submission.received.chunks) {
    parts.push_back(std::string(1, kChunkPart) + chunk);
    std::string().swap(chunk);  // the store holds it now
  }
  if (!submission.received.whole_mesh.empty()) {
    parts.push_back(std::string(1, kMeshPart) + submission.received.whole_mesh);
  }
  const std::int64_t created_ms = NowMs();
  for (int tries = 0; tries < 3; ++tries) {
    const std::string id = NewJobId();
    v1::Job describe;
    describe.set_job_id(id);
    describe.set_state(v1::JOB_STATE_QUEUED);
    describe.set_method(wire::ToWireMethod(submission.params.method));
    describe.set_nodes(static_cast<std::uint64_t>(submission.mesh.mesh.node_count()));
    describe.set_elements(static_cast<std::uint64_t>(submission.mesh.mesh.element_count()));
    describe.set_created_unix_seconds(static_cast<double>(created_ms) / 1000.0);
    if (auto s = PushAll(*redis_, JobKey(id) + ":upload", parts, kUnqueuedUploadLife); !s.ok()) {
      return s;
    }
    absl::StatusOr<redis::RedisReply> queued = redis_->Eval(
        store_scripts::Submit(), {},
        {prefix_, id, owner, describe.SerializeAsString(), submission.header.SerializeAsString(),
         absl::StrCat(submission.upload_bytes), absl::StrCat(options_.max_queued_jobs),
         absl::StrCat(options_.max_queued_bytes), absl::StrCat(created_ms),
         submission.submitter_fetches_result ? "1" : "0"});
    if (!queued.ok()) return queued.status();
    const auto& reply = queued->elements();
    switch (reply.empty() ? -1 : reply[0].integer()) {
      case 0: {
        auto job = std::make_shared<StoredJob>(*this, id);
        std::shared_ptr<EventSource> events = job->WatchEvents();
        return SubmittedJob{std::move(job), std::move(events), ResultHold()};
      }
      case 1:
        return absl::ResourceExhaustedError(absl::StrCat(
            "the job queue is full: ", reply[1].integer(),
            " jobs are waiting for a worker in the shared job store (--max_queued_jobs); retry "
            "later"));
      case 2:
        return absl::ResourceExhaustedError(
            absl::StrCat("queued and running jobs hold ", reply[1].integer(),
                         " bytes of meshes in the shared job store; this job's ",
                         submission.upload_bytes, " bytes would pass the limit of ",
                         options_.max_queued_bytes, " bytes (--max_queued_bytes); retry later"));
      case 3:
        continue;  // the random id was taken: draw another
      default:
        return absl::InternalError("the job store's submit script answered unexpectedly");
    }
  }
  return absl::InternalError("no free job id after three draws");
}

absl::StatusOr<std::shared_ptr<JobHandle>> SharedJobStore::FindJob(const std::string& id,
                                                                   absl::string_view owner) const {
  absl::StatusOr<redis::RedisReply> stored = redis_->Command({"HGET", JobKey(id), "owner"});
  if (!stored.ok()) return stored.status();
  if (stored->is_nil() || stored->str() != owner) {
    return absl::NotFoundError(
        absl::StrCat("no job with id '", id, "' (unknown, or forgotten after its result expired)"));
  }
  return std::shared_ptr<JobHandle>(std::make_shared<StoredJob>(*this, id));
}

std::vector<v1::Job> SharedJobStore::DescribeJobs(absl::string_view owner) const {
  std::vector<v1::Job> jobs;
  const std::string owner_key = absl::StrCat(prefix_, "owner:", owner);
  absl::StatusOr<redis::RedisReply> ids =
      redis_->Command({"ZREVRANGE", owner_key, "0", absl::StrCat(kMaxListed - 1)});
  if (!ids.ok()) return jobs;
  std::vector<std::string> listed;
  listed.reserve(ids->elements().size());
  for (const redis::RedisReply& id : ids->elements()) listed.push_back(id.str());
  std::vector<std::optional<v1::Job>> described = StoredJob::DescribeMany(*this, listed);
  std::vector<std::vector<std::string>> forget;
  for (std::size_t i = 0; i < described.size(); ++i) {
    if (described[i]) {
      jobs.push_back(*std::move(described[i]));
      continue;
    }
    // Forgotten after its time to live: the indexes forget it too.
    forget.push_back({"ZREM", owner_key, listed[i]});
    forget.push_back({"ZREM", prefix_ + "jobs", listed[i]});
  }
  if (!forget.empty()) (void)redis_->Pipeline(forget);
  return jobs;
}

absl::StatusOr<std::optional<TakenJob>> SharedJobStore::Take(absl::Duration wait) {
  absl::StatusOr<std::optional<TakenJob>> taken = TakeQueued();
  if (!taken.ok() || taken->has_value()) return taken;
  // Submit and Requeue ring the doorbell: an idle replica wakes at once instead of polling.
  const std::string seconds = absl::StrFormat("%.3f", absl::ToDoubleSeconds(wait));
  absl::StatusOr<redis::RedisReply> rung =
      redis_->Blocking({"BLPOP", prefix_ + "doorbell", seconds}, wait);
  if (!rung.ok()) return rung.status();
  return TakeQueued();
}

absl::StatusOr<std::optional<TakenJob>> SharedJobStore::TakeQueued() {
  absl::StatusOr<redis::RedisReply> reply =
      redis_->Eval(store_scripts::Take(), {}, {prefix_, replica_, Ms(options_.job_lease)});
  if (!reply.ok()) return reply.status();
  if (reply->is_nil()) return std::optional<TakenJob>();
  const auto& f = reply->elements();
  TakenJob job;
  job.id = f[0].str();
  job.owner = f[1].str();
  job.header.ParseFromString(f[2].str());
  (void)absl::SimpleAtoi(f[3].str(), &job.upload_bytes);
  (void)absl::SimpleAtoi(f[4].str(), &job.attempt);
  (void)absl::SimpleAtoi(f[5].str(), &job.last_sequence);
  std::int64_t created_ms = 0;
  (void)absl::SimpleAtoi(f[6].str(), &created_ms);
  job.created_unix_seconds = static_cast<double>(created_ms) / 1000.0;
  job.cancel_reason = f[7].str();
  job.submitter_fetches_result = f[8].str() == "1";
  const std::string upload_key = JobKey(job.id) + ":upload";
  for (std::int64_t start = 0;; start += kPartsPerCommand) {
    absl::StatusOr<redis::RedisReply> parts =
        redis_->Command({"LRANGE", upload_key, absl::StrCat(start),
                         absl::StrCat(start + static_cast<std::int64_t>(kPartsPerCommand) - 1)});
    if (!parts.ok()) return parts.status();
    for (const redis::RedisReply& part : parts->elements()) {
      const std::string& bytes = part.str();
      if (bytes.empty()) continue;
      if (bytes[0] == kMeshPart) {
        job.upload.whole_mesh = bytes.substr(1);
      } else {
        job.upload.chunks.push_back(bytes.substr(1));
      }
    }
    if (parts->elements().size() < kPartsPerCommand) break;
  }
  return std::optional<TakenJob>(std::move(job));
}

absl::StatusOr<LeaseState> SharedJobStore::Renew(const std::string& id) {
  absl::StatusOr<redis::RedisReply> reply =
      redis_->Eval(store_scripts::Renew(), {}, {prefix_, id, replica_, Ms(options_.job_lease)});
  if (!reply.ok()) return reply.status();
  LeaseState lease;
  lease.held = !reply->is_nil();
  if (lease.held) lease.cancel_reason = reply->str();
  return lease;
}

absl::StatusOr<bool> SharedJobStore::Append(const std::string& id, const v1::Job& describe,
                                            std::uint64_t last_sequence,
                                            const std::vector<std::string>& events) {
  std::vector<std::string> args = {prefix_, id, replica_, describe.SerializeAsString(),
                                   absl::StrCat(last_sequence)};
  args.insert(args.end(), events.begin(), events.end());
  absl::StatusOr<redis::RedisReply> reply = redis_->Eval(store_scripts::Append(), {}, args);
  if (!reply.ok()) return reply.status();
  return reply->integer() == 1;
}

absl::StatusOr<bool> SharedJobStore::Finish(const TakenJob& taken, const v1::Job& describe,
                                            const std::optional<v1::SmoothResult>& summary,
                                            const std::vector<std::string>& result_messages,
                                            const v1::ProgressEvent& final_event) {
  const std::string& id = taken.id;
  // A Smooth call fetches the result the moment it reads the final event, but a loaded replica
  // may read it later than a short --result_ttl after the end; the store cannot see that call,
  // so such a result lives at least one lease, the time a live replica is trusted to answer in.
  const absl::Duration result_life = taken.submitter_fetches_result
                                         ? std::max(options_.result_ttl, options_.job_lease)
                                         : options_.result_ttl;
  std::string result_key;
  if (!result_messages.empty()) {
    // A key per attempt: a replica that lost the job but still runs can never mix its messages
    // into the result of the attempt that replaced it.
    result_key = absl::StrCat(JobKey(id), ":result:", taken.attempt);
    if (auto s = PushAll(*redis_, result_key, result_messages, result_life); !s.ok()) {
      // Part of it may be there: freed at once, so the job can still be ended as failed.
      (void)redis_->Command({"DEL", result_key});
      return s;
    }
  }
  absl::StatusOr<redis::RedisReply> reply = redis_->Eval(
      store_scripts::Finish(), {},
      {prefix_, id, replica_, absl::StrCat(static_cast<int>(describe.state())),
       describe.SerializeAsString(), summary.has_value() ? summary->SerializeAsString() : "",
       result_key, final_event.SerializeAsString(), Ms(result_life),
       absl::StrCat(final_event.sequence())});
  if (!reply.ok()) return reply.status();
  if (reply->integer() != 1 && !result_key.empty()) (void)redis_->Command({"DEL", result_key});
  return reply->integer() == 1;
}

absl::StatusOr<int> SharedJobStore::RequeueExpired() {
  absl::StatusOr<redis::RedisReply> claimed =
      redis_->Eval(store_scripts::ClaimExpired(), {}, {prefix_, "16"});
  if (!claimed.ok()) return claimed.status();
  int requeued = 0;
  for (const redis::RedisReply& entry : claimed->elements()) {
    const std::string& id = entry.elements()[0].str();
    v1::ProgressEvent restarted;
    restarted.set_job_id(id);
    restarted.set_sequence(static_cast<std::uint64_t>(entry.elements()[1].integer()));
    restarted.set_attempt(static_cast<std::uint32_t>(entry.elements()[2].integer()));
    restarted.set_restarted(true);
    // The event goes first, so every event of the new attempt comes after it.
    absl::StatusOr<redis::RedisReply> added =
        redis_->Command({"XADD", JobKey(id) + ":events", "*", "e", restarted.SerializeAsString()});
    if (!added.ok()) return added.status();
    absl::StatusOr<redis::RedisReply> back =
        redis_->Eval(store_scripts::Requeue(), {}, {prefix_, id});
    if (!back.ok()) return back.status();
    if (back->integer() == 1) {
      ++requeued;
      spdlog::warn(
          "job={} phase=restart attempt={}: the replica running it stopped renewing its lease; "
          "queued again",
          id, restarted.attempt());
    }
  }
  return requeued;
}

absl::Status SharedJobStore::ReleaseLease(const std::string& id) {
  return redis_->Command({"ZADD", prefix_ + "running", "XX", "0", id}).status();
}

absl::Status SharedJobStore::Heartbeat() {
  const std::int64_t now = NowMs();
  absl::StatusOr<std::vector<redis::RedisReply>> replies = redis_->Pipeline(
      {{"ZADD", prefix_ + "replicas", absl::StrCat(now), replica_},
       {"ZREMRANGEBYSCORE", prefix_ + "replicas", "-inf", absl::StrCat(now - 60'000)}});
  return replies.status();
}

std::optional<std::int64_t> SharedJobStore::LiveReplicas() const {
  absl::StatusOr<redis::RedisReply> count =
      redis_->Command({"ZCOUNT", prefix_ + "replicas",
                       absl::StrCat(NowMs() - absl::ToInt64Milliseconds(kReplicaSilence)), "+inf"});
  if (!count.ok()) return std::nullopt;
  return count->integer();
}

}  // namespace getme::server
