#include "redis_server_process.h"

#include <hiredis/hiredis.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "absl/time/time.h"

namespace getme::redis::testing {
namespace {

// A port the kernel just handed out and took back. Another process may take it before
// redis-server binds it: Start then tries another.
int PickFreePort() {
  const int socket_fd = socket(AF_INET, SOCK_STREAM, 0);
  if (socket_fd < 0) return 0;
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = 0;
  socklen_t length = sizeof(address);
  int port = 0;
  if (bind(socket_fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0 &&
      getsockname(socket_fd, reinterpret_cast<sockaddr*>(&address), &length) == 0) {
    port = ntohs(address.sin_port);
  }
  close(socket_fd);
  return port;
}

// Any reply, even NOAUTH, shows the server is up and serving.
bool Answers(int port) {
  redisContext* context = redisConnectWithTimeout("127.0.0.1", port, {0, 200'000});
  if (context == nullptr) return false;
  bool answered = false;
  if (context->err == 0) {
    void* reply = redisCommand(context, "PING");
    answered = reply != nullptr;
    if (reply != nullptr) freeReplyObject(reply);
  }
  redisFree(context);
  return answered;
}

// A TLS port cannot be PINGed by plain hiredis: that it accepts connections is enough, since
// redis-server opens its ports last.
bool Listens(int port) {
  const int socket_fd = socket(AF_INET, SOCK_STREAM, 0);
  if (socket_fd < 0) return false;
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  address.sin_port = htons(static_cast<uint16_t>(port));
  const bool listens =
      connect(socket_fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0;
  close(socket_fd);
  return listens;
}

}  // namespace

bool RedisServerProcess::Available() { return access(kBinary, X_OK) == 0; }

absl::StatusOr<std::unique_ptr<RedisServerProcess>> RedisServerProcess::Start(Options options) {
  std::string directory = (std::filesystem::temp_directory_path() / "getme-redis-XXXXXX").string();
  if (mkdtemp(directory.data()) == nullptr) {
    return absl::InternalError(absl::StrCat("mkdtemp ", directory, " failed"));
  }
  std::unique_ptr<RedisServerProcess> server(
      new RedisServerProcess(std::move(options), std::move(directory)));
  absl::Status status;
  for (int attempt = 0; attempt < 5; ++attempt) {
    server->port_ = PickFreePort();
    // redis-server appends to its log: a new attempt starts a new one, so that the last
    // attempt's failure is the one reported.
    std::error_code ignored;
    std::filesystem::remove(server->directory_ + "/redis.log", ignored);
    status = server->Launch();
    if (!absl::IsAlreadyExists(status)) break;
  }
  if (!status.ok()) return status;
  return server;
}

absl::Status RedisServerProcess::Launch() {
  const std::string log_path = directory_ + "/redis.log";
  std::vector<std::string> args = {kBinary,  "--port",       absl::StrCat(port_),
                                   "--bind", "127.0.0.1",    "--save",
                                   "",       "--appendonly", "no",
                                   "--dir",  directory_,     "--logfile",
                                   log_path, "--daemonize",  "no"};
  for (const std::string& address : options_.extra_bind_addresses) {
    args[4] += " " + address;
  }
  if (!options_.password.empty()) {
    args.push_back("--requirepass");
    args.push_back(options_.password);
  }
  if (options_.tls) {
    args[2] = "0";  // no plain port
    for (const std::string& arg :
         {std::string("--tls-port"), absl::StrCat(port_), std::string("--tls-cert-file"),
          options_.tls->cert_file, std::string("--tls-key-file"), options_.tls->key_file,
          std::string("--tls-ca-cert-file"), options_.tls->ca_file,
          std::string("--tls-auth-clients"),
          std::string(options_.tls->require_client_certificate ? "yes" : "no")}) {
      args.push_back(arg);
    }
  }
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  pid_ = fork();
  if (pid_ < 0) return absl::InternalError("fork failed");
  if (pid_ == 0) {
    // A test that crashes must not leave servers behind.
    prctl(PR_SET_PDEATHSIG, SIGKILL);
    execv(kBinary, argv.data());
    _exit(127);
  }
  const absl::Time deadline = absl::Now() + absl::Seconds(10);
  while (absl::Now() < deadline) {
    int wait_status = 0;
    if (waitpid(pid_, &wait_status, WNOHANG) == pid_) {
      pid_ = -1;
      const std::string text = log();
      if (absl::StrContains(text, "Address already in use")) {
        return absl::AlreadyExistsError(absl::StrCat("port ", port_, " taken"));
      }
      return absl::UnavailableError(absl::StrCat("redis-server exited early:\n", text));
    }
    if (options_.tls ? Listens(port_) : Answers(port_)) return absl::OkStatus();
    absl::SleepFor(absl::Milliseconds(10));
  }
  Stop(SIGKILL, true);
  return absl::UnavailableError(
      absl::StrCat("redis-server did not answer PING within 10 s:\n", log()));
}

void RedisServerProcess::Stop(int signal_number, bool wait_forever) {
  if (pid_ <= 0) return;
  kill(pid_, signal_number);
  const absl::Time deadline = absl::Now() + absl::Seconds(2);
  while (wait_forever || absl::Now() < deadline) {
    if (waitpid(pid_, nullptr, WNOHANG) == pid_) {
      pid_ = -1;
      return;
    }
    absl::SleepFor(absl::Milliseconds(5));
  }
  kill(pid_, SIGKILL);
  waitpid(pid_, nullptr, 0);
  pid_ = -1;
}

RedisServerProcess::~RedisServerProcess() {
  Stop(SIGTERM, false);
  std::error_code ignored;
  std::filesystem::remove_all(directory_, ignored);
}

void RedisServerProcess::Kill() { Stop(SIGKILL, true); }

absl::Status RedisServerProcess::Restart() {
  Stop(SIGTERM, false);
  return Launch();
}

std::string RedisServerProcess::url() const {
  const std::string login = options_.password.empty() ? "" : ":" + options_.password + "@";
  if (options_.tls) {
    return absl::StrCat("rediss://", login, "127.0.0.1:", port_,
                        "/0?cacert=", options_.tls->ca_file);
  }
  return absl::StrCat("redis://", login, "127.0.0.1:", port_);
}

std::string RedisServerProcess::log() const {
  std::ifstream file(directory_ + "/redis.log");
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace getme::redis::testing
