#include "remote/smoother_client.h"

#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "getme_wire/mesh_assembler.h"
#include "getme_wire/mesh_chunker.h"
#include "getme_wire/mesh_fields.h"
#include "getme_wire/status.h"
#include "grpcpp/create_channel.h"
#include "grpcpp/security/credentials.h"
#include "remote/cancel_watcher.h"
#include "remote/retry.h"

namespace getme::remote {
namespace {

void ApplyDeadline(const Attempt& attempt, grpc::ClientContext& context) {
  if (attempt.deadline == absl::InfiniteFuture()) return;
  context.set_deadline(absl::ToChronoTime(attempt.deadline));
}

v1::SmoothRequest HeaderRequest(const v1::Mesh& mesh, const SmoothJobOptions& job) {
  v1::SmoothRequest request;
  v1::SmoothHeader& header = *request.mutable_header();
  *header.mutable_parameters() = job.parameters;
  *header.mutable_result_options() = job.result_options;
  *header.mutable_expected_size() = wire::SizeOf(mesh);
  return request;
}

// Writes the header and every chunk; stops early when the server has ended the call (its status
// then tells why, so the caller goes on to Finish). True when the whole upload was sent.
template <typename Writer, typename Request>
bool Upload(Writer& writer, Request header, const v1::Mesh& mesh, std::size_t chunk_bytes) {
  if (!writer.Write(header)) return false;
  wire::MeshChunker chunker(mesh, chunk_bytes);
  Request request;
  while (chunker.Next(*request.mutable_chunk())) {
    if (!writer.Write(request)) return false;
  }
  return writer.WritesDone();
}

// Reads a result stream's SmoothResult and mesh chunks (and progress events before them).
class ResultReader {
 public:
  explicit ResultReader(const ProgressHandler& on_progress) : on_progress_(on_progress) {}

  absl::Status Consume(const v1::SmoothResponse& response) {
    switch (response.kind_case()) {
      case v1::SmoothResponse::kProgress:
        if (have_result_) {
          return absl::InternalError("the server sent a progress event after the result");
        }
        if (on_progress_) on_progress_(response.progress());
        return absl::OkStatus();
      case v1::SmoothResponse::kResult:
        if (have_result_) return absl::InternalError("the server sent two results");
        have_result_ = true;
        result_.result = response.result();
        return absl::OkStatus();
      case v1::SmoothResponse::kChunk:
        if (!have_result_) {
          return absl::InternalError("the server sent mesh chunks before the result");
        }
        return assembler_.Add(response.chunk());
      case v1::SmoothResponse::KIND_NOT_SET:
        break;
    }
    return absl::InternalError("the server sent an empty SmoothResponse");
  }

  absl::StatusOr<RemoteSmoothResult> Take() && {
    if (!have_result_) {
      return absl::InternalError("the server ended the stream without a result");
    }
    if (absl::Status status = assembler_.CheckComplete(result_.result.nodes()); !status.ok()) {
      return status;
    }
    result_.mesh = std::move(assembler_.mesh());
    return std::move(result_);
  }

