#pragma once

#include "absl/status/status.h"

namespace getme::cli {

// Exit statuses of the getme commands.
inline constexpr int kExitSuccess = 0;
inline constexpr int kExitFailure = 1;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitInterrupted = 130;  // 128 + SIGINT, as shells report it

// Reports a failure: "getme: <message>" on stderr and, in JSON mode, an
// {"event":"error","code":…,"message":…} line on stdout. Returns `exit_status`.
int ReportFailure(const absl::Status& status, bool json, int exit_status);

// The same for a failure reported by a getme-server, named with its status code:
// "getme: UNAVAILABLE: failed to connect to all addresses".
int ReportRemoteFailure(const absl::Status& status, bool json, int exit_status);

}  // namespace getme::cli
