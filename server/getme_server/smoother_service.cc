#include "getme_server/smoother_service.h"

#include <chrono>
#include <string>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "getme/mesh/mesh_quality.h"
#include "getme/parallel/thread_pool.h"
#include "getme_server/job_submission.h"
#include "getme_server/upload_meter.h"
#include "getme_wire/mesh_assembler.h"
#include "getme_wire/mesh_chunker.h"
#include "getme_wire/mesh_upload.h"
#include "getme_wire/reports.h"
#include "getme_wire/status.h"
#include "spdlog/spdlog.h"

namespace getme::server {
namespace {

using wire::ToGrpcStatus;

// How often a handler waiting for progress checks whether its client is still there: a cancelled
// call or a passed deadline then cancels the job, which stops within one engine iteration.
constexpr absl::Duration kClientPollInterval = absl::Milliseconds(50);

template <typename Header>
absl::Status CheckHeader(const Header& header, std::int64_t max_elements,
                         const UploadMeter& meter) {
  if (!header.has_expected_size()) return absl::OkStatus();
  if (auto s = wire::CheckDeclaredSize(header.expected_size(), max_elements); !s.ok()) return s;
  return meter.CheckDeclared(header.expected_size());
}

// Reads an upload stream: an optional header first, then mesh chunks, each handed to `upload` as
// it arrives (wire::MeshUpload builds the engine mesh; no copy of the wire mesh is kept). A
// missing header means default parameters.
// `received` (may be null) keeps each chunk as it came, for a shared job store.
template <typename Request, typename Header, typename Reader>
absl::Status ReadUpload(grpc::ServerContext* context, Reader* reader, std::int64_t max_elements,
                        UploadMeter meter, Header& header, wire::MeshUpload& upload,
                        ReceivedUpload* received = nullptr) {
  Request request;
  std::int64_t message = 0;
  bool have_header = false;
  while (reader->Read(&request)) {
    if (request.has_header()) {
      if (message > 0) {
        return absl::InvalidArgumentError(
            absl::StrCat("request message ", message,
                         " is a header: the header must be the first message, "
                         "and come only once"));
      }
      header = request.header();
      have_header = true;
      if (auto s = CheckHeader(header, max_elements, meter); !s.ok()) return s;
    } else if (request.has_chunk()) {
      if (auto s = upload.Add(request.chunk()); !s.ok()) return s;
      if (auto s = meter.AddChunk(request.chunk(), upload.assembler().nodes()); !s.ok()) return s;
      if (received != nullptr) received->chunks.push_back(request.chunk().SerializeAsString());
    } else {
      return absl::InvalidArgumentError(
          absl::StrCat("request message ", message, " carries neither a header nor a chunk"));
    }
    ++message;
  }
  if (context->IsCancelled()) return absl::CancelledError("the client cancelled the upload");
  if (have_header && header.has_expected_size()) {
    return upload.assembler().CheckExpectedSize(header.expected_size());
  }
  return absl::OkStatus();
}

enum class WatchEnd { kJobEnded, kClientGone, kDeadline };

// Why a call that can no longer be written to ended. gRPC's deadline timer may end it a little
// before the deadline reads as passed on the system clock (seen under load), so an end within
// the poll interval of the deadline counts as the deadline.
WatchEnd WhyCallEnded(const grpc::ServerContext* context) {
  const bool deadline = context->deadline() <= std::chrono::system_clock::now() +
                                                   absl::ToChronoMilliseconds(kClientPollInterval);
  return deadline ? WatchEnd::kDeadline : WatchEnd::kClientGone;
}

// Forwards progress events until the job's final event, or until the client goes away.
template <typename WriteEvent>
WatchEnd ForwardProgress(grpc::ServerContext* context, EventSource& events,
                         const WriteEvent& write) {
  v1::ProgressEvent event;
  while (true) {
    switch (events.Next(kClientPollInterval, event)) {
      case EventSource::NextResult::kEnded:
        return WatchEnd::kJobEnded;
      case EventSource::NextResult::kEvent:
        if (!write(event)) return WhyCallEnded(context);
        if (event.final()) return WatchEnd::kJobEnded;
        break;
      case EventSource::NextResult::kTimeout:
        if (context->IsCancelled()) return WhyCallEnded(context);
        break;
    }
  }
}

// A download cut short gives the result back to the job, so it can be fetched again with
// GetResult (until --result_ttl passes).
template <typename Writer>
grpc::Status StreamResult(ResultStream& result, Writer* writer) {
  v1::SmoothResponse message;
  bool first = true;
  while (result.Next(message)) {
    if (!writer->Write(message)) {
      result.GiveBack();
      return grpc::Status(grpc::StatusCode::CANCELLED,
                          first ? "the client went away before the result"
                                : "the client went away while the result was streamed");
    }
    first = false;
    message.Clear();
  }
  return grpc::Status::OK;
}

}  // namespace

absl::StatusOr<std::string> SmootherService::CallerOf(const grpc::ServerContext& context) const {
  const auto& metadata = context.client_metadata();
  std::optional<absl::string_view> authorization;
  if (auto it = metadata.find("authorization"); it != metadata.end()) {
    authorization = absl::string_view(it->second.data(), it->second.size());
  }
  return authenticator_.Authenticate(authorization);
}

absl::Status SmootherService::RefuseWhileDraining() const {
  // Before the upload: a draining server does not read a mesh it will not queue.
  if (jobs_.accepting()) return absl::OkStatus();
  return absl::UnavailableError("the server is shutting down and accepts no new jobs");
}

template <typename Reader>
absl::StatusOr<JobSubmission> SmootherService::ReadSubmission(grpc::ServerContext* context,
                                                              Reader* reader) {
  JobSubmission submission;
  wire::MeshUpload upload(options_.max_elements);
  if (auto s = ReadUpload<v1::SmoothRequest>(
          context, reader, options_.max_elements, UploadMeter(options_, &jobs_), submission.header,
          upload, jobs_.keeps_uploads() ? &submission.received : nullptr);
      !s.ok()) {
    return s;
  }
  absl::StatusOr<SmoothingParams> params = CheckJobRequest(submission.header, options_);
  if (!params.ok()) return params.status();
  submission.params = *params;
  submission.upload_bytes = upload.assembler().encoded_bytes();
  absl::StatusOr<wire::UploadedMesh> mesh = std::move(upload).Finish();
  if (!mesh.ok()) return mesh.status();
  submission.mesh = *std::move(mesh);
  return submission;
}

grpc::Status SmootherService::Smooth(
    grpc::ServerContext* context,
    grpc::ServerReaderWriter<v1::SmoothResponse, v1::SmoothRequest>* stream) {
  absl::StatusOr<std::string> owner = CallerOf(*context);
  if (!owner.ok()) return ToGrpcStatus(owner.status());
  if (auto s = RefuseWhileDraining(); !s.ok()) return ToGrpcStatus(s);
  absl::StatusOr<ClientStreamLimiter::Slot> slot = streams_.Acquire(context->peer());
  if (!slot.ok()) return ToGrpcStatus(slot.status());
  absl::StatusOr<JobSubmission> submission = ReadSubmission(context, stream);
  if (!submission.ok()) return ToGrpcStatus(submission.status());
  submission->submitter_fetches_result = true;  // held until this call returns
  // The directory hands back a reader of every event from the first one.
  absl::StatusOr<SubmittedJob> submitted = jobs_.Submit(*std::move(submission), *owner);
  if (!submitted.ok()) return ToGrpcStatus(submitted.status());
  const std::shared_ptr<JobHandle>* job = &submitted->job;
  spdlog::info("job={} queued by Smooth from {}{}{}", (*job)->id(), context->peer(),
               owner->empty() ? "" : " owner=", *owner);

  const WatchEnd end =
      ForwardProgress(context, *submitted->events, [stream](const v1::ProgressEvent& e) {
        v1::SmoothResponse response;
        *response.mutable_progress() = e;
        return stream->Write(response);
      });
  if (end == WatchEnd::kDeadline) {
    (*job)->Cancel("the Smooth call's deadline passed");
    return grpc::Status(grpc::StatusCode::DEADLINE_EXCEEDED,
                        absl::StrCat("deadline passed; job ", (*job)->id(), " cancelled"));
  }
  if (end == WatchEnd::kClientGone) {
    (*job)->Cancel("the client cancelled the Smooth call");
    return grpc::Status(grpc::StatusCode::CANCELLED,
                        absl::StrCat("call cancelled; job ", (*job)->id(), " cancelled"));
  }
  absl::StatusOr<std::unique_ptr<ResultStream>> result = (*job)->TakeResultStream();
  if (!result.ok()) return ToGrpcStatus(result.status());
  return StreamResult(**result, stream);
}

grpc::Status SmootherService::SubmitJob(grpc::ServerContext* context,
                                        grpc::ServerReader<v1::SmoothRequest>* reader,
                                        v1::Job* job_out) {
  absl::StatusOr<std::string> owner = CallerOf(*context);
  if (!owner.ok()) return ToGrpcStatus(owner.status());
  if (auto s = RefuseWhileDraining(); !s.ok()) return ToGrpcStatus(s);
  absl::StatusOr<ClientStreamLimiter::Slot> slot = streams_.Acquire(context->peer());
  if (!slot.ok()) return ToGrpcStatus(slot.status());
  absl::StatusOr<JobSubmission> submission = ReadSubmission(context, reader);
  if (!submission.ok()) return ToGrpcStatus(submission.status());
  absl::StatusOr<SubmittedJob> submitted = jobs_.Submit(*std::move(submission), *owner);
  if (!submitted.ok()) return ToGrpcStatus(submitted.status());
  spdlog::info("job={} queued by SubmitJob from {}{}{}", submitted->job->id(), context->peer(),
               owner->empty() ? "" : " owner=", *owner);
  *job_out = submitted->job->Describe();
  return grpc::Status::OK;
}

grpc::Status SmootherService::WatchJob(grpc::ServerContext* context,
                                       const v1::WatchJobRequest* request,
                                       grpc::ServerWriter<v1::ProgressEvent>* writer) {
  absl::StatusOr<std::string> owner = CallerOf(*context);
  if (!owner.ok()) return ToGrpcStatus(owner.status());
  absl::StatusOr<ClientStreamLimiter::Slot> slot = streams_.Acquire(context->peer());
  if (!slot.ok()) return ToGrpcStatus(slot.status());
  absl::StatusOr<std::shared_ptr<JobHandle>> job = jobs_.FindJob(request->job_id(), *owner);
  if (!job.ok()) return ToGrpcStatus(job.status());
  std::shared_ptr<EventSource> events = (*job)->WatchEvents();
  // A watcher leaving does not cancel the job: that is what CancelJob is for.
  switch (ForwardProgress(context, *events,
                          [writer](const v1::ProgressEvent& e) { return writer->Write(e); })) {
    case WatchEnd::kJobEnded:
      return grpc::Status::OK;
    case WatchEnd::kDeadline:
      return grpc::Status(grpc::StatusCode::DEADLINE_EXCEEDED, "deadline passed while watching");
    case WatchEnd::kClientGone:
      break;
  }
  return grpc::Status(grpc::StatusCode::CANCELLED, "the watcher went away");
}

grpc::Status SmootherService::GetJob(grpc::ServerContext* context, const v1::GetJobRequest* request,
                                     v1::Job* job_out) {
  absl::StatusOr<std::string> owner = CallerOf(*context);
  if (!owner.ok()) return ToGrpcStatus(owner.status());
  absl::StatusOr<std::shared_ptr<JobHandle>> job = jobs_.FindJob(request->job_id(), *owner);
  if (!job.ok()) return ToGrpcStatus(job.status());
  *job_out = (*job)->Describe();
  return grpc::Status::OK;
}

grpc::Status SmootherService::CancelJob(grpc::ServerContext* context,
                                        const v1::CancelJobRequest* request, v1::Job* job_out) {
  absl::StatusOr<std::string> owner = CallerOf(*context);
  if (!owner.ok()) return ToGrpcStatus(owner.status());
  absl::StatusOr<std::shared_ptr<JobHandle>> job = jobs_.FindJob(request->job_id(), *owner);
  if (!job.ok()) return ToGrpcStatus(job.status());
  (*job)->Cancel(absl::StrCat("CancelJob from ", context->peer()));
  *job_out = (*job)->Describe();
  return grpc::Status::OK;
}

grpc::Status SmootherService::ListJobs(grpc::ServerContext* context, const v1::ListJobsRequest*,
                                       v1::ListJobsResponse* response) {
  absl::StatusOr<std::string> owner = CallerOf(*context);
  if (!owner.ok()) return ToGrpcStatus(owner.status());
  for (v1::Job& job : jobs_.DescribeJobs(*owner)) *response->add_jobs() = std::move(job);
  return grpc::Status::OK;
}

grpc::Status SmootherService::GetResult(grpc::ServerContext* context,
                                        const v1::GetResultRequest* request,
                                        grpc::ServerWriter<v1::SmoothResponse>* writer) {
  absl::StatusOr<std::string> owner = CallerOf(*context);
  if (!owner.ok()) return ToGrpcStatus(owner.status());
  absl::StatusOr<ClientStreamLimiter::Slot> slot = streams_.Acquire(context->peer());
  if (!slot.ok()) return ToGrpcStatus(slot.status());
  absl::StatusOr<std::shared_ptr<JobHandle>> job = jobs_.FindJob(request->job_id(), *owner);
  if (!job.ok()) return ToGrpcStatus(job.status());
  absl::StatusOr<std::unique_ptr<ResultStream>> result = (*job)->TakeResultStream();
  if (!result.ok()) return ToGrpcStatus(result.status());
  spdlog::info("job={} result fetched", (*job)->id());
  return StreamResult(**result, writer);
}

grpc::Status SmootherService::EvaluateQuality(
    grpc::ServerContext* context, grpc::ServerReader<v1::EvaluateQualityRequest>* reader,
    v1::QualityReport* report) {
  absl::StatusOr<std::string> owner = CallerOf(*context);
  if (!owner.ok()) return ToGrpcStatus(owner.status());
  absl::StatusOr<ClientStreamLimiter::Slot> slot = streams_.Acquire(context->peer());
  if (!slot.ok()) return ToGrpcStatus(slot.status());
  v1::EvaluateQualityHeader header;
  wire::MeshUpload upload(options_.max_elements);
  if (auto s = ReadUpload<v1::EvaluateQualityRequest>(
          context, reader, options_.max_elements, UploadMeter(options_, nullptr), header, upload);
      !s.ok()) {
    return ToGrpcStatus(s);
  }
  if (auto s = CheckHistogramBins(header.histogram_bins(), "histogram_bins"); !s.ok()) {
    return ToGrpcStatus(s);
  }
  absl::StatusOr<wire::UploadedMesh> uploaded = std::move(upload).Finish();
  if (!uploaded.ok()) return ToGrpcStatus(uploaded.status());
  const Mesh* mesh = &uploaded->mesh;
  ThreadPool pool(options_.threads_per_job);
  QualityOptions quality_options;
  if (header.histogram_bins() > 0) {
    quality_options.histogram_bins = static_cast<int>(header.histogram_bins());
  }
  *report = wire::ToWireReport(EvaluateMeshQuality(*mesh, pool, quality_options), uploaded->ids);
  spdlog::info("quality evaluated: nodes={} elements={} q_min={} q_mean={}", mesh->node_count(),
               mesh->element_count(), report->q_min(), report->q_mean());
  return grpc::Status::OK;
}

}  // namespace getme::server
