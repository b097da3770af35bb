// The real getme-server process killed (SIGKILL) and restarted on the same port while clients
// call it, and the client library's retry rule, which keeps a restart from duplicating jobs.
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"
#include "remote/retry.h"
#include "remote/smoother_client.h"
#include "server_process.h"
#include "server_test_support.h"

namespace getme::server::testing {
namespace {

using ::testing::HasSubstr;

std::string LogPath(const std::string& name) {
  return absl::StrCat(::testing::TempDir(), "/getme-server-", name, "-", getpid(), ".log");
}

remote::CallOptions PatientCall() {
  remote::CallOptions call;
  call.retry.max_attempts = 30;
  call.retry.initial_backoff = absl::Milliseconds(100);
  call.retry.max_backoff = absl::Milliseconds(500);
  call.timeout = absl::Seconds(60);
  return call;
}

remote::SmoothJobOptions QuickJob() {
  remote::SmoothJobOptions job;
  job.parameters.set_method(v1::METHOD_SIMULTANEOUS);
  return job;
}

TEST(ProcessFaultsTest, KilledServerIsUnavailableAndARetryAfterRestartSucceedsOnce) {
  const std::string first_log = LogPath("killed");
  ServerProcess first = SpawnServer(first_log, {"--workers=1"});
  ASSERT_GT(first.pid, 0);
  const int port = WaitForPort(first_log);
  ASSERT_GT(port, 0) << ReadFile(first_log);
  const std::string address = absl::StrCat("127.0.0.1:", port);
  remote::SmootherClient client(remote::SmootherClient::CreateChannel(address));
  ASSERT_TRUE(client.ListJobs().ok());
  const v1::Mesh wire = ToWire(SmallHybridMesh());

  // Two restarts: a Smooth call, then a SubmitJob, each made while the server is down.
  for (const bool submit : {false, true}) {
    ASSERT_EQ(kill(first.pid, SIGKILL), 0);
    EXPECT_EQ(WaitForExit(first.pid, absl::Seconds(10)), 128 + SIGKILL);
    remote::CallOptions once;
    once.retry.max_attempts = 1;
    absl::StatusOr<std::vector<v1::Job>> down = client.ListJobs(once);
    EXPECT_EQ(down.status().code(), absl::StatusCode::kUnavailable) << down.status();

    const std::string log = LogPath(absl::StrCat("restarted-", submit));
    std::thread restart([&] {
      absl::SleepFor(absl::Milliseconds(400));
      first = SpawnServer(log, {"--workers=1", absl::StrCat("--listen=", address)});
    });
    std::string job_id;
    if (submit) {
      absl::StatusOr<v1::Job> job = client.SubmitJob(wire, QuickJob(), PatientCall());
      ASSERT_TRUE(job.ok()) << job.status();
      job_id = job->job_id();
      ASSERT_TRUE(client.WatchJob(job_id, {}, PatientCall()).ok());
      absl::StatusOr<remote::RemoteSmoothResult> result = client.GetResult(job_id);
      ASSERT_TRUE(result.ok()) << result.status();
      EXPECT_EQ(result->mesh.coordinates_size(), wire.coordinates_size());
    } else {
      absl::StatusOr<remote::RemoteSmoothResult> result =
          client.Smooth(wire, QuickJob(), {}, PatientCall());
      restart.join();
      ASSERT_TRUE(result.ok()) << result.status() << ReadFile(log);
      EXPECT_EQ(result->mesh.coordinates_size(), wire.coordinates_size());
      EXPECT_EQ(result->result.after().invalid_elements(), 0);
      job_id = result->result.job_id();
    }
    if (restart.joinable()) restart.join();
    EXPECT_EQ(WaitForPort(log), port);
    // Exactly one job reached the restarted server: the retries duplicated nothing.
    absl::StatusOr<std::vector<v1::Job>> jobs = client.ListJobs();
    ASSERT_TRUE(jobs.ok()) << jobs.status();
    ASSERT_EQ(jobs->size(), 1u);
    EXPECT_EQ(jobs->front().job_id(), job_id);
    std::remove(log.c_str());
  }
  kill(first.pid, SIGTERM);
  EXPECT_EQ(WaitForExit(first.pid, absl::Seconds(30)), 0);
  std::remove(first_log.c_str());
}

// gRPC would share a taken port through SO_REUSEPORT and split the connections between both
// servers; a second server on the same port must be refused instead.
TEST(ProcessFaultsTest, ASecondServerOnATakenPortIsRefused) {
  const std::string first_log = LogPath("first-on-port");
  const ServerProcess first = SpawnServer(first_log, {"--workers=1"});
  ASSERT_GT(first.pid, 0);
  const int port = WaitForPort(first_log);
  ASSERT_GT(port, 0) << ReadFile(first_log);
  const std::string address = absl::StrCat("127.0.0.1:", port);

  const std::string second_log = LogPath("second-on-port");
  const ServerProcess second = SpawnServer(second_log, {absl::StrCat("--listen=", address)});
  ASSERT_GT(second.pid, 0);
  EXPECT_EQ(WaitForExit(second.pid, absl::Seconds(30)), 1) << ReadFile(second_log);
  EXPECT_THAT(ReadFile(second_log), HasSubstr(absl::StrCat("cannot listen on '", address, "'")));

  {
    // The first one still answers, alone.
    remote::SmootherClient client(remote::SmootherClient::CreateChannel(address));
    EXPECT_TRUE(client.ListJobs().ok());
  }
  kill(first.pid, SIGTERM);
  EXPECT_EQ(WaitForExit(first.pid, absl::Seconds(30)), 0);
  std::remove(first_log.c_str());
  std::remove(second_log.c_str());
}

TEST(RetryPolicyTest, RetriesOnlyUnavailableAttemptsMarkedSafeAndSaysHowMany) {
  remote::CallOptions call;
  call.retry.max_attempts = 3;
  call.retry.initial_backoff = absl::Milliseconds(1);
  int attempts = 0;
  absl::Status unavailable = remote::WithRetry(call, [&](remote::Attempt&) {
    ++attempts;
    return absl::UnavailableError("connection refused");
  });
  EXPECT_EQ(attempts, 3);
  EXPECT_EQ(unavailable.message(), "connection refused (3 attempts)");

  attempts = 0;
  absl::Status accepted = remote::WithRetry(call, [&](remote::Attempt& attempt) {
    ++attempts;
    attempt.retry_safe = false;  // e.g. the whole upload was sent
    return absl::UnavailableError("connection reset");
  });
  EXPECT_EQ(attempts, 1);
  EXPECT_EQ(accepted.message(), "connection reset");

  attempts = 0;
  absl::StatusOr<int> refused = remote::WithRetry(call, [&](remote::Attempt&) {
    ++attempts;
    return absl::StatusOr<int>(absl::ResourceExhaustedError("queue full"));
  });
  EXPECT_EQ(attempts, 1);
  EXPECT_EQ(refused.status().code(), absl::StatusCode::kResourceExhausted);

  attempts = 0;
  absl::StatusOr<int> second = remote::WithRetry(call, [&](remote::Attempt&) {
    return ++attempts < 2 ? absl::StatusOr<int>(absl::UnavailableError("down"))
                          : absl::StatusOr<int>(7);
  });
  EXPECT_EQ(attempts, 2);
  EXPECT_EQ(second.value_or(0), 7);

  // The timeout covers all attempts.
  call.retry.max_attempts = 100;
  call.retry.initial_backoff = absl::Milliseconds(50);
  call.timeout = absl::Milliseconds(300);
  attempts = 0;
  const absl::Time start = absl::Now();
  absl::Status timed_out = remote::WithRetry(call, [&](remote::Attempt& attempt) {
    ++attempts;
    EXPECT_LE(attempt.deadline, start + absl::Milliseconds(310));
    return absl::UnavailableError("down");
  });
  EXPECT_LT(absl::Now() - start, absl::Seconds(2));
  EXPECT_LT(attempts, 10);
  EXPECT_THAT(std::string(timed_out.message()), HasSubstr("attempts)"));
}

}  // namespace
}  // namespace getme::server::testing
