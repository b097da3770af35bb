#pragma once

#include <sys/types.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"

namespace getme::redis::testing {

// A real redis-server for one test: a child process on a free loopback port, nothing persisted
// (--save "" --appendonly no), its files and log in a temporary directory removed afterwards.
class RedisServerProcess {
 public:
  static constexpr char kBinary[] = "/usr/bin/redis-server";

  struct Options {
    std::string password;  // --requirepass when not empty
    // TLS only (--port 0 --tls-port): the server's certificate and key, and the CA its clients'
    // certificates must chain to. `require_client_certificate` is Redis's tls-auth-clients.
    struct Tls {
      std::string cert_file;
      std::string key_file;
      std::string ca_file;
      bool require_client_certificate = false;
    };
    std::optional<Tls> tls;
    // Loopback addresses to listen on besides 127.0.0.1 (e.g. 127.0.0.2, which the test
    // certificates do not name).
    std::vector<std::string> extra_bind_addresses;
  };

  // False when redis-server is not installed: tests then GTEST_SKIP (CI installs it through
  // scripts/packages.txt).
  static bool Available();

  // Starts the server and waits until it answers PING; fails after 10 s with its log.
  static absl::StatusOr<std::unique_ptr<RedisServerProcess>> Start(Options options);
  static absl::StatusOr<std::unique_ptr<RedisServerProcess>> Start() { return Start(Options()); }

  // SIGTERM, then SIGKILL if it is still there after 2 s; removes the directory.
  ~RedisServerProcess();
  RedisServerProcess(const RedisServerProcess&) = delete;
  RedisServerProcess& operator=(const RedisServerProcess&) = delete;

  // SIGKILL, as a crash or an OOM kill would end it; waits until it is gone.
  void Kill();
  // Starts it again on the same port (after Kill), e.g. to test that clients reconnect.
  absl::Status Restart();

  int port() const { return port_; }
  // redis://[:password@]127.0.0.1:port, or with TLS
  // rediss://[:password@]127.0.0.1:port/0?cacert=CA (no client certificate)
  std::string url() const;
  std::string log() const;

 private:
  RedisServerProcess(Options options, std::string directory)
      : options_(std::move(options)), directory_(std::move(directory)) {}

  // Spawns redis-server on port_ and waits for PING; UNAVAILABLE with the log if it exits or
  // does not answer in time, ALREADY_EXISTS if the port was taken meanwhile.
  absl::Status Launch();
  void Stop(int signal_number, bool wait_forever);

  Options options_;
  std::string directory_;
  int port_ = 0;
  pid_t pid_ = -1;
};

}  // namespace getme::redis::testing
