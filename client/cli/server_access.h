#pragma once

#include <memory>

#include "absl/status/statusor.h"
#include "cli/cli_options.h"
#include "grpcpp/channel.h"

namespace getme::cli {

// The channel to `--server` with the access options applied: the bearer token of --token-file
// (else of the GETME_TOKEN environment variable), TLS when --tls-ca or --tls-cert is given.
// INVALID_ARGUMENT / NOT_FOUND naming the option and file when one cannot be read or is empty.
absl::StatusOr<std::shared_ptr<grpc::Channel>> OpenServerChannel(const std::string& server,
                                                                 const ServerAccessOptions& access);

}  // namespace getme::cli
