// The real getme-server binary and SIGTERM: the running job finishes (or, past the grace period,
// is cancelled), queued jobs are cancelled, new jobs are refused with UNAVAILABLE, exit code 0.
#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <string>
#include <thread>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "gmock/gmock.h"
#include "grpcpp/create_channel.h"
#include "grpcpp/security/credentials.h"
#include "gtest/gtest.h"
#include "server_process.h"
#include "server_test_support.h"

namespace getme::server::testing {
namespace {

using ::testing::HasSubstr;

std::string LogPath(const char* name) {
  return absl::StrCat(::testing::TempDir(), "/getme-server-", name, "-", getpid(), ".log");
}

std::unique_ptr<v1::Smoother::Stub> Connect(int port) {
  return v1::Smoother::NewStub(
      grpc::CreateChannel(absl::StrCat("127.0.0.1:", port), grpc::InsecureChannelCredentials()));
}

// Polls ListJobs until `count` jobs are listed and the oldest one runs.
bool WaitUntilRunningWithQueue(v1::Smoother::Stub& stub, int count) {
  for (int attempt = 0; attempt < 1000; ++attempt) {
    grpc::ClientContext context;
    v1::ListJobsResponse list;
    if (stub.ListJobs(&context, {}, &list).ok() && list.jobs_size() == count &&
        list.jobs(count - 1).state() == v1::JOB_STATE_RUNNING) {
      return true;
    }
    absl::SleepFor(absl::Milliseconds(10));
  }
  return false;
}

TEST(SigtermDrainTest, RunningJobFinishesAndTheServerExitsZero) {
  const std::string log_path = LogPath("sigterm");
  ServerProcess child = SpawnServer(log_path, {"--workers=1", "--shutdown_grace=60s"});
  ASSERT_GT(child.pid, 0);
  const int port = WaitForPort(log_path);
  ASSERT_GT(port, 0) << "the server did not log its port";
  auto stub = Connect(port);

  v1::SmoothingParameters finite;
  finite.set_method(v1::METHOD_SEQUENTIAL);
  finite.set_sequential_max_iterations(300'000);
  finite.set_sequential_stall_iterations(1'000'000);
  finite.set_sequential_improvement_tolerance(0.0);
  const v1::Mesh wire = ToWire(TetBlock(6, 0.3));
  SmoothOutcome outcome;
  std::thread client([&] { outcome = CallSmooth(*stub, SmoothRequests(wire, finite)); });
  // Send SIGTERM once the job runs.
  WaitUntilRunningWithQueue(*stub, 1);
  ASSERT_EQ(kill(child.pid, SIGTERM), 0);
  const int exit_code = WaitForExit(child.pid, absl::Seconds(60));
  client.join();
  EXPECT_EQ(exit_code, 0);
  ASSERT_TRUE(outcome.status.ok()) << outcome.status.error_message();
  EXPECT_EQ(outcome.result.iterations_sequential(), 300'000);
  EXPECT_EQ(outcome.mesh.coordinates_size(), wire.coordinates_size());

  const std::string log = ReadFile(log_path);
  EXPECT_NE(log.find("received SIGTERM"), std::string::npos) << log;
  EXPECT_NE(log.find("outcome=SUCCEEDED"), std::string::npos) << log;
  std::remove(log_path.c_str());
}

TEST(SigtermDrainTest, QueuedJobsAreCancelledAndNewJobsRefusedWhileDraining) {
  const std::string log_path = LogPath("sigterm-queued");
  // Long enough for the refused submission below (a new connection and an upload) to finish
  // inside it on a loaded machine: after it, gRPC itself shuts down and answers differently.
  constexpr absl::Duration kGrace = absl::Seconds(5);
  ServerProcess child = SpawnServer(
      log_path, {"--workers=1", absl::StrCat("--shutdown_grace=", absl::FormatDuration(kGrace))});
  ASSERT_GT(child.pid, 0);
  const int port = WaitForPort(log_path);
  ASSERT_GT(port, 0) << "the server did not log its port";
  auto stub = Connect(port);
  const auto requests = SmoothRequests(ToWire(TetBlock(6, 0.3)), LongRunningParameters());

  SmoothOutcome running;
  SmoothOutcome queued;
  std::thread running_client([&] { running = CallSmooth(*stub, requests); });
  ASSERT_TRUE(WaitUntilRunningWithQueue(*stub, 1));
  std::thread queued_client([&] { queued = CallSmooth(*stub, requests); });
  ASSERT_TRUE(WaitUntilRunningWithQueue(*stub, 2));

  const absl::Time signalled = absl::Now();
  ASSERT_EQ(kill(child.pid, SIGTERM), 0);
  for (int attempt = 0; attempt < 500; ++attempt) {
    if (ReadFile(log_path).find("shutting down") != std::string::npos) break;
    absl::SleepFor(absl::Milliseconds(10));
  }
  // Draining: the running job is still within its grace period, and a new job is refused.
  absl::StatusOr<v1::Job> refused = Submit(*Connect(port), requests);
  EXPECT_EQ(refused.status().code(), absl::StatusCode::kUnavailable) << refused.status();
  EXPECT_EQ(refused.status().message(), "the server is shutting down and accepts no new jobs");

  const int exit_code = WaitForExit(child.pid, absl::Seconds(30));
  const absl::Duration drain = absl::Now() - signalled;
  running_client.join();
  queued_client.join();
  EXPECT_EQ(exit_code, 0);
  EXPECT_GE(drain, kGrace) << "the running job was not given its grace period";
  EXPECT_LT(drain, kGrace + absl::Seconds(15));
  std::printf("drain took %s (grace %s)\n", absl::FormatDuration(drain).c_str(),
              absl::FormatDuration(kGrace).c_str());

  EXPECT_EQ(queued.status.error_code(), grpc::StatusCode::CANCELLED);
  EXPECT_THAT(queued.status.error_message(), HasSubstr("the server is shutting down"));
  EXPECT_EQ(running.status.error_code(), grpc::StatusCode::CANCELLED);
  EXPECT_THAT(running.status.error_message(), HasSubstr("the server is shutting down"));
  const std::string log = ReadFile(log_path);
  EXPECT_THAT(log, HasSubstr("(while queued)"));
  EXPECT_THAT(log, HasSubstr("grace period over: cancelling the jobs still running"));
  std::remove(log_path.c_str());
}

}  // namespace
}  // namespace getme::server::testing
