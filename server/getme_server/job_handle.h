#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "absl/time/time.h"
#include "getme/v1/smoother.pb.h"

namespace getme::server {

// A job's progress events in order, for one reader (a WatchJob call, an SSE stream).
class EventSource {
 public:
  enum class NextResult { kEvent, kTimeout, kEnded };
  virtual ~EventSource() = default;
  // Waits up to `timeout` for the next event. kEnded once the final event was delivered.
  virtual NextResult Next(absl::Duration timeout, v1::ProgressEvent& event) = 0;
};

// The messages of a succeeded job's result as GetResult sends them: the summary first, then the
// mesh chunks. Handed out once; a download that does not complete gives it back.
class ResultStream {
 public:
  virtual ~ResultStream() = default;
  // The next message; false after the last one.
  virtual bool Next(v1::SmoothResponse& message) = 0;
  // The download was cut short: the result can be fetched again (until the time to live passes).
  virtual void GiveBack() = 0;
};

// What the service's front ends (gRPC handlers, HTTP gateway) do with a job, whether it lives in
// this process (Job) or in a shared store every replica reads (StoredJob, issue 18).
class JobHandle {
 public:
  virtual ~JobHandle() = default;
  virtual const std::string& id() const = 0;
  virtual v1::Job Describe() const = 0;
  // A reader of the job's progress events (see each implementation for where it starts).
  virtual std::shared_ptr<EventSource> WatchEvents() = 0;
  // Queued: CANCELLED at once. Running: the engine stops within one iteration. Final: no-op.
  virtual void Cancel(absl::string_view reason) = 0;
  // FAILED/CANCELLED jobs give their outcome, unfinished ones FAILED_PRECONDITION, fetched or
  // expired results NOT_FOUND.
  virtual absl::StatusOr<std::unique_ptr<ResultStream>> TakeResultStream() = 0;
  // The summary of a SUCCEEDED job, kept after its result was fetched; nullopt otherwise.
  virtual std::optional<v1::SmoothResult> Summary() const = 0;
  // The job's events so far, thinned (every phase_done and the final event kept).
  virtual std::vector<v1::ProgressEvent> Trace() const = 0;
  // OK for SUCCEEDED (and while unfinished), else the status it failed or was cancelled with.
  virtual absl::Status outcome() const = 0;
  virtual bool final() const = 0;
};

}  // namespace getme::server
