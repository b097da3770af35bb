#pragma once

#include "absl/status/status.h"
#include "grpcpp/support/status.h"

namespace getme::server {

// The one place where engine and server errors (absl::Status) become gRPC statuses. Abseil's
// canonical codes are gRPC's codes, value for value.
grpc::Status ToGrpcStatus(const absl::Status& status);

}  // namespace getme::server
