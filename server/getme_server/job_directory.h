#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "getme/smoothing/smoothing_params.h"
#include "getme/v1/smoother.pb.h"
#include "getme_server/job_handle.h"
#include "getme_server/result_hold.h"
#include "getme_wire/mesh_upload.h"

namespace getme::server {

// An upload as it came in, for a job store that hands the job to another replica, which builds
// the mesh again from it (wire::MeshUpload, the same checks): the serialized v1::MeshChunk
// messages of a gRPC upload, or the one serialized v1::Mesh of an HTTP POST /v1/jobs.
struct ReceivedUpload {
  std::vector<std::string> chunks;
  std::string whole_mesh;
};

// A checked request with its mesh, built and validated, before it has an id.
struct JobSubmission {
  v1::SmoothHeader header;
  SmoothingParams params;
  wire::UploadedMesh mesh;
  std::int64_t upload_bytes = 0;  // encoded size, counted against --max_queued_bytes
  ReceivedUpload received;        // filled only when the directory keeps_uploads()
  // The call that submits the job waits on it and fetches the result itself (Smooth): see
  // SubmittedJob::result_hold.
  bool submitter_fetches_result = false;
};

// A queued job and a reader of its events from the first one (Smooth forwards them).
struct SubmittedJob {
  std::shared_ptr<JobHandle> job;
  std::shared_ptr<EventSource> events;
  // For a submitter_fetches_result submission to this process's registry: the result does not
  // expire while this is alive. Empty otherwise (a shared store counts the time to live in the
  // store).
  ResultHold result_hold;
};

// Where the front ends queue and find jobs: this process's JobRegistry (the default), or a store
// shared by every replica (--job_store, issue 18). Callers see only their own jobs: another owner's
// job id is answered exactly like an unknown one, so ids do not leak.
class JobDirectory {
 public:
  virtual ~JobDirectory() = default;

  virtual bool accepting() const = 0;  // false once this replica drains
  // Whether Submit needs JobSubmission::received (a shared store does; the registry does not).
  virtual bool keeps_uploads() const = 0;
  virtual std::int64_t QueuedCount() const = 0;  // jobs waiting for a worker
  virtual std::int64_t HeldBytes() const = 0;    // upload bytes of the QUEUED and RUNNING jobs
  // Queues the job: RESOURCE_EXHAUSTED when the queue (jobs or bytes) is full, UNAVAILABLE once
  // this replica stopped accepting.
  virtual absl::StatusOr<SubmittedJob> Submit(JobSubmission submission, std::string owner) = 0;
  // NOT_FOUND for unknown ids, forgotten ones, and another owner's, with the same message.
  virtual absl::StatusOr<std::shared_ptr<JobHandle>> FindJob(const std::string& id,
                                                             absl::string_view owner) const = 0;
  virtual std::vector<v1::Job> DescribeJobs(absl::string_view owner) const = 0;  // newest first
  // Replicas sharing the directory that are alive now; nullopt for a single process.
  virtual std::optional<std::int64_t> LiveReplicas() const { return std::nullopt; }
};

}  // namespace getme::server
