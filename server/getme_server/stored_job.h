#pragma once

#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "getme_server/job_handle.h"

namespace getme::server {

class SharedJobStore;

// A job in the shared store, seen from any replica: every call reads or changes the store, so
// it answers the same whichever replica serves it. The store outlives its handles.
class StoredJob : public JobHandle {
 public:
  StoredJob(const SharedJobStore& store, std::string id);

  const std::string& id() const override { return id_; }
  v1::Job Describe() const override;
  // Describe() of many jobs in two round trips instead of two per job (the job list shows up to
  // hundreds). nullopt for an id whose record is gone (forgotten after its time to live); an
  // empty vector when the store cannot be read.
  static std::vector<std::optional<v1::Job>> DescribeMany(const SharedJobStore& store,
                                                          const std::vector<std::string>& ids);
  // Every event from the job's first, with the sequence numbers the running replica gave them.
  std::shared_ptr<EventSource> WatchEvents() override;
  void Cancel(absl::string_view reason) override;
  absl::StatusOr<std::unique_ptr<ResultStream>> TakeResultStream() override;
  std::optional<v1::SmoothResult> Summary() const override;
  std::vector<v1::ProgressEvent> Trace() const override;
  absl::Status outcome() const override;
  bool final() const override;

 private:
  const SharedJobStore& store_;
  const std::string id_;
  const std::string key_;
};

// Reads a job's event stream (XREAD BLOCK) from its first event.
class StoredEvents : public EventSource {
 public:
  StoredEvents(const SharedJobStore& store, std::string id);
  NextResult Next(absl::Duration timeout, v1::ProgressEvent& event) override;

 private:
  const SharedJobStore& store_;
  const std::string key_;
  const std::string events_key_;
  std::string last_id_ = "0-0";
  std::deque<v1::ProgressEvent> pending_;
  bool ended_ = false;
  absl::Time last_existence_check_ = absl::InfinitePast();
};

// A result the store holds as the messages GetResult sends, moved to a key of this download
// while it streams; deleted once sent, moved back if the download is cut short.
class StoredResult : public ResultStream {
 public:
  StoredResult(const SharedJobStore& store, std::string taken_key, std::string result_key);
  bool Next(v1::SmoothResponse& message) override;
  void GiveBack() override;

 private:
  const SharedJobStore& store_;
  const std::string taken_key_;
  const std::string result_key_;
  std::deque<std::string> batch_;
  std::int64_t next_index_ = 0;
  bool exhausted_ = false;
};

}  // namespace getme::server
