// Jobs that outlive calls: several clients at once, the bounded queue, cancellation (CancelJob,
// client cancel, deadline), result time to live, and the Shutdown drain.
#include <chrono>
#include <thread>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "grpcpp/create_channel.h"
#include "grpcpp/security/credentials.h"
#include "gtest/gtest.h"
#include "server_test_support.h"

namespace getme::server::testing {
namespace {

std::vector<v1::SmoothRequest> LongJobRequests() {
  return SmoothRequests(ToWire(TetBlock(6, 0.3)), LongRunningParameters());
}

TEST(JobsTest, SeveralClientsWithMoreJobsThanWorkersAllSucceed) {
  ServerOptions options = TestOptions();
  options.workers = 2;
  options.max_queued_jobs = 8;
  TestServer test = StartTestServer(options);
  const v1::Mesh wire = ToWire(SmallHybridMesh());
  v1::SmoothingParameters parameters;
  parameters.set_method(v1::METHOD_SIMULTANEOUS);

  const SmoothOutcome reference = CallSmooth(*test.stub, SmoothRequests(wire, parameters));
  ASSERT_TRUE(reference.status.ok()) << reference.status.error_message();

  constexpr int kClients = 6;  // three times the workers; all fit in the queue
  std::vector<SmoothOutcome> outcomes(kClients);
  std::vector<std::thread> clients;
  for (int c = 0; c < kClients; ++c) {
    clients.emplace_back([&, c] {
      // Each client has its own channel, like separate processes.
      auto channel = grpc::CreateChannel(absl::StrCat("127.0.0.1:", test.server->port()),
                                         grpc::InsecureChannelCredentials());
      auto stub = v1::Smoother::NewStub(channel);
      outcomes[c] = CallSmooth(*stub, SmoothRequests(wire, parameters));
    });
  }
  for (auto& client : clients) client.join();
  for (int c = 0; c < kClients; ++c) {
    ASSERT_TRUE(outcomes[c].status.ok())
        << "client " << c << ": " << outcomes[c].status.error_message();
    EXPECT_EQ(outcomes[c].mesh.coordinates_size(), reference.mesh.coordinates_size());
    for (int i = 0; i < reference.mesh.coordinates_size(); ++i) {
      ASSERT_EQ(outcomes[c].mesh.coordinates(i), reference.mesh.coordinates(i));
    }
  }
}

TEST(JobsTest, FullQueueAnswersResourceExhaustedAtOnce) {
  ServerOptions options = TestOptions();
  options.workers = 1;
  options.max_queued_jobs = 1;
  TestServer test = StartTestServer(options);
  auto running = Submit(*test.stub, LongJobRequests());
  ASSERT_TRUE(running.ok()) << running.status();
  WaitForState(*test.stub, running->job_id(), v1::JOB_STATE_RUNNING);
  auto queued = Submit(*test.stub, LongJobRequests());
  ASSERT_TRUE(queued.ok()) << queued.status();
  EXPECT_EQ(queued->state(), v1::JOB_STATE_QUEUED);

  const absl::Time start = absl::Now();
  auto refused = Submit(*test.stub, LongJobRequests());
  EXPECT_LT(absl::Now() - start, absl::Seconds(2)) << "refused at once, not after waiting";
  ASSERT_EQ(refused.status().code(), absl::StatusCode::kResourceExhausted);
  EXPECT_NE(refused.status().message().find("--max_queued_jobs"), std::string::npos);
  // Smooth goes through the same queue.
  SmoothOutcome refused_smooth = CallSmooth(*test.stub, LongJobRequests());
  EXPECT_EQ(refused_smooth.status.error_code(), grpc::StatusCode::RESOURCE_EXHAUSTED);

  // ListJobs: newest first, the refused jobs are not there.
  grpc::ClientContext context;
  v1::ListJobsResponse list;
  ASSERT_TRUE(test.stub->ListJobs(&context, {}, &list).ok());
  ASSERT_EQ(list.jobs_size(), 2);
  EXPECT_EQ(list.jobs(0).job_id(), queued->job_id());
  EXPECT_EQ(list.jobs(1).job_id(), running->job_id());
  EXPECT_EQ(list.jobs(1).state(), v1::JOB_STATE_RUNNING);

  // Cancelling the queued job frees its slot at once.
  grpc::ClientContext cancel_context;
  v1::CancelJobRequest cancel;
  cancel.set_job_id(queued->job_id());
  v1::Job cancelled;
  ASSERT_TRUE(test.stub->CancelJob(&cancel_context, cancel, &cancelled).ok());
  EXPECT_EQ(cancelled.state(), v1::JOB_STATE_CANCELLED);
  EXPECT_EQ(cancelled.error_code(), static_cast<int>(grpc::StatusCode::CANCELLED));
  auto accepted = Submit(*test.stub, LongJobRequests());
  EXPECT_TRUE(accepted.ok()) << accepted.status();
  test.server->Shutdown(absl::ZeroDuration());
}

TEST(JobsTest, CancelJobStopsARunningJobQuickly) {
  TestServer test = StartTestServer();
  auto job = Submit(*test.stub, LongJobRequests());
  ASSERT_TRUE(job.ok()) << job.status();
  WaitForProgress(*test.stub, job->job_id());

  const absl::Time start = absl::Now();
  grpc::ClientContext context;
  v1::CancelJobRequest cancel;
  cancel.set_job_id(job->job_id());
  v1::Job reply;
  ASSERT_TRUE(test.stub->CancelJob(&context, cancel, &reply).ok());
  v1::Job done = WaitForState(*test.stub, job->job_id(), v1::JOB_STATE_CANCELLED);
  EXPECT_LT(absl::Now() - start, absl::Seconds(2));
  EXPECT_EQ(done.error_code(), static_cast<int>(grpc::StatusCode::CANCELLED));
  EXPECT_NE(done.error_message().find("CancelJob"), std::string::npos) << done.error_message();
  EXPECT_GT(done.latest_progress().iteration(), 0);

  SmoothOutcome result = CallGetResult(*test.stub, job->job_id());
  EXPECT_EQ(result.status.error_code(), grpc::StatusCode::CANCELLED);
}

TEST(JobsTest, ClientCancellingSmoothCancelsTheJob) {
  TestServer test = StartTestServer();
  const std::vector<v1::SmoothRequest> requests = LongJobRequests();
  grpc::ClientContext context;
  std::string job_id;
  absl::Time cancelled_at;
  std::thread canceller([&] {
    // Cancelled while it runs: once the server lists the job with progress.
    const absl::Time deadline = absl::Now() + absl::Seconds(60);
    while (job_id.empty() && absl::Now() < deadline) {
      for (const v1::Job& job : ListedJobs(*test.stub)) job_id = job.job_id();
      if (job_id.empty()) absl::SleepFor(absl::Milliseconds(5));
    }
    if (!job_id.empty()) WaitForProgress(*test.stub, job_id);
    cancelled_at = absl::Now();
    context.TryCancel();
  });
  SmoothOutcome outcome = CallSmooth(*test.stub, requests, &context);
  canceller.join();
  EXPECT_EQ(outcome.status.error_code(), grpc::StatusCode::CANCELLED);
  ASSERT_FALSE(job_id.empty()) << "the job was never listed";
  v1::Job done = WaitForState(*test.stub, job_id, v1::JOB_STATE_CANCELLED, absl::Seconds(5));
  EXPECT_LT(absl::Now() - cancelled_at, absl::Seconds(4));
  EXPECT_GT(done.latest_progress().iteration(), 0) << "the job ran before it was cancelled";
  EXPECT_NE(done.error_message().find("client cancelled"), std::string::npos)
      << done.error_message();
}

TEST(JobsTest, DeadlineStopsTheJob) {
  TestServer test = StartTestServer();
  grpc::ClientContext context;
  const std::vector<v1::SmoothRequest> requests = LongJobRequests();
  // Long enough for the upload, the start and the first events on a loaded machine.
  constexpr absl::Duration kDeadline = absl::Seconds(3);
  context.set_deadline(absl::ToChronoTime(absl::Now() + kDeadline));
  const absl::Time start = absl::Now();
  SmoothOutcome outcome = CallSmooth(*test.stub, requests, &context);
  EXPECT_EQ(outcome.status.error_code(), grpc::StatusCode::DEADLINE_EXCEEDED);
  ASSERT_FALSE(outcome.events.empty());
  const std::string job_id = outcome.events.front().job_id();
  v1::Job done = WaitForState(*test.stub, job_id, v1::JOB_STATE_CANCELLED, absl::Seconds(5));
  EXPECT_LT(absl::Now() - start, kDeadline + absl::Seconds(3));
  EXPECT_NE(done.error_message().find("deadline"), std::string::npos) << done.error_message();
}

TEST(JobsTest, WatcherLeavingDoesNotCancelTheJob) {
  TestServer test = StartTestServer();
  auto job = Submit(*test.stub, LongJobRequests());
  ASSERT_TRUE(job.ok());
  WaitForProgress(*test.stub, job->job_id());  // a new watcher starts with the latest event
  {
    grpc::ClientContext context;
    context.set_deadline(std::chrono::system_clock::now() + std::chrono::milliseconds(400));
    v1::WatchJobRequest watch;
    watch.set_job_id(job->job_id());
    auto reader = test.stub->WatchJob(&context, watch);
    v1::ProgressEvent event;
    int events = 0;
    while (reader->Read(&event)) ++events;
    EXPECT_EQ(reader->Finish().error_code(), grpc::StatusCode::DEADLINE_EXCEEDED);
    EXPECT_GT(events, 0);
  }
  absl::SleepFor(absl::Milliseconds(200));
  EXPECT_EQ(GetJob(*test.stub, job->job_id()).state(), v1::JOB_STATE_RUNNING);
  test.server->Shutdown(absl::ZeroDuration());
}

TEST(JobsTest, UnfetchedResultsExpireAfterTheirTimeToLive) {
  ServerOptions options = TestOptions();
  options.result_ttl = absl::Seconds(1);  // expired for a second before it is forgotten
  TestServer test = StartTestServer(options);
  v1::SmoothingParameters parameters;
  parameters.set_method(v1::METHOD_SIMULTANEOUS);
  auto job = Submit(*test.stub, SmoothRequests(ToWire(SmallHybridMesh()), parameters));
  ASSERT_TRUE(job.ok());
  WaitForState(*test.stub, job->job_id(), v1::JOB_STATE_SUCCEEDED);
  // The sweeper expires results on its own schedule: wait for it (GetJob says so without
  // fetching), not for a fixed time that a loaded machine may overrun.
  grpc::StatusCode code = grpc::StatusCode::OK;
  const absl::Time deadline = absl::Now() + absl::Seconds(20);
  bool expired_seen = false;
  while (absl::Now() < deadline) {
    grpc::ClientContext context;
    v1::GetJobRequest request;
    request.set_job_id(job->job_id());
    v1::Job described;
    code = test.stub->GetJob(&context, request, &described).error_code();
    if (code != grpc::StatusCode::OK) break;  // forgotten
    if (!expired_seen && !described.result_available()) {
      expired_seen = true;
      SmoothOutcome expired = CallGetResult(*test.stub, job->job_id());
      EXPECT_EQ(expired.status.error_code(), grpc::StatusCode::NOT_FOUND);
      EXPECT_NE(expired.status.error_message().find("its time to live passed"), std::string::npos)
          << expired.status.error_message();
    }
    absl::SleepFor(absl::Milliseconds(20));
  }
  EXPECT_TRUE(expired_seen) << "the result never expired while the job was listed";
  EXPECT_EQ(code, grpc::StatusCode::NOT_FOUND) << "the job was never forgotten";
}

TEST(JobsTest, ShutdownLetsRunningJobsFinishAndCancelsQueuedOnes) {
  ServerOptions options = TestOptions();
  options.workers = 1;
  TestServer test = StartTestServer(options);
  v1::SmoothingParameters finite;
  finite.set_method(v1::METHOD_SEQUENTIAL);
  finite.set_sequential_max_iterations(300'000);  // about a second, then done
  finite.set_sequential_stall_iterations(1'000'000);
  finite.set_sequential_improvement_tolerance(0.0);
  const v1::Mesh wire = ToWire(TetBlock(6, 0.3));

  SmoothOutcome running, queued;
  std::thread running_client(
      [&] { running = CallSmooth(*test.stub, SmoothRequests(wire, finite)); });
  auto list_size = [&] {
    grpc::ClientContext context;
    v1::ListJobsResponse list;
    EXPECT_TRUE(test.stub->ListJobs(&context, {}, &list).ok());
    return list.jobs_size() > 0 ? list.jobs(0) : v1::Job();
  };
  while (list_size().state() != v1::JOB_STATE_RUNNING) absl::SleepFor(absl::Milliseconds(5));
  std::thread queued_client([&] { queued = CallSmooth(*test.stub, LongJobRequests()); });
  while (list_size().state() != v1::JOB_STATE_QUEUED) absl::SleepFor(absl::Milliseconds(5));

  // A job still running when the grace period ends is cancelled; this one finishes in time.
  auto shutdown = std::thread([&] { test.server->Shutdown(absl::Seconds(60)); });
  absl::SleepFor(absl::Milliseconds(100));
  EXPECT_FALSE(Submit(*test.stub, LongJobRequests()).ok()) << "no new jobs while draining";
  shutdown.join();
  test.server->Wait();
  running_client.join();
  queued_client.join();
  ASSERT_TRUE(running.status.ok()) << running.status.error_message();
  EXPECT_TRUE(running.have_result);
  EXPECT_EQ(running.result.iterations_sequential(), 300'000);
  EXPECT_EQ(running.mesh.coordinates_size(), wire.coordinates_size());
  EXPECT_EQ(queued.status.error_code(), grpc::StatusCode::CANCELLED);
  EXPECT_NE(queued.status.error_message().find("shutting down"), std::string::npos)
      << queued.status.error_message();
  ASSERT_FALSE(queued.events.empty());
  EXPECT_TRUE(queued.events.back().final());
}

TEST(JobsTest, ShutdownCancelsJobsStillRunningAfterTheGracePeriod) {
  TestServer test = StartTestServer();
  auto job = Submit(*test.stub, LongJobRequests());
  ASSERT_TRUE(job.ok());
  WaitForState(*test.stub, job->job_id(), v1::JOB_STATE_RUNNING);
  const absl::Time start = absl::Now();
  test.server->Shutdown(absl::Milliseconds(300));
  EXPECT_LT(absl::Now() - start, absl::Seconds(3));
  test.server->Shutdown(absl::Milliseconds(300));  // idempotent
  test.server->Wait();
}

}  // namespace
}  // namespace getme::server::testing
