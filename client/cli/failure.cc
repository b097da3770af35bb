#include "cli/failure.h"

#include <cstdio>
#include <string>

#include "events/json_events.h"

namespace getme::cli {

int ReportFailure(const absl::Status& status, bool json, int exit_status) {
  std::fprintf(stderr, "getme: %s\n", std::string(status.message()).c_str());
  std::fflush(stderr);
  if (json) {
    std::printf("%s\n", events::ErrorJson(status).c_str());
    std::fflush(stdout);
  }
  return exit_status;
}

int ReportRemoteFailure(const absl::Status& status, bool json, int exit_status) {
  // The server's message says what it wants; this says how the CLI provides it.
  const char* hint = status.code() == absl::StatusCode::kUnauthenticated
                         ? " (give the token with --token-file FILE or GETME_TOKEN)"
                         : "";
  std::fprintf(stderr, "getme: %s: %s%s\n", absl::StatusCodeToString(status.code()).c_str(),
               std::string(status.message()).c_str(), hint);
  std::fflush(stderr);
  if (json) {
    std::printf("%s\n", events::ErrorJson(status).c_str());
    std::fflush(stdout);
  }
  return exit_status;
}

}  // namespace getme::cli
