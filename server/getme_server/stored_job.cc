#include "getme_server/stored_job.h"

#include <string>
#include <utility>

#include "absl/random/random.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/time/clock.h"
#include "getme_server/job_store_scripts.h"
#include "getme_server/shared_job_store.h"
#include "getme_wire/status.h"
#include "spdlog/spdlog.h"

namespace getme::server {
namespace {

// Messages fetched per LRANGE while a result streams: about 32 MB at the ~1 MB chunk size.
constexpr int kResultBatch = 32;
// A watcher whose stream stays silent checks this often whether the job record still exists (a
// job forgotten after its time to live ends the watch instead of blocking forever).
constexpr absl::Duration kExistenceCheck = absl::Seconds(1);

const char* StateName(v1::JobState state) {
  return v1::JobState_Name(state).c_str() + sizeof("JOB_STATE_") - 1;
}

// The store's state field: v1::JobState's number, or "r" for a lost job being requeued, which
// callers see as QUEUED (it is about to be).
v1::JobState ParseState(const redis::RedisReply& reply) {
  if (reply.str() == "r") return v1::JOB_STATE_QUEUED;
  int state = 0;
  if (!absl::SimpleAtoi(reply.str(), &state) || !v1::JobState_IsValid(state)) {
    return v1::JOB_STATE_UNSPECIFIED;
  }
  return static_cast<v1::JobState>(state);
}

bool IsFinal(v1::JobState state) {
  return state == v1::JOB_STATE_SUCCEEDED || state == v1::JOB_STATE_FAILED ||
         state == v1::JOB_STATE_CANCELLED;
}

// A job record as the front ends show it: the last description written (by the replica that
// queued or runs it), with the state the store holds now.
struct JobRecord {
  bool exists = false;
  std::string stored_state;  // as the store has it ("r" included)
  v1::JobState state = v1::JOB_STATE_UNSPECIFIED;
  v1::Job describe;
  std::string result_key;
  std::string seq;
};

std::vector<std::string> ReadRecordCommand(const std::string& key) {
  return {"HMGET", key, "state", "describe", "result_key", "seq"};
}

JobRecord RecordFromReply(const redis::RedisReply& fields) {
  JobRecord record;
  const auto& f = fields.elements();
  if (f.size() != 4 || f[0].is_nil()) return record;
  record.exists = true;
  record.stored_state = f[0].str();
  record.state = ParseState(f[0]);
  record.describe.ParseFromString(f[1].str());
  record.describe.set_state(record.state);
  record.result_key = f[2].is_nil() ? "" : f[2].str();
  record.seq = f[3].is_nil() ? "0" : f[3].str();
  return record;
}

JobRecord ReadRecord(const SharedJobStore& store, const std::string& key) {
  absl::StatusOr<redis::RedisReply> fields = store.redis().Command(ReadRecordCommand(key));
  if (!fields.ok()) {
    spdlog::warn("job store: reading {} failed: {}", key, fields.status().ToString());
    return JobRecord();
  }
  return RecordFromReply(*fields);
}

// The description a front end shows: the record's, with its id and whether a result waits.
v1::Job DescriptionOf(JobRecord record, const std::string& id, bool result_exists) {
  v1::Job job = std::move(record.describe);
  job.set_job_id(id);
  job.set_result_available(result_exists);
  return job;
}

bool ResultMayWait(const JobRecord& record) {
  return record.state == v1::JOB_STATE_SUCCEEDED && !record.result_key.empty();
}

std::string RandomSuffix() {
  thread_local absl::BitGen random;
  return absl::StrFormat("%016x", absl::Uniform<std::uint64_t>(random));
}

}  // namespace

StoredJob::StoredJob(const SharedJobStore& store, std::string id)
    : store_(store), id_(std::move(id)), key_(store.JobKey(id_)) {}

v1::Job StoredJob::Describe() const {
  JobRecord record = ReadRecord(store_, key_);
  bool available = false;
  if (ResultMayWait(record)) {
    absl::StatusOr<redis::RedisReply> exists =
        store_.redis().Command({"EXISTS", record.result_key});
    available = exists.ok() && exists->integer() == 1;
  }
  return DescriptionOf(std::move(record), id_, available);
}

std::vector<std::optional<v1::Job>> StoredJob::DescribeMany(const SharedJobStore& store,
                                                            const std::vector<std::string>& ids) {
  std::vector<std::vector<std::string>> reads;
  reads.reserve(ids.size());
  for (const std::string& id : ids) reads.push_back(ReadRecordCommand(store.JobKey(id)));
  absl::StatusOr<std::vector<redis::RedisReply>> fields = store.redis().Pipeline(reads);
  if (!fields.ok()) {
    spdlog::warn("job store: reading {} job records failed: {}", ids.size(),
                 fields.status().ToString());
    return {};
  }
  std::vector<JobRecord> records;
  records.reserve(ids.size());
  std::vector<std::vector<std::string>> result_checks;
  for (const redis::RedisReply& reply : *fields) {
    records.push_back(RecordFromReply(reply));
    if (ResultMayWait(records.back()))
      result_checks.push_back({"EXISTS", records.back().result_key});
  }
  std::vector<redis::RedisReply> result_exists;
  if (!result_checks.empty()) {
    absl::StatusOr<std::vector<redis::RedisReply>> checked = store.redis().Pipeline(result_checks);
    if (!checked.ok()) {
      spdlog::warn("job store: checking {} results failed: {}", result_checks.size(),
                   checked.status().ToString());
      return {};
    }
    result_exists = *std::move(checked);
  }
  std::vector<std::optional<v1::Job>> jobs;
  jobs.reserve(ids.size());
  std::size_t next_check = 0;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (!records[i].exists) {
      jobs.emplace_back();
      continue;
    }
    const bool available = ResultMayWait(records[i]) && result_exists[next_check++].integer() == 1;
    jobs.emplace_back(DescriptionOf(std::move(records[i]), ids[i], available));
  }
  return jobs;
}

