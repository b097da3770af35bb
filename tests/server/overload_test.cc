// Overload and faulty clients against an in-process server: more jobs than queue slots from many
// clients at once, clients that vanish mid-upload or mid-download, and a watcher that never reads.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "getme/mesh/mesh_quality.h"
#include "getme/parallel/thread_pool.h"
#include "gmock/gmock.h"
#include "grpcpp/create_channel.h"
#include "grpcpp/security/credentials.h"
#include "gtest/gtest.h"
#include "server_test_support.h"

namespace getme::server::testing {
namespace {

using ::testing::HasSubstr;

std::shared_ptr<grpc::Channel> NewChannel(const TestServer& test,
                                          grpc::ChannelArguments arguments = {}) {
  // A channel per client, like separate processes (a shared one would share one connection).
  arguments.SetInt("getme.test.unique", reinterpret_cast<std::intptr_t>(&arguments) & 0x7fffffff);
  return grpc::CreateCustomChannel(absl::StrCat("127.0.0.1:", test.server->port()),
                                   grpc::InsecureChannelCredentials(), arguments);
}

// A finite job of a few hundred milliseconds: long enough that 16 clients at once overrun 2
// workers and 4 queue slots.
v1::SmoothingParameters FiniteParameters() {
  v1::SmoothingParameters parameters;
  parameters.set_method(v1::METHOD_SEQUENTIAL);
  parameters.set_sequential_max_iterations(20'000);
  parameters.set_sequential_stall_iterations(1'000'000);
  parameters.set_sequential_improvement_tolerance(0.0);
  return parameters;
}

// The returned mesh is valid and its reported quality is what the coordinates give.
void ExpectValidResult(const v1::Mesh& input, const v1::SmoothResult& result,
                       const v1::Mesh& returned) {
  ASSERT_EQ(returned.coordinates_size(), input.coordinates_size());
  v1::Mesh smoothed = input;
  *smoothed.mutable_coordinates() = returned.coordinates();
  ThreadPool pool(1);
  const MeshQuality quality = EvaluateMeshQuality(FromWire(smoothed), pool);
  EXPECT_EQ(quality.invalid, 0);
  EXPECT_EQ(quality.q_min, result.after().q_min());
  EXPECT_GT(result.after().q_min(), result.before().q_min());
}

TEST(OverloadTest, ManyClientsOverrunningTheQueueLoseAndDuplicateNoJob) {
  ServerOptions options = TestOptions();
  options.workers = 2;
  options.max_queued_jobs = 4;
  options.progress_interval = absl::Milliseconds(20);
  // Long enough that a client thread descheduled between the final event and GetResult on a
  // loaded machine still finds its result; short enough to watch the registry forget.
  options.result_ttl = absl::Seconds(2);
  TestServer test = StartTestServer(options);
  const v1::Mesh wire = ToWire(TetBlock(6, 0.3));
  const auto requests = SmoothRequests(wire, FiniteParameters());

  constexpr int kClients = 16;
  constexpr int kJobsPerClient = 3;
  std::mutex mutex;
  std::vector<std::string> completed;  // job ids
  int refused = 0;
  std::vector<std::string> unexpected;
  std::atomic<int> ready{0};
  std::vector<std::thread> clients;
  for (int c = 0; c < kClients; ++c) {
    clients.emplace_back([&, c] {
      // Connected before the race starts: this test is about the queue. Sixteen connects at once
      // on a loaded machine once had one fail at once ("failed to connect to all addresses"),
      // and a channel's first call does not wait for its reconnect; WaitForConnected does.
      std::shared_ptr<grpc::Channel> channel = NewChannel(test);
      EXPECT_TRUE(
          channel->WaitForConnected(std::chrono::system_clock::now() + std::chrono::seconds(30)));
      auto stub = v1::Smoother::NewStub(channel);
      ++ready;
      while (ready.load() < kClients) std::this_thread::yield();  // all start at once
      for (int j = 0; j < kJobsPerClient; ++j) {
        SmoothOutcome outcome;
        if (c % 2 == 0) {
          outcome = CallSmooth(*stub, requests);
        } else {
          // Half the clients queue the job, watch it, then fetch the result.
          absl::StatusOr<v1::Job> job = Submit(*stub, requests);
          if (!job.ok()) {
            outcome.status = grpc::Status(static_cast<grpc::StatusCode>(job.status().code()),
                                          std::string(job.status().message()));
          } else {
            grpc::ClientContext context;
            v1::WatchJobRequest watch;
            watch.set_job_id(job->job_id());
            auto reader = stub->WatchJob(&context, watch);
            v1::ProgressEvent event;
            while (reader->Read(&event)) {
            }
            EXPECT_TRUE(reader->Finish().ok());
            outcome = CallGetResult(*stub, job->job_id());
          }
        }
        std::lock_guard lock(mutex);
        if (outcome.status.ok()) {
          ExpectValidResult(wire, outcome.result, outcome.mesh);
          completed.push_back(outcome.result.job_id());
        } else if (outcome.status.error_code() == grpc::StatusCode::RESOURCE_EXHAUSTED &&
                   outcome.status.error_message().find("--max_queued_jobs") != std::string::npos) {
          ++refused;
        } else {
          unexpected.push_back(
              absl::StrCat(outcome.status.error_code(), ": ", outcome.status.error_message()));
        }
      }
    });
  }
  for (std::thread& client : clients) client.join();

  EXPECT_THAT(unexpected, ::testing::IsEmpty());
  EXPECT_EQ(static_cast<int>(completed.size()) + refused, kClients * kJobsPerClient);
  EXPECT_GE(completed.size(), 6u) << "2 running + 4 queued always fit";
  EXPECT_GT(refused, 0) << "16 clients at once must overrun 2 workers + 4 queue slots";
  const std::set<std::string> unique(completed.begin(), completed.end());
  EXPECT_EQ(unique.size(), completed.size()) << "a job id delivered twice";
  std::printf("overload: %zu jobs completed, %d refused with RESOURCE_EXHAUSTED\n",
              completed.size(), refused);

  // The registry knows exactly the completed jobs, all final, and nothing is queued.
  std::set<std::string> listed;
  for (const v1::Job& job : ListedJobs(*test.stub)) {
    EXPECT_EQ(job.state(), v1::JOB_STATE_SUCCEEDED) << job.DebugString();
    listed.insert(job.job_id());
  }
  // Refused uploads left no job behind (the earliest completed ones may already be forgotten:
  // the test's TTL is short), and then the registry empties.
  EXPECT_TRUE(std::includes(unique.begin(), unique.end(), listed.begin(), listed.end()));
  bool empty = false;
  const absl::Time deadline = absl::Now() + 2 * options.result_ttl + absl::Seconds(20);
  while (!empty && absl::Now() < deadline) {
    empty = ListedJobs(*test.stub).empty();
    if (!empty) absl::SleepFor(absl::Milliseconds(20));
  }
  EXPECT_TRUE(empty) << "finished jobs are forgotten after twice --result_ttl";
}

TEST(OverloadTest, ClientVanishingMidUploadLeavesNoJobAndNoStreamBehind) {
  ServerOptions options = TestOptions();
  options.max_streams_per_client = 1;  // a leaked stream slot would refuse the next call
  TestServer test = StartTestServer(options);
  const v1::Mesh wire = ToWire(TetBlock(12, 0.3));
  const auto requests = SmoothRequests(wire, FiniteParameters());
  std::vector<v1::SmoothRequest> chunked(1, requests[0]);
  for (v1::MeshChunk& chunk : SplitIntoChunks(wire, 16 << 10)) {
    *chunked.emplace_back().mutable_chunk() = std::move(chunk);
  }
  ASSERT_GT(chunked.size(), 6u);

  // Half an upload, then the client cancels: CANCELLED. The server frees the previous round's
  // stream slot when its handler sees that cancel, which may come after the next call arrives;
  // that call is then refused (RESOURCE_EXHAUSTED naming the limit) and the round is retried.
  auto upload_half_then_vanish = [&] {
    grpc::ClientContext context;
    v1::Job job;
    auto writer = test.stub->SubmitJob(&context, &job);
    for (std::size_t i = 0; i < chunked.size() / 2; ++i) {
      if (!writer->Write(chunked[i])) break;  // refused: Finish tells why
    }
    context.TryCancel();
    return writer->Finish();
  };
  for (int round = 0; round < 5; ++round) {
    grpc::Status status = upload_half_then_vanish();
    for (int retry = 0; retry < 100 && status.error_code() == grpc::StatusCode::RESOURCE_EXHAUSTED;
         ++retry) {
      EXPECT_THAT(status.error_message(), HasSubstr("--max_streams_per_client"));
      absl::SleepFor(absl::Milliseconds(20));
      status = upload_half_then_vanish();
    }
    EXPECT_EQ(status.error_code(), grpc::StatusCode::CANCELLED) << status.error_message();
  }
  EXPECT_EQ(ListedJobs(*test.stub).size(), 0u);
  // The server frees a stream when its handler sees the cancel: poll, then a whole job runs.
  SmoothOutcome after;
  for (int attempt = 0; attempt < 100; ++attempt) {
    after = CallSmooth(*test.stub, requests);
    if (after.status.error_code() != grpc::StatusCode::RESOURCE_EXHAUSTED) break;
    absl::SleepFor(absl::Milliseconds(20));
  }
  ASSERT_TRUE(after.status.ok()) << after.status.error_message();
  ExpectValidResult(wire, after.result, after.mesh);
  EXPECT_EQ(ListedJobs(*test.stub).size(), 1u);
}

TEST(OverloadTest, ClientVanishingMidDownloadLeavesTheResultFetchable) {
  TestServer test = StartTestServer();
  const v1::Mesh wire = ToWire(TetBlock(16, 0.3));  // a result of ~700 kB
  v1::ResultOptions result_options;
  result_options.set_nodes_per_chunk(200);
  absl::StatusOr<v1::Job> job =
      Submit(*test.stub, SmoothRequests(wire, FiniteParameters(), result_options));
  ASSERT_TRUE(job.ok()) << job.status();
  WaitForState(*test.stub, job->job_id(), v1::JOB_STATE_SUCCEEDED);

  {
    // A small receive window (no automatic growth): the server cannot push the whole result
    // into buffers before the cancel arrives.
    grpc::ChannelArguments arguments;
    arguments.SetInt(GRPC_ARG_HTTP2_STREAM_LOOKAHEAD_BYTES, 16 << 10);
    arguments.SetInt(GRPC_ARG_HTTP2_BDP_PROBE, 0);
    auto stub = v1::Smoother::NewStub(NewChannel(test, arguments));
    grpc::ClientContext context;
    v1::GetResultRequest request;
    request.set_job_id(job->job_id());
    auto reader = stub->GetResult(&context, request);
    v1::SmoothResponse first;
    ASSERT_TRUE(reader->Read(&first));
    ASSERT_TRUE(first.has_result());
    context.TryCancel();
    EXPECT_EQ(reader->Finish().error_code(), grpc::StatusCode::CANCELLED);
  }
  // The server gives the result back to the job when its write fails.
  bool available = false;
  for (int attempt = 0; attempt < 200 && !available; ++attempt) {
    available = GetJob(*test.stub, job->job_id()).result_available();
    if (!available) absl::SleepFor(absl::Milliseconds(10));
  }
  ASSERT_TRUE(available);
  SmoothOutcome again = CallGetResult(*test.stub, job->job_id());
  ASSERT_TRUE(again.status.ok()) << again.status.error_message();
  EXPECT_GT(again.chunks, 1);
  ExpectValidResult(wire, again.result, again.mesh);
  EXPECT_EQ(again.mesh.tetrahedra_size(), wire.tetrahedra_size());
  // Fetched whole: now it is gone.
  EXPECT_EQ(CallGetResult(*test.stub, job->job_id()).status.error_code(),
            grpc::StatusCode::NOT_FOUND);
}

TEST(OverloadTest, WatcherThatNeverReadsHoldsUpNeitherTheJobNorOtherWatchers) {
  TestServer test = StartTestServer();  // every progress event forwarded
  v1::SmoothingParameters parameters = FiniteParameters();
  parameters.set_sequential_max_iterations(100'000);
  parameters.set_sequential_cycle(20);  // an event every 20 picks: thousands of events
  const v1::Mesh wire = ToWire(TetBlock(6, 0.3));

  // Reference: the same job with nobody stalling.
  const absl::Time reference_start = absl::Now();
  SmoothOutcome reference = CallSmooth(*test.stub, SmoothRequests(wire, parameters));
  ASSERT_TRUE(reference.status.ok()) << reference.status.error_message();
  const absl::Duration reference_time = absl::Now() - reference_start;
  ASSERT_GT(reference.events.size(), 2000u);

  absl::StatusOr<v1::Job> job = Submit(*test.stub, SmoothRequests(wire, parameters));
  ASSERT_TRUE(job.ok()) << job.status();
  const absl::Time start = absl::Now();
  grpc::ChannelArguments small_window;
  small_window.SetInt(GRPC_ARG_HTTP2_STREAM_LOOKAHEAD_BYTES, 4 << 10);
  small_window.SetInt(GRPC_ARG_HTTP2_BDP_PROBE, 0);
  auto stalled_stub = v1::Smoother::NewStub(NewChannel(test, small_window));
  grpc::ClientContext stalled_context;
  v1::WatchJobRequest watch;
  watch.set_job_id(job->job_id());
  auto stalled = stalled_stub->WatchJob(&stalled_context, watch);  // never read

  grpc::ClientContext context;
  auto reader = test.stub->WatchJob(&context, watch);
  std::vector<v1::ProgressEvent> events;
  v1::ProgressEvent event;
  while (reader->Read(&event)) events.push_back(event);
  EXPECT_TRUE(reader->Finish().ok());
  const v1::Job done = WaitForState(*test.stub, job->job_id(), v1::JOB_STATE_SUCCEEDED);
  const absl::Duration elapsed = absl::Now() - start;
  ASSERT_FALSE(events.empty());
  EXPECT_TRUE(events.back().final());
  for (std::size_t i = 1; i < events.size(); ++i) {
    EXPECT_GT(events[i].sequence(), events[i - 1].sequence());
  }
  // The reading watcher got nearly every event published after it attached (a reader that falls
  // behind by thousands loses its oldest intermediate ones, not phase ends): the stalled one
  // slowed nobody down. Counted from its first event, not against the reference: the job starts
  // as soon as it is submitted, and on a loaded machine the reader attaches some events later.
  const std::uint64_t published = events.back().sequence() - events.front().sequence() + 1;
  EXPECT_GE(published, 1000u) << "the reader attached too late to tell anything";
  EXPECT_GE(events.size(), published * 9 / 10);
  auto phase_ends = [](const std::vector<v1::ProgressEvent>& list) {
    return std::count_if(list.begin(), list.end(), [](const auto& e) { return e.phase_done(); });
  };
  EXPECT_EQ(phase_ends(events), phase_ends(reference.events));
  // Generous: a blocked job would not finish at all.
  EXPECT_LT(elapsed, 5 * reference_time + absl::Seconds(5));
  std::printf("slow watcher: job ran %s (without: %s), the reading watcher got %zu events\n",
              absl::FormatDuration(elapsed).c_str(), absl::FormatDuration(reference_time).c_str(),
              events.size());
  EXPECT_EQ(done.state(), v1::JOB_STATE_SUCCEEDED);
  stalled_context.TryCancel();
  stalled->Finish();
}

}  // namespace
}  // namespace getme::server::testing
