#pragma once

#include "getme/v1/smoother.grpc.pb.h"
#include "getme_server/authenticator.h"
#include "getme_server/job_directory.h"
#include "getme_server/server_metrics.h"
#include "getme_server/server_options.h"
#include "getme_server/stream_limiter.h"

namespace getme::server {

// The getme.v1.Smoother handlers (synchronous API). They translate wire messages to engine
// types and back, and leave queueing, running and progress fan-out to the job directory (this
// process's registry, or the store shared by every replica) and its jobs.
// Every call first authenticates its caller (metadata `authorization: Bearer <token>` when
// authentication is on) and sees only that caller's jobs.
class SmootherService final : public v1::Smoother::Service {
 public:
  SmootherService(JobDirectory& jobs, const ServerOptions& options,
                  const Authenticator& authenticator)
      : jobs_(jobs),
        options_(options),
        authenticator_(authenticator),
        streams_(options.max_streams_per_client) {}

  grpc::Status Smooth(
      grpc::ServerContext* context,
      grpc::ServerReaderWriter<v1::SmoothResponse, v1::SmoothRequest>* stream) override;
  grpc::Status SubmitJob(grpc::ServerContext* context,
                         grpc::ServerReader<v1::SmoothRequest>* reader, v1::Job* job) override;
  grpc::Status WatchJob(grpc::ServerContext* context, const v1::WatchJobRequest* request,
                        grpc::ServerWriter<v1::ProgressEvent>* writer) override;
  grpc::Status GetJob(grpc::ServerContext* context, const v1::GetJobRequest* request,
                      v1::Job* job) override;
  grpc::Status CancelJob(grpc::ServerContext* context, const v1::CancelJobRequest* request,
                         v1::Job* job) override;
  grpc::Status ListJobs(grpc::ServerContext* context, const v1::ListJobsRequest* request,
                        v1::ListJobsResponse* response) override;
  grpc::Status GetResult(grpc::ServerContext* context, const v1::GetResultRequest* request,
                         grpc::ServerWriter<v1::SmoothResponse>* writer) override;
  grpc::Status EvaluateQuality(grpc::ServerContext* context,
                               grpc::ServerReader<v1::EvaluateQualityRequest>* reader,
                               v1::QualityReport* report) override;

 private:
  absl::Status RefuseWhileDraining() const;
  // Reads and checks a Smooth/SubmitJob upload (not yet submitted).
  template <typename Reader>
  absl::StatusOr<JobSubmission> ReadSubmission(grpc::ServerContext* context, Reader* reader);
  absl::StatusOr<std::string> CallerOf(const grpc::ServerContext& context) const;

  JobDirectory& jobs_;
  const ServerOptions options_;
  const Authenticator& authenticator_;
  ClientStreamLimiter streams_;
};

}  // namespace getme::server