std::shared_ptr<EventSource> StoredJob::WatchEvents() {
  return std::make_shared<StoredEvents>(store_, id_);
}

void StoredJob::Cancel(absl::string_view reason) {
  // A queued job is cancelled here, with its final event, unless a worker takes it meanwhile (the
  // script then finds it RUNNING and this looks again); a running one is asked to stop.
  for (int attempt = 0; attempt < 8; ++attempt) {
    const JobRecord record = ReadRecord(store_, key_);
    if (!record.exists || IsFinal(record.state)) return;
    if (record.stored_state != "1") {  // running, or being requeued
      absl::StatusOr<redis::RedisReply> asked = store_.redis().Eval(
          store_scripts::RequestCancel(), {}, {store_.prefix(), id_, std::string(reason)});
      if (!asked.ok()) {
        spdlog::warn("job={} cancel request to the job store failed: {}", id_,
                     asked.status().ToString());
        return;
      }
      if (asked->integer() == 1) {
        spdlog::info("job={} cancel requested: {}", id_, std::string(reason));
        return;
      }
      continue;  // it changed state meanwhile
    }
    std::uint64_t seq = 0;
    (void)absl::SimpleAtoi(record.seq, &seq);
    v1::Job describe = record.describe;
    describe.set_state(v1::JOB_STATE_CANCELLED);
    describe.set_finished_unix_seconds(absl::ToDoubleSeconds(absl::Now() - absl::UnixEpoch()));
    wire::ToWireJobError(absl::CancelledError(absl::StrCat("job ", id_, " cancelled: ", reason)),
                         describe);
    v1::ProgressEvent final_event;
    final_event.set_job_id(id_);
    final_event.set_sequence(seq + 1);
    final_event.set_final(true);
    absl::StatusOr<redis::RedisReply> cancelled =
        store_.redis().Eval(store_scripts::CancelQueued(), {},
                            {store_.prefix(), id_, record.seq, describe.SerializeAsString(),
                             final_event.SerializeAsString(),
                             absl::StrCat(absl::ToInt64Milliseconds(store_.result_ttl()))});
    if (!cancelled.ok()) {
      spdlog::warn("job={} cancel in the job store failed: {}", id_, cancelled.status().ToString());
      return;
    }
    if (cancelled->integer() == 1) {
      spdlog::info("job={} phase=done outcome=CANCELLED reason=\"{}\" (while queued)", id_,
                   std::string(reason));
      return;
    }
  }
}

absl::StatusOr<std::unique_ptr<ResultStream>> StoredJob::TakeResultStream() {
  const JobRecord record = ReadRecord(store_, key_);
  if (!record.exists) {
    return absl::NotFoundError(absl::StrCat("no job with id '", id_,
                                            "' (unknown, or forgotten after its result expired)"));
  }
  switch (record.state) {
    case v1::JOB_STATE_SUCCEEDED:
      break;
    case v1::JOB_STATE_FAILED:
    case v1::JOB_STATE_CANCELLED:
      return wire::FromWireJobError(record.describe);
    default:
      return absl::FailedPreconditionError(
          absl::StrCat("job ", id_, " is ", StateName(record.state), ": it has no result yet"));
  }
  const std::string taken_key = absl::StrCat(key_, ":taken:", RandomSuffix());
  absl::StatusOr<redis::RedisReply> taken =
      store_.redis().Eval(store_scripts::TakeResult(), {}, {store_.prefix(), id_, taken_key});
  if (!taken.ok()) return taken.status();
  if (taken->integer() != 1) {
    return absl::NotFoundError(absl::StrCat(
        "the result of job ", id_, " is gone: it was already fetched or its time to live passed"));
  }
  return std::make_unique<StoredResult>(store_, taken_key, record.result_key);
}

