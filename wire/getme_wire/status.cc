#include "getme_wire/status.h"

namespace getme::wire {

grpc::Status ToGrpcStatus(const absl::Status& status) {
  if (status.ok()) return grpc::Status::OK;
  return grpc::Status(static_cast<grpc::StatusCode>(status.code()), std::string(status.message()));
}

absl::Status FromGrpcStatus(const grpc::Status& status) {
  if (status.ok()) return absl::OkStatus();
  return absl::Status(static_cast<absl::StatusCode>(status.error_code()), status.error_message());
}

void ToWireJobError(const absl::Status& outcome, v1::Job& job) {
  job.set_error_code(static_cast<int>(outcome.code()));
  job.set_error_message(std::string(outcome.message()));
}

absl::Status FromWireJobError(const v1::Job& job) {
  if (job.error_code() == 0) return absl::OkStatus();
  return absl::Status(static_cast<absl::StatusCode>(job.error_code()), job.error_message());
}

}  // namespace getme::wire
