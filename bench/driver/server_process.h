#pragma once

#include <sys/types.h>

#include <memory>
#include <string>

#include "absl/status/statusor.h"

namespace getme::bench {

// A getme-server child process on a free loopback port, for measuring the service overhead the
// way a user meets it (a separate process, reached over TCP). Stopped with SIGTERM (its graceful
// drain) when destroyed; the log is removed then unless `keep_log`.
class ServerProcess {
 public:
  // Starts `binary --listen 127.0.0.1:0 --progress_interval 0`, its output going to `log_path`,
  // and waits (up to 30 s) for the port it logs. Unavailable naming the log if it does not start.
  static absl::StatusOr<std::unique_ptr<ServerProcess>> Start(const std::string& binary,
                                                              const std::string& log_path,
                                                              bool keep_log);
  ~ServerProcess();
  ServerProcess(const ServerProcess&) = delete;
  ServerProcess& operator=(const ServerProcess&) = delete;

  pid_t pid() const { return pid_; }
  std::string target() const { return "127.0.0.1:" + std::to_string(port_); }

 private:
  ServerProcess(pid_t pid, std::string log_path, bool keep_log)
      : pid_(pid), log_path_(std::move(log_path)), keep_log_(keep_log) {}
  pid_t pid_;
  int port_ = 0;
  std::string log_path_;
  bool keep_log_;
};

}  // namespace getme::bench
