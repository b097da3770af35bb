#include "server_process.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>

#include "absl/strings/match.h"
#include "absl/time/clock.h"

namespace getme::server::testing {

ServerProcess SpawnServer(const std::string& log_path, const std::vector<std::string>& flags,
                          const std::vector<std::string>& environment) {
  ServerProcess child{-1, log_path};
  const std::string binary = std::string(GETME_BINARY_DIR) + "/bin/getme-server";
  std::vector<std::string> args = {binary};
  auto given = [&flags](const char* name) {
    for (const std::string& flag : flags) {
      if (absl::StartsWith(flag, name)) return true;
    }
    return false;
  };
  if (!given("--listen")) args.push_back("--listen=127.0.0.1:0");
  if (!given("--http_listen")) args.push_back("--http_listen=");
  args.insert(args.end(), flags.begin(), flags.end());
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  // Emptied here, before the fork: WaitForPort reads the file at once, and an earlier process
  // with the same pid (pids wrap) may have left a log of this name naming its own, dead, port.
  std::ofstream(log_path, std::ios::trunc).close();
  child.pid = fork();
  if (child.pid == 0) {
    FILE* log = std::freopen(log_path.c_str(), "w", stderr);
    // Not ctest's pipe: a server outliving a killed test would keep ctest waiting for its end.
    if (log != nullptr) dup2(fileno(log), STDOUT_FILENO);
    for (const std::string& variable : environment) putenv(strdup(variable.c_str()));
    execv(binary.c_str(), argv.data());
    _exit(127);
  }
  return child;
}

std::string ReadFile(const std::string& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

namespace {

// The number the first match of `pattern` captures in the log, waiting up to 10 s; 0 if none.
int WaitForLoggedNumber(const std::string& log_path, const std::regex& pattern) {
  for (int attempt = 0; attempt < 500; ++attempt) {
    std::smatch match;
    const std::string contents = ReadFile(log_path);
    if (std::regex_search(contents, match, pattern)) return std::stoi(match[1]);
    absl::SleepFor(absl::Milliseconds(20));
  }
  return 0;
}

}  // namespace

int WaitForPort(const std::string& log_path) {
  return WaitForLoggedNumber(log_path, std::regex("listening on port ([0-9]+)"));
}

int WaitForHttpPort(const std::string& log_path) {
  return WaitForLoggedNumber(log_path,
                             std::regex("HTTP gateway and dashboard at .* \\(port ([0-9]+)\\)"));
}

int WaitForExit(pid_t pid, absl::Duration timeout) {
  const absl::Time deadline = absl::Now() + timeout;
  while (absl::Now() < deadline) {
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) {
      return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    absl::SleepFor(absl::Milliseconds(20));
  }
  kill(pid, SIGKILL);
  waitpid(pid, nullptr, 0);
  return -1;
}

std::int64_t ResidentKiB(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line)) {
    if (absl::StartsWith(line, "VmRSS:")) return std::stoll(line.substr(6));
  }
  return -1;
}

}  // namespace getme::server::testing