 private:
  const ProgressHandler& on_progress_;
  bool have_result_ = false;
  RemoteSmoothResult result_;
  wire::MeshAssembler assembler_;
};

// Drains a SmoothResponse stream into a result. A protocol violation cancels the call. Once a
// message arrived the attempt is not retried.
template <typename Stream>
absl::StatusOr<RemoteSmoothResult> ReadResult(Stream& stream, grpc::ClientContext& context,
                                              const ProgressHandler& on_progress,
                                              Attempt& attempt) {
  ResultReader reader(on_progress);
  v1::SmoothResponse response;
  absl::Status protocol = absl::OkStatus();
  while (stream.Read(&response)) {
    attempt.retry_safe = false;
    protocol = reader.Consume(response);
    if (!protocol.ok()) {
      context.TryCancel();
      while (stream.Read(&response)) {
      }
      break;
    }
  }
  const absl::Status status = wire::FromGrpcStatus(stream.Finish());
  if (!protocol.ok()) return protocol;
  if (!status.ok()) return status;
  return std::move(reader).Take();
}

}  // namespace

SmootherClient::SmootherClient(std::shared_ptr<grpc::ChannelInterface> channel)
    : stub_(v1::Smoother::NewStub(std::move(channel))) {}

std::shared_ptr<grpc::Channel> SmootherClient::CreateChannel(const std::string& target) {
  return CreateSecureChannel(target, {});
}

std::shared_ptr<grpc::Channel> SmootherClient::CreateChannel(const std::string& target,
                                                             const ChannelSecurity& security) {
  return CreateSecureChannel(target, security);
}

absl::StatusOr<RemoteSmoothResult> SmootherClient::Smooth(const v1::Mesh& mesh,
                                                          const SmoothJobOptions& job,
                                                          const ProgressHandler& on_progress,
                                                          const CallOptions& call) {
  return WithRetry(call, [&](Attempt& attempt) -> absl::StatusOr<RemoteSmoothResult> {
    grpc::ClientContext context;
    ApplyDeadline(attempt, context);
    CancelWatcher watcher(context, call.cancel);
    std::unique_ptr<grpc::ClientReaderWriter<v1::SmoothRequest, v1::SmoothResponse>> stream =
        stub_->Smooth(&context);
    Upload(*stream, HeaderRequest(mesh, job), mesh, call.chunk_bytes);
    absl::StatusOr<RemoteSmoothResult> result = ReadResult(*stream, context, on_progress, attempt);
    if (!result.ok() && watcher.fired()) {
      return absl::CancelledError(
          absl::StrCat("cancelled by the client (", result.status().message(), ")"));
    }
    return result;
  });
}

absl::StatusOr<v1::Job> SmootherClient::SubmitJob(const v1::Mesh& mesh, const SmoothJobOptions& job,
                                                  const CallOptions& call) {
  return WithRetry(call, [&](Attempt& attempt) -> absl::StatusOr<v1::Job> {
    grpc::ClientContext context;
    ApplyDeadline(attempt, context);
    CancelWatcher watcher(context, call.cancel);
    v1::Job submitted;
    std::unique_ptr<grpc::ClientWriter<v1::SmoothRequest>> writer =
        stub_->SubmitJob(&context, &submitted);
    // Sent whole, the upload may have become a queued job even if the reply is lost.
    attempt.retry_safe = !Upload(*writer, HeaderRequest(mesh, job), mesh, call.chunk_bytes);
    if (absl::Status status = wire::FromGrpcStatus(writer->Finish()); !status.ok()) return status;
    return submitted;
  });
}

absl::Status SmootherClient::WatchJob(const std::string& job_id, const ProgressHandler& on_progress,
                                      const CallOptions& call) {
  return WithRetry(call, [&](Attempt& attempt) -> absl::Status {
    grpc::ClientContext context;
    ApplyDeadline(attempt, context);
    CancelWatcher watcher(context, call.cancel);
    v1::WatchJobRequest request;
    request.set_job_id(job_id);
    std::unique_ptr<grpc::ClientReader<v1::ProgressEvent>> reader =
        stub_->WatchJob(&context, request);
    v1::ProgressEvent event;
    while (reader->Read(&event)) {
      attempt.retry_safe = false;  // a retry would repeat events
      if (on_progress) on_progress(event);
    }
    absl::Status status = wire::FromGrpcStatus(reader->Finish());
    if (!status.ok() && watcher.fired()) {
      return absl::CancelledError(absl::StrCat("watching job ", job_id, " stopped by the client"));
    }
    return status;
  });
}

absl::StatusOr<v1::Job> SmootherClient::GetJob(const std::string& job_id, const CallOptions& call) {
  return WithRetry(call, [&](Attempt& attempt) -> absl::StatusOr<v1::Job> {
    grpc::ClientContext context;
    ApplyDeadline(attempt, context);
    v1::GetJobRequest request;
    request.set_job_id(job_id);
    v1::Job job;
    if (absl::Status status = wire::FromGrpcStatus(stub_->GetJob(&context, request, &job));
        !status.ok()) {
      return status;
    }
    return job;
  });
}

absl::StatusOr<v1::Job> SmootherClient::CancelJob(const std::string& job_id,
                                                  const CallOptions& call) {
  // Cancelling twice is the same as once.
  return WithRetry(call, [&](Attempt& attempt) -> absl::StatusOr<v1::Job> {
    grpc::ClientContext context;
    ApplyDeadline(attempt, context);
    v1::CancelJobRequest request;
    request.set_job_id(job_id);
    v1::Job job;
    if (absl::Status status = wire::FromGrpcStatus(stub_->CancelJob(&context, request, &job));
        !status.ok()) {
      return status;
    }
    return job;
  });
}

absl::StatusOr<std::vector<v1::Job>> SmootherClient::ListJobs(const CallOptions& call) {
  return WithRetry(call, [&](Attempt& attempt) -> absl::StatusOr<std::vector<v1::Job>> {
    grpc::ClientContext context;
    ApplyDeadline(attempt, context);
    v1::ListJobsResponse response;
    if (absl::Status status =
            wire::FromGrpcStatus(stub_->ListJobs(&context, v1::ListJobsRequest(), &response));
        !status.ok()) {
      return status;
    }
    return std::vector<v1::Job>(response.jobs().begin(), response.jobs().end());
  });
}

absl::StatusOr<RemoteSmoothResult> SmootherClient::GetResult(const std::string& job_id,
                                                             const CallOptions& call) {
  return WithRetry(call, [&](Attempt& attempt) -> absl::StatusOr<RemoteSmoothResult> {
    grpc::ClientContext context;
    ApplyDeadline(attempt, context);
    CancelWatcher watcher(context, call.cancel);
    v1::GetResultRequest request;
    request.set_job_id(job_id);
    std::unique_ptr<grpc::ClientReader<v1::SmoothResponse>> reader =
        stub_->GetResult(&context, request);
    return ReadResult(*reader, context, ProgressHandler(), attempt);
  });
}

absl::StatusOr<v1::QualityReport> SmootherClient::EvaluateQuality(const v1::Mesh& mesh,
                                                                  std::uint32_t histogram_bins,
                                                                  const CallOptions& call) {
  // The server keeps nothing from an evaluation.
  return WithRetry(call, [&](Attempt& attempt) -> absl::StatusOr<v1::QualityReport> {
    grpc::ClientContext context;
    ApplyDeadline(attempt, context);
    CancelWatcher watcher(context, call.cancel);
    v1::QualityReport report;
    std::unique_ptr<grpc::ClientWriter<v1::EvaluateQualityRequest>> writer =
        stub_->EvaluateQuality(&context, &report);
    v1::EvaluateQualityRequest header;
    header.mutable_header()->set_histogram_bins(histogram_bins);
    *header.mutable_header()->mutable_expected_size() = wire::SizeOf(mesh);
    Upload(*writer, std::move(header), mesh, call.chunk_bytes);
    if (absl::Status status = wire::FromGrpcStatus(writer->Finish()); !status.ok()) return status;
    return report;
  });
}

}  // namespace getme::remote
