#pragma once

#include <string>

#include "absl/status/status.h"
#include "grpcpp/support/status.h"

namespace getme::remote {

// The absl::Status of a finished call, with the server's code and message unchanged (both
// libraries use the canonical gRPC code numbering).
absl::Status FromGrpcStatus(const grpc::Status& status);

// "UNAVAILABLE: failed to connect to all addresses" — how the CLI names a remote failure.
std::string DescribeStatus(const absl::Status& status);

}  // namespace getme::remote