std::optional<v1::SmoothResult> StoredJob::Summary() const {
  absl::StatusOr<redis::RedisReply> summary = store_.redis().Command({"HGET", key_, "summary"});
  if (!summary.ok() || summary->is_nil() || summary->str().empty()) return std::nullopt;
  v1::SmoothResult result;
  if (!result.ParseFromString(summary->str())) return std::nullopt;
  return result;
}

std::vector<v1::ProgressEvent> StoredJob::Trace() const {
  std::vector<v1::ProgressEvent> events;
  absl::StatusOr<redis::RedisReply> entries =
      store_.redis().Command({"XRANGE", absl::StrCat(key_, ":events"), "-", "+"});
  if (!entries.ok()) return events;
  for (const redis::RedisReply& entry : entries->elements()) {
    if (entry.elements().size() != 2 || entry.elements()[1].elements().size() != 2) continue;
    v1::ProgressEvent event;
    if (event.ParseFromString(entry.elements()[1].elements()[1].str())) {
      events.push_back(std::move(event));
    }
  }
  return events;
}

absl::Status StoredJob::outcome() const {
  return wire::FromWireJobError(ReadRecord(store_, key_).describe);
}

bool StoredJob::final() const { return IsFinal(ReadRecord(store_, key_).state); }

StoredEvents::StoredEvents(const SharedJobStore& store, std::string id)
    : store_(store), key_(store.JobKey(id)), events_key_(absl::StrCat(key_, ":events")) {}

EventSource::NextResult StoredEvents::Next(absl::Duration timeout, v1::ProgressEvent& event) {
  if (pending_.empty() && !ended_) {
    const std::int64_t block_ms = std::max<std::int64_t>(1, absl::ToInt64Milliseconds(timeout));
    absl::StatusOr<redis::RedisReply> reply =
        store_.redis().Blocking({"XREAD", "COUNT", "256", "BLOCK", absl::StrCat(block_ms),
                                 "STREAMS", events_key_, last_id_},
                                absl::Milliseconds(block_ms));
    if (!reply.ok()) {
      spdlog::warn("job store: reading {} failed: {}", events_key_, reply.status().ToString());
      absl::SleepFor(timeout);
      return NextResult::kTimeout;
    }
    if (reply->is_nil() || reply->elements().empty()) {
      if (absl::Now() - last_existence_check_ >= kExistenceCheck) {
        last_existence_check_ = absl::Now();
        absl::StatusOr<redis::RedisReply> exists = store_.redis().Command({"EXISTS", key_});
        if (exists.ok() && exists->integer() == 0) ended_ = true;
      }
      return ended_ ? NextResult::kEnded : NextResult::kTimeout;
    }
    // [[key, [[id, [field, value]], ...]]]
    for (const redis::RedisReply& entry : reply->elements()[0].elements()[1].elements()) {
      last_id_ = entry.elements()[0].str();
      const auto& fields = entry.elements()[1].elements();
      v1::ProgressEvent parsed;
      if (fields.size() == 2 && parsed.ParseFromString(fields[1].str())) {
        pending_.push_back(std::move(parsed));
      }
    }
  }
  if (pending_.empty()) return ended_ ? NextResult::kEnded : NextResult::kTimeout;
  event = std::move(pending_.front());
  pending_.pop_front();
  if (event.final()) {
    ended_ = true;
    pending_.clear();
  }
  return NextResult::kEvent;
}

StoredResult::StoredResult(const SharedJobStore& store, std::string taken_key,
                           std::string result_key)
    : store_(store), taken_key_(std::move(taken_key)), result_key_(std::move(result_key)) {}

bool StoredResult::Next(v1::SmoothResponse& message) {
  if (batch_.empty() && !exhausted_) {
    absl::StatusOr<redis::RedisReply> range =
        store_.redis().Command({"LRANGE", taken_key_, absl::StrCat(next_index_),
                                absl::StrCat(next_index_ + kResultBatch - 1)});
    if (!range.ok()) {
      spdlog::warn("job store: reading result {} failed: {}", taken_key_,
                   range.status().ToString());
      exhausted_ = true;
    } else {
      for (const redis::RedisReply& element : range->elements()) batch_.push_back(element.str());
      next_index_ += static_cast<std::int64_t>(range->elements().size());
      if (static_cast<int>(range->elements().size()) < kResultBatch) exhausted_ = true;
    }
  }
  if (batch_.empty()) {
    (void)store_.redis().Command({"DEL", taken_key_});  // fetched: handed out once
    return false;
  }
  const bool parsed = message.ParseFromString(batch_.front());
  batch_.pop_front();
  return parsed;
}

void StoredResult::GiveBack() {
  absl::StatusOr<redis::RedisReply> back =
      store_.redis().Command({"RENAMENX", taken_key_, result_key_});
  if (!back.ok()) {
    spdlog::warn("job store: giving back result {} failed: {}", result_key_,
                 back.status().ToString());
  }
}

}  // namespace getme::server
