#pragma once

#include "absl/status/status.h"
#include "getme/v1/smoother.pb.h"
#include "grpcpp/support/status.h"

namespace getme::wire {

// The one place where absl::Status and gRPC statuses meet, both directions. Abseil's canonical
// codes are gRPC's codes, value for value, so code and message pass unchanged.
grpc::Status ToGrpcStatus(const absl::Status& status);
absl::Status FromGrpcStatus(const grpc::Status& status);

// A job's outcome as getme.v1.Job carries it (error_code, error_message): set from a failed
// outcome, and read back (OK when error_code is 0).
void ToWireJobError(const absl::Status& outcome, v1::Job& job);
absl::Status FromWireJobError(const v1::Job& job);

}  // namespace getme::wire
