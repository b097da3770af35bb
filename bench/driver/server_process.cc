#include "server_process.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>
#include <vector>

#include "absl/strings/str_cat.h"

extern char** environ;

namespace getme::bench {
namespace {

// The port from the server's "getme-server listening on port N" line, or 0 if not there yet.
int PortFromLog(const std::string& log_path) {
  std::ifstream log(log_path);
  std::stringstream text;
  text << log.rdbuf();
  static const std::regex kListening("getme-server listening on port ([0-9]+)");
  std::smatch match;
  const std::string content = text.str();
  if (!std::regex_search(content, match, kListening)) return 0;
  return std::stoi(match[1].str());
}

}  // namespace

absl::StatusOr<std::unique_ptr<ServerProcess>> ServerProcess::Start(const std::string& binary,
                                                                    const std::string& log_path,
                                                                    bool keep_log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log_path.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  // Every progress event is streamed, as in-process: the overhead measured includes all of them.
  std::vector<std::string> args = {binary, "--listen", "127.0.0.1:0", "--progress_interval", "0"};
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (error != 0) {
    if (!keep_log) std::remove(log_path.c_str());  // the child may have created it
    return absl::ErrnoToStatus(error, absl::StrCat("cannot start the server '", binary, "'"));
  }
  // Owned from here on, so every return below stops the server again.
  std::unique_ptr<ServerProcess> server(new ServerProcess(pid, log_path, keep_log));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (std::chrono::steady_clock::now() < deadline) {
    if (const int port = PortFromLog(log_path); port != 0) {
      server->port_ = port;
      return server;
    }
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) {
      server->pid_ = 0;
      server->keep_log_ = true;  // it says why
      return absl::UnavailableError(
          absl::StrCat("the server '", binary, "' exited at start; see ", log_path));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  server->keep_log_ = true;
  return absl::UnavailableError(
      absl::StrCat("the server '", binary, "' logged no port within 30 s; see ", log_path));
}

ServerProcess::~ServerProcess() {
  if (pid_ > 0) {
    kill(pid_, SIGTERM);
    int status = 0;
    waitpid(pid_, &status, 0);
  }
  if (!keep_log_) std::remove(log_path_.c_str());
}

}  // namespace getme::bench
