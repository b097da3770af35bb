#pragma once

#include "absl/status/status.h"
#include "grpcpp/support/status.h"

namespace getme::wire {

// The one place where absl::Status and gRPC statuses meet, both directions. Abseil's canonical
// codes are gRPC's codes, value for value, so code and message pass unchanged.
grpc::Status ToGrpcStatus(const absl::Status& status);
absl::Status FromGrpcStatus(const grpc::Status& status);

}  // namespace getme::wire
