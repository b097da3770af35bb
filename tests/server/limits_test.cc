// The server's resource limits (--max_message_bytes, --max_upload_bytes, --max_nodes,
// --max_queued_bytes, --max_job_time, --max_streams_per_client): each refusal has its exact status
// and a message naming the limit and its value.
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "getme_server/stream_limiter.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"
#include "server_test_support.h"

namespace getme::server::testing {
namespace {

using ::testing::HasSubstr;

v1::SmoothRequest HeaderOnly(const v1::MeshSize& expected) {
  v1::SmoothRequest request;
  *request.mutable_header()->mutable_expected_size() = expected;
  return request;
}

// The mesh split into chunks of `bytes` (as SmoothRequests), after a header without a size.
std::vector<v1::SmoothRequest> ChunkedRequests(const v1::Mesh& mesh, std::size_t bytes,
                                               const v1::SmoothingParameters& parameters = {}) {
  std::vector<v1::SmoothRequest> requests(1);
  *requests[0].mutable_header()->mutable_parameters() = parameters;
  for (v1::MeshChunk& chunk : SplitIntoChunks(mesh, bytes)) {
    v1::SmoothRequest request;
    *request.mutable_chunk() = std::move(chunk);
    requests.push_back(std::move(request));
  }
  return requests;
}

// Opens WatchJob on `job_id` and waits for its first event, so the server holds the stream.
struct OpenWatch {
  std::unique_ptr<grpc::ClientContext> context = std::make_unique<grpc::ClientContext>();
  std::unique_ptr<grpc::ClientReader<v1::ProgressEvent>> reader;
  bool got_event = false;
};
OpenWatch Watch(v1::Smoother::Stub& stub, const std::string& job_id) {
  OpenWatch watch;
  v1::WatchJobRequest request;
  request.set_job_id(job_id);
  watch.reader = stub.WatchJob(watch.context.get(), request);
  v1::ProgressEvent event;
  watch.got_event = watch.reader->Read(&event);
  return watch;
}

TEST(LimitsTest, MessageOverMaxMessageBytesIsRefusedByGrpc) {
  ServerOptions options = TestOptions();
  options.max_message_bytes = 64 << 10;
  TestServer test = StartTestServer(options);
  const v1::Mesh wire = ToWire(TetBlock(12, 0.3));  // ~10k elements, ~250 kB
  SmoothOutcome big = CallSmooth(*test.stub, ChunkedRequests(wire, 200 << 10));
  EXPECT_EQ(big.status.error_code(), grpc::StatusCode::RESOURCE_EXHAUSTED);
  EXPECT_THAT(big.status.error_message(), HasSubstr("larger than max"));
  EXPECT_THAT(big.status.error_message(), HasSubstr("65536"));
  // The same mesh in chunks below the limit is fine.
  SmoothOutcome chunked = CallSmooth(*test.stub, ChunkedRequests(wire, 32 << 10));
  EXPECT_TRUE(chunked.status.ok()) << chunked.status.error_message();
}

TEST(LimitsTest, UploadOverMaxUploadBytesIsRefusedAsChunksArrive) {
  ServerOptions options = TestOptions();
  options.max_upload_bytes = 50'000;
  TestServer test = StartTestServer(options);
  const v1::Mesh wire = ToWire(TetBlock(14, 0.3));
  const std::size_t chunk_bytes = 16 << 10;
  ASSERT_GT(wire.ByteSizeLong(), 3 * options.max_upload_bytes);
  SmoothOutcome outcome = CallSmooth(*test.stub, ChunkedRequests(wire, chunk_bytes));
  EXPECT_EQ(outcome.status.error_code(), grpc::StatusCode::RESOURCE_EXHAUSTED);
  const std::string& message = outcome.status.error_message();
  EXPECT_THAT(message, HasSubstr("more than the server's limit of 50000 bytes per job "
                                 "(--max_upload_bytes)"));
  // Refused at the first chunk past the limit, not after buffering the whole mesh: the message
  // names the bytes received, which stay within one chunk of the limit.
  const std::size_t passed = message.find("passed ");
  ASSERT_NE(passed, std::string::npos) << message;
  const std::int64_t received = std::stoll(message.substr(passed + 7));
  EXPECT_GT(received, options.max_upload_bytes);
  EXPECT_LE(received, options.max_upload_bytes + static_cast<std::int64_t>(chunk_bytes) + 64);
  v1::ListJobsResponse list;
  grpc::ClientContext context;
  ASSERT_TRUE(test.stub->ListJobs(&context, {}, &list).ok());
  EXPECT_EQ(list.jobs_size(), 0) << "a refused upload leaves no job";
}

TEST(LimitsTest, NodesOverMaxNodesAreRefusedBeforeAndDuringTheUpload) {
  ServerOptions options = TestOptions();
  options.max_nodes = 100;
  TestServer test = StartTestServer(options);
  v1::MeshSize declared;
  declared.set_nodes(1000);
  declared.set_tetrahedra(10);
  SmoothOutcome early = CallSmooth(*test.stub, {HeaderOnly(declared)});
  EXPECT_EQ(early.status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(early.status.error_message(),
            "expected_size declares 1000 nodes, more than the server's limit of 100 "
            "(--max_nodes)");

  const v1::Mesh wire = ToWire(TetBlock(6, 0.3));  // 343 nodes
  SmoothOutcome counted = CallSmooth(*test.stub, ChunkedRequests(wire, 1 << 20));
  EXPECT_EQ(counted.status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(counted.status.error_message(),
            "mesh has 343 nodes, more than the server's limit of 100 (--max_nodes)");
}

TEST(LimitsTest, ElementsDeclaredOverMaxElementsAreRefusedBeforeTheUpload) {
  ServerOptions options = TestOptions();
  options.max_elements = 50;
  TestServer test = StartTestServer(options);
  v1::MeshSize declared;
  declared.set_nodes(10);
  declared.set_tetrahedra(40);
  declared.set_hexahedra(20);
  SmoothOutcome outcome = CallSmooth(*test.stub, {HeaderOnly(declared)});
  EXPECT_EQ(outcome.status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_EQ(outcome.status.error_message(),
            "expected_size declares 60 elements, more than the server's limit of 50 "
            "(--max_elements)");
}

TEST(LimitsTest, QueuedBytesBudgetRefusesAJobUntilMemoryIsFreed) {
  const v1::Mesh wire = ToWire(TetBlock(6, 0.3));
  const auto requests = SmoothRequests(wire, LongRunningParameters());
  ServerOptions options = TestOptions();
  options.workers = 1;
  // One job fits, two do not.
  options.max_upload_bytes = static_cast<std::int64_t>(wire.ByteSizeLong() * 3 / 2);
  options.max_queued_bytes = options.max_upload_bytes;
  TestServer test = StartTestServer(options);
  absl::StatusOr<v1::Job> first = Submit(*test.stub, requests);
  ASSERT_TRUE(first.ok()) << first.status();
  absl::StatusOr<v1::Job> second = Submit(*test.stub, requests);
  EXPECT_EQ(second.status().code(), absl::StatusCode::kResourceExhausted);
  EXPECT_THAT(std::string(second.status().message()),
              HasSubstr(absl::StrCat("passes the server's limit of ", options.max_queued_bytes,
                                     " bytes (--max_queued_bytes); retry later")));
  grpc::ClientContext context;
  v1::CancelJobRequest cancel;
  cancel.set_job_id(first->job_id());
  v1::Job cancelled;
  ASSERT_TRUE(test.stub->CancelJob(&context, cancel, &cancelled).ok());
  WaitForState(*test.stub, first->job_id(), v1::JOB_STATE_CANCELLED, absl::Seconds(10));
  absl::StatusOr<v1::Job> third = Submit(*test.stub, requests);
  ASSERT_TRUE(third.ok()) << third.status();
  grpc::ClientContext cancel_context;
  cancel.set_job_id(third->job_id());
  test.stub->CancelJob(&cancel_context, cancel, &cancelled);
}

TEST(LimitsTest, JobOverMaxJobTimeFailsWithDeadlineExceededEverywhere) {
  ServerOptions options = TestOptions();
  options.max_job_time = absl::Milliseconds(300);
  TestServer test = StartTestServer(options);
  const auto requests = SmoothRequests(ToWire(TetBlock(6, 0.3)), LongRunningParameters());
  const std::string expected_tail =
      "ran longer than the server's limit of 300ms per job (--max_job_time)";

  // Smooth: the call ends with the job's status.
  const absl::Time start = absl::Now();
  SmoothOutcome smooth = CallSmooth(*test.stub, requests);
  EXPECT_LT(absl::Now() - start, absl::Seconds(10));
  EXPECT_EQ(smooth.status.error_code(), grpc::StatusCode::DEADLINE_EXCEEDED);
  EXPECT_THAT(smooth.status.error_message(), HasSubstr(expected_tail));
  ASSERT_FALSE(smooth.events.empty());
  EXPECT_TRUE(smooth.events.back().final());

  // SubmitJob + WatchJob: the watch sees the final event; GetJob tells the outcome.
  absl::StatusOr<v1::Job> submitted = Submit(*test.stub, requests);
  ASSERT_TRUE(submitted.ok()) << submitted.status();
  OpenWatch watch = Watch(*test.stub, submitted->job_id());
  v1::ProgressEvent event;
  bool final_seen = false;
  while (watch.reader->Read(&event)) final_seen = final_seen || event.final();
  EXPECT_TRUE(watch.reader->Finish().ok());
  EXPECT_TRUE(final_seen);
  const v1::Job job = GetJob(*test.stub, submitted->job_id());
  EXPECT_EQ(job.state(), v1::JOB_STATE_FAILED);
  EXPECT_EQ(job.error_code(), static_cast<int>(grpc::StatusCode::DEADLINE_EXCEEDED));
  EXPECT_THAT(job.error_message(), HasSubstr(expected_tail));
  EXPECT_GE(job.finished_unix_seconds() - job.started_unix_seconds(), 0.3);
}

TEST(LimitsTest, StreamsOverMaxStreamsPerClientAreRefusedUntilOneEnds) {
  ServerOptions options = TestOptions();
  options.max_streams_per_client = 2;
  TestServer test = StartTestServer(options);
  absl::StatusOr<v1::Job> job =
      Submit(*test.stub, SmoothRequests(ToWire(TetBlock(6, 0.3)), LongRunningParameters()));
  ASSERT_TRUE(job.ok()) << job.status();
  WaitForState(*test.stub, job->job_id(), v1::JOB_STATE_RUNNING);

  OpenWatch first = Watch(*test.stub, job->job_id());
  OpenWatch second = Watch(*test.stub, job->job_id());
  ASSERT_TRUE(first.got_event && second.got_event);
  OpenWatch third = Watch(*test.stub, job->job_id());
  EXPECT_FALSE(third.got_event);
  const grpc::Status refused = third.reader->Finish();
  EXPECT_EQ(refused.error_code(), grpc::StatusCode::RESOURCE_EXHAUSTED);
  EXPECT_THAT(refused.error_message(),
              HasSubstr("client 127.0.0.1 already has 2 open streaming calls"));
  EXPECT_THAT(refused.error_message(), HasSubstr("(--max_streams_per_client)"));
  // Unary calls are not streams: still served.
  EXPECT_EQ(GetJob(*test.stub, job->job_id()).state(), v1::JOB_STATE_RUNNING);

  first.context->TryCancel();
  first.reader->Finish();
  // The server frees the slot when its handler notices the cancel (within its poll interval).
  bool admitted = false;
  for (int attempt = 0; attempt < 100 && !admitted; ++attempt) {
    OpenWatch again = Watch(*test.stub, job->job_id());
    admitted = again.got_event;
    again.context->TryCancel();
    again.reader->Finish();
    if (!admitted) absl::SleepFor(absl::Milliseconds(20));
  }
  EXPECT_TRUE(admitted);
  second.context->TryCancel();
  second.reader->Finish();
  grpc::ClientContext context;
  v1::CancelJobRequest cancel;
  cancel.set_job_id(job->job_id());
  v1::Job cancelled;
  test.stub->CancelJob(&context, cancel, &cancelled);
}

TEST(LimitsTest, InconsistentLimitsAreRefusedAtStart) {
  ServerOptions options = TestOptions();
  options.max_upload_bytes = 1000;
  options.max_queued_bytes = 999;
  auto server = SmootherServer::Start(options);
  EXPECT_EQ(server.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(server.status().message(),
            "--max_queued_bytes = 999 is out of range: must be >= 1000 (--max_upload_bytes)");
  options = TestOptions();
  options.max_job_time = absl::ZeroDuration();
  EXPECT_EQ(SmootherServer::Start(options).status().message(),
            "--max_job_time = 0 must be positive");
  // A lease renewed every lease/3 must outlast a scheduling hiccup; checked before the store is
  // dialled, so no Redis is needed to see it refused.
  options = TestOptions();
  options.job_lease = absl::Milliseconds(99);
  options.job_store = "redis://127.0.0.1:1";
  EXPECT_EQ(SmootherServer::Start(options).status(),
            absl::InvalidArgumentError("--job_lease = 99ms must be at least 100ms"));
  options.job_lease = absl::Milliseconds(100);  // the least allowed: on to dialling the store
  EXPECT_EQ(SmootherServer::Start(options).status(),
            absl::UnavailableError("--job_store: redis: cannot connect to redis://127.0.0.1:1/0: "
                                   "Connection refused"));
  options = TestOptions();
  options.result_ttl = absl::ZeroDuration();
  EXPECT_EQ(SmootherServer::Start(options).status(),
            absl::InvalidArgumentError("--result_ttl = 0 must be positive"));
}

TEST(ClientHostTest, DropsThePortOfIpPeers) {
  EXPECT_EQ(ClientHost("ipv4:10.0.0.7:53012"), "10.0.0.7");
  EXPECT_EQ(ClientHost("ipv6:[::1]:53012"), "[::1]");
  EXPECT_EQ(ClientHost("unix:/run/getme.sock"), "unix:/run/getme.sock");
}

}  // namespace
}  // namespace getme::server::testing
