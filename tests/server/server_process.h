#pragma once

#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

#include "absl/time/time.h"

namespace getme::server::testing {

// The real getme-server binary as a child process, its stderr in a log file.
struct ServerProcess {
  pid_t pid = -1;
  std::string log_path;
};
// Starts bin/getme-server with `flags` (--listen, --http_listen= are added unless given) and
// `environment` ("NAME=value") added to the test's.
ServerProcess SpawnServer(const std::string& log_path, const std::vector<std::string>& flags,
                          const std::vector<std::string>& environment = {});
// The gRPC port from the "listening on port N" log line; 0 if it does not appear in time.
int WaitForPort(const std::string& log_path);
// The HTTP gateway's port (--http_listen) from its log line; 0 if it does not appear in time.
int WaitForHttpPort(const std::string& log_path);
// The exit code (128 + signal when killed); -1 after `timeout` (the process is then killed).
int WaitForExit(pid_t pid, absl::Duration timeout);
std::string ReadFile(const std::string& path);
// Resident set size from /proc/<pid>/status, in KiB; -1 if unreadable.
std::int64_t ResidentKiB(pid_t pid);

}  // namespace getme::server::testing
