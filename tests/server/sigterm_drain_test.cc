// The real getme-server binary: SIGTERM drains it (running job finishes, exit code 0).
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <thread>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "grpcpp/create_channel.h"
#include "grpcpp/security/credentials.h"
#include "gtest/gtest.h"
#include "server_test_support.h"

namespace getme::server::testing {
namespace {

struct Child {
  pid_t pid = -1;
  std::string log_path;
};

Child SpawnServer(const std::string& log_path) {
  Child child{-1, log_path};
  const std::string binary = std::string(GETME_BINARY_DIR) + "/bin/getme-server";
  child.pid = fork();
  if (child.pid == 0) {
    FILE* log = std::freopen(log_path.c_str(), "w", stderr);
    (void)log;
    execl(binary.c_str(), binary.c_str(), "--listen=127.0.0.1:0", "--workers=1",
          "--shutdown_grace=60s", static_cast<char*>(nullptr));
    _exit(127);
  }
  return child;
}

// The port from the "listening on port N" log line.
int WaitForPort(const std::string& log_path) {
  const std::regex listening("listening on port ([0-9]+)");
  for (int attempt = 0; attempt < 500; ++attempt) {
    std::ifstream log(log_path);
    std::stringstream text;
    text << log.rdbuf();
    std::smatch match;
    const std::string contents = text.str();
    if (std::regex_search(contents, match, listening)) return std::stoi(match[1]);
    absl::SleepFor(absl::Milliseconds(20));
  }
  return 0;
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

TEST(SigtermDrainTest, RunningJobFinishesAndTheServerExitsZero) {
  const std::string log_path =
      absl::StrCat(::testing::TempDir(), "/getme-server-sigterm-", getpid(), ".log");
  Child child = SpawnServer(log_path);
  ASSERT_GT(child.pid, 0);
  const int port = WaitForPort(log_path);
  ASSERT_GT(port, 0) << "the server did not log its port";
  auto stub = v1::Smoother::NewStub(
      grpc::CreateChannel(absl::StrCat("127.0.0.1:", port), grpc::InsecureChannelCredentials()));

  v1::SmoothingParameters finite;
  finite.set_method(v1::METHOD_SEQUENTIAL);
  finite.set_sequential_max_iterations(300'000);
  finite.set_sequential_stall_iterations(1'000'000);
  finite.set_sequential_improvement_tolerance(0.0);
  const v1::Mesh wire = ToWire(TetBlock(6, 0.3));
  SmoothOutcome outcome;
  std::thread client([&] { outcome = CallSmooth(*stub, SmoothRequests(wire, finite)); });
  // Send SIGTERM once the job runs.
  for (int attempt = 0; attempt < 1000; ++attempt) {
    grpc::ClientContext context;
    v1::ListJobsResponse list;
    if (stub->ListJobs(&context, {}, &list).ok() && list.jobs_size() > 0 &&
        list.jobs(0).state() == v1::JOB_STATE_RUNNING) {
      break;
    }
    absl::SleepFor(absl::Milliseconds(10));
  }
  ASSERT_EQ(kill(child.pid, SIGTERM), 0);
  const int exit_code = WaitForExit(child.pid, absl::Seconds(60));
  client.join();
  EXPECT_EQ(exit_code, 0);
  ASSERT_TRUE(outcome.status.ok()) << outcome.status.error_message();
  EXPECT_EQ(outcome.result.iterations_sequential(), 300'000);
  EXPECT_EQ(outcome.mesh.coordinates_size(), wire.coordinates_size());

  std::ifstream log(log_path);
  std::stringstream text;
  text << log.rdbuf();
  EXPECT_NE(text.str().find("received SIGTERM"), std::string::npos) << text.str();
  EXPECT_NE(text.str().find("outcome=SUCCEEDED"), std::string::npos) << text.str();
  std::remove(log_path.c_str());
}

}  // namespace
}  // namespace getme::server::testing
