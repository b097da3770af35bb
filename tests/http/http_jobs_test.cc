// The JSON jobs API: the same jobs as gRPC, canonical JSON field names, and errors with exact
// HTTP statuses and codes.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "absl/strings/escaping.h"
#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "gmock/gmock.h"
#include "google/protobuf/struct.pb.h"
#include "google/protobuf/util/json_util.h"
#include "grpcpp/client_context.h"
#include "gtest/gtest.h"
#include "http_test_support.h"

namespace getme::server::testing {
namespace {

using ::testing::HasSubstr;

v1::SmoothingParameters Simultaneous() {
  v1::SmoothingParameters parameters;
  parameters.set_method(v1::METHOD_SIMULTANEOUS);
  return parameters;
}

// {"code": ..., "message": ...} with the expected code; returns the message.
std::string ExpectError(const HttpReply& reply, int status, const std::string& code) {
  EXPECT_EQ(reply.status, status) << reply.body;
  EXPECT_EQ(reply.content_type, "application/json");
  EXPECT_THAT(reply.body, HasSubstr(absl::StrCat("\"code\": \"", code, "\"")));
  const std::size_t at = reply.body.find("\"message\": \"");
  return at == std::string::npos ? "" : reply.body.substr(at);
}

TEST(HttpJobsTest, HealthAndReadinessAnswerOk) {
  HttpTestServer test = StartHttpTestServer();
  EXPECT_EQ(HttpGet(*test.http, "/healthz").status, 200);
  EXPECT_EQ(HttpGet(*test.http, "/readyz").status, 200);
}

TEST(HttpJobsTest, JobFromGrpcReadsTheSameOverHttpWithCanonicalJsonNames) {
  HttpTestServer test = StartHttpTestServer();
  auto job = Submit(*test.grpc.stub, SmoothRequests(ToWire(SmallHybridMesh()), Simultaneous()));
  ASSERT_TRUE(job.ok()) << job.status();
  const v1::Job done = WaitForState(*test.grpc.stub, job->job_id(), v1::JOB_STATE_SUCCEEDED);
  // A job seen final carries its final event: the state and that event change together.
  EXPECT_TRUE(done.latest_progress().final()) << done.latest_progress().DebugString();

  const HttpReply reply = HttpGet(*test.http, "/v1/jobs/" + job->job_id());
  ASSERT_EQ(reply.status, 200) << reply.body;
  EXPECT_EQ(reply.content_type, "application/json");
  // lowerCamelCase per the proto3 JSON mapping, enums by name, 64-bit integers as strings.
  for (const char* field : {"\"jobId\":", "\"latestProgress\":", "\"resultAvailable\":true",
                            "\"state\":\"JOB_STATE_SUCCEEDED\"",
                            "\"qMin\":", "\"phaseDone\":", "\"createdUnixSeconds\":"}) {
    EXPECT_THAT(reply.body, HasSubstr(field));
  }
  EXPECT_THAT(reply.body, HasSubstr(absl::StrCat("\"elements\":\"", done.elements(), "\"")));
  EXPECT_THAT(reply.body, ::testing::Not(HasSubstr("job_id")));
  const v1::Job over_http = ParseJson<v1::Job>(reply.body);
  EXPECT_EQ(over_http.job_id(), done.job_id());
  EXPECT_EQ(over_http.latest_progress().sequence(), done.latest_progress().sequence());
  EXPECT_EQ(over_http.latest_progress().q_min(), done.latest_progress().q_min());

  const auto list = ParseJson<v1::ListJobsResponse>(HttpGet(*test.http, "/v1/jobs").body);
  ASSERT_EQ(list.jobs_size(), 1);
  EXPECT_EQ(list.jobs(0).job_id(), job->job_id());
}

TEST(HttpJobsTest, PostedJobSmoothsLikeTheGrpcSmoothCall) {
  HttpTestServer test = StartHttpTestServer();
  const v1::Mesh wire = ToWire(SmallHybridMesh());
  const SmoothOutcome reference = CallSmooth(*test.grpc.stub, SmoothRequests(wire, Simultaneous()));
  ASSERT_TRUE(reference.status.ok()) << reference.status.error_message();

  const HttpReply posted = HttpPost(*test.http, "/v1/jobs", CreateJobJson(wire, Simultaneous()));
  ASSERT_EQ(posted.status, 200) << posted.body;
  const v1::Job job = ParseJson<v1::Job>(posted.body);
  EXPECT_EQ(job.method(), v1::METHOD_SIMULTANEOUS);
  EXPECT_EQ(job.elements(), static_cast<std::uint64_t>(reference.result.after().elements()));
  WaitForState(*test.grpc.stub, job.job_id(), v1::JOB_STATE_SUCCEEDED);

  const HttpReply report = HttpGet(*test.http, "/v1/jobs/" + job.job_id() + "/report");
  ASSERT_EQ(report.status, 200) << report.body;
  const auto summary = ParseJson<v1::SmoothResult>(report.body);
  EXPECT_EQ(summary.after().q_min(), reference.result.after().q_min());
  EXPECT_EQ(summary.after().q_mean(), reference.result.after().q_mean());
  EXPECT_EQ(summary.iterations_simultaneous(), reference.result.iterations_simultaneous());
  ASSERT_EQ(summary.after().histogram_size(), 20);
  // The report does not consume the result: gRPC GetResult still delivers the mesh.
  const SmoothOutcome fetched = CallGetResult(*test.grpc.stub, job.job_id());
  ASSERT_TRUE(fetched.status.ok()) << fetched.status.error_message();
  EXPECT_EQ(fetched.mesh.coordinates(0), reference.mesh.coordinates(0));
  EXPECT_EQ(HttpGet(*test.http, "/v1/jobs/" + job.job_id() + "/report").status, 200);
}

TEST(HttpJobsTest, CancelEndsARunningJobAsCancelled) {
  HttpTestServer test = StartHttpTestServer();
  const HttpReply posted = HttpPost(
      *test.http, "/v1/jobs", CreateJobJson(ToWire(TetBlock(4, 0.3)), LongRunningParameters()));
  ASSERT_EQ(posted.status, 200) << posted.body;
  const std::string id = ParseJson<v1::Job>(posted.body).job_id();
  WaitForState(*test.grpc.stub, id, v1::JOB_STATE_RUNNING);

  const HttpReply cancelled = HttpPost(*test.http, "/v1/jobs/" + id + ":cancel", "");
  ASSERT_EQ(cancelled.status, 200) << cancelled.body;
  EXPECT_EQ(WaitForState(*test.grpc.stub, id, v1::JOB_STATE_CANCELLED).state(),
            v1::JOB_STATE_CANCELLED);
  const auto job = ParseJson<v1::Job>(HttpGet(*test.http, "/v1/jobs/" + id).body);
  EXPECT_EQ(job.state(), v1::JOB_STATE_CANCELLED);
  EXPECT_EQ(job.error_code(), static_cast<int>(grpc::StatusCode::CANCELLED));
  ExpectError(HttpGet(*test.http, "/v1/jobs/" + id + "/report"), 499, "CANCELLED");
}

TEST(HttpJobsTest, ErrorsCarryTheCanonicalCodeAndItsHttpStatus) {
  ServerOptions options = TestOptions();
  options.workers = 1;
  options.max_queued_jobs = 1;
  HttpTestServer test = StartHttpTestServer(options);

  EXPECT_THAT(ExpectError(HttpGet(*test.http, "/v1/jobs/feedbeef0000"), 404, "NOT_FOUND"),
              HasSubstr("feedbeef0000"));
  ExpectError(HttpPost(*test.http, "/v1/jobs/feedbeef0000:cancel", ""), 404, "NOT_FOUND");
  ExpectError(HttpGet(*test.http, "/v1/jobs/feedbeef0000/events"), 404, "NOT_FOUND");
  ExpectError(HttpGet(*test.http, "/no/such/route"), 404, "NOT_FOUND");

  // Bad JSON names the field (protobuf's JSON parser reports its path).
  EXPECT_THAT(ExpectError(HttpPost(*test.http, "/v1/jobs", R"({"mesh": {"coordinatez": [1]}})"),
                          400, "INVALID_ARGUMENT"),
              HasSubstr("coordinatez"));
  EXPECT_THAT(
      ExpectError(HttpPost(*test.http, "/v1/jobs", R"({"mesh": {"coordinates": [0, "x"]}})"), 400,
                  "INVALID_ARGUMENT"),
      HasSubstr("mesh.coordinates[1]"));
  EXPECT_THAT(
      ExpectError(HttpPost(*test.http, "/v1/jobs", R"({"mesh": )"), 400, "INVALID_ARGUMENT"),
      HasSubstr("bad JSON"));
  // A well-formed document with a bad mesh: the same validation as gRPC.
  EXPECT_THAT(ExpectError(HttpPost(*test.http, "/v1/jobs",
                                   R"({"mesh": {"coordinates": [0, 0, 0, 1, 0, 0, 0, 1, 0],
                                                "tetrahedra": [0, 1, 2, 7]}})"),
                          400, "INVALID_ARGUMENT"),
              HasSubstr("7"));
  v1::SmoothingParameters bad_rho;
  bad_rho.set_simultaneous_rho(5);
  EXPECT_THAT(ExpectError(HttpPost(*test.http, "/v1/jobs",
                                   CreateJobJson(ToWire(TetBlock(2, 0.1)), bad_rho)),
                          400, "INVALID_ARGUMENT"),
              HasSubstr("simultaneous_rho"));

  // Queue full: one job runs, one waits, the next is refused at once.
  const std::string long_job = CreateJobJson(ToWire(TetBlock(4, 0.3)), LongRunningParameters());
  const auto running = ParseJson<v1::Job>(HttpPost(*test.http, "/v1/jobs", long_job).body);
  WaitForState(*test.grpc.stub, running.job_id(), v1::JOB_STATE_RUNNING);
  ASSERT_EQ(HttpPost(*test.http, "/v1/jobs", long_job).status, 200);
  EXPECT_THAT(ExpectError(HttpPost(*test.http, "/v1/jobs", long_job), 429, "RESOURCE_EXHAUSTED"),
              HasSubstr("--max_queued_jobs"));

  // Too big for JSON: 413, pointing to gRPC.
  const std::string huge(9 << 20, ' ');
  EXPECT_THAT(ExpectError(HttpPost(*test.http, "/v1/jobs", huge), 413, "RESOURCE_EXHAUSTED"),
              HasSubstr("gRPC"));
  test.grpc.server->Shutdown(absl::ZeroDuration());
}

// Found by fuzz/http_job_fuzzer.cc: protobuf's parse error quotes the body's bytes, and bytes that
// are not UTF-8 made the error body invalid JSON. Every input in tests/data/fuzz-regressions/http
// is refused with a JSON error body that names the code.
TEST(HttpJobsTest, ErrorBodiesStayJsonWhenTheRequestIsNotUtf8) {
  HttpTestServer test = StartHttpTestServer(TestOptions());
  std::vector<std::string> bodies = {"\xff", "{\"mesh\": \"\xc3\x28\"}", "{\"x\xed\xa0\x80\": 1}"};
  for (const auto& entry : std::filesystem::directory_iterator(std::string(GETME_TEST_DATA) +
                                                               "/fuzz-regressions/http")) {
    std::ifstream file(entry.path(), std::ios::binary);
    bodies.emplace_back(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
  }
  ASSERT_GT(bodies.size(), 3u) << "no regression inputs found";
  for (const std::string& body : bodies) {
    SCOPED_TRACE(absl::CHexEscape(body));
    const HttpReply reply = HttpPost(*test.http, "/v1/jobs", body);
    ExpectError(reply, 400, "INVALID_ARGUMENT");
    google::protobuf::Struct parsed;
    ASSERT_TRUE(google::protobuf::util::JsonStringToMessage(reply.body, &parsed).ok())
        << reply.body;
    EXPECT_EQ(parsed.fields().at("code").string_value(), "INVALID_ARGUMENT");
    EXPECT_THAT(parsed.fields().at("message").string_value(), HasSubstr("bad JSON"));
  }
}

TEST(HttpJobsTest, DrainingServerIsNotReadyAndRefusesJobsWithUnavailable) {
  HttpTestServer test = StartHttpTestServer();
  const HttpReply posted = HttpPost(
      *test.http, "/v1/jobs", CreateJobJson(ToWire(TetBlock(4, 0.3)), LongRunningParameters()));
  const std::string id = ParseJson<v1::Job>(posted.body).job_id();
  WaitForState(*test.grpc.stub, id, v1::JOB_STATE_RUNNING);

  std::thread shutdown([&] { test.grpc.server->Shutdown(absl::Seconds(30)); });
  HttpReply ready;
  for (int i = 0; i < 500; ++i) {
    ready = HttpGet(*test.http, "/readyz");
    if (ready.status != 200) break;
    absl::SleepFor(absl::Milliseconds(10));
  }
  ExpectError(ready, 503, "UNAVAILABLE");
  EXPECT_EQ(HttpGet(*test.http, "/healthz").status, 200) << "alive while draining";
  ExpectError(HttpPost(*test.http, "/v1/jobs", CreateJobJson(ToWire(TetBlock(2, 0.1)), {})), 503,
              "UNAVAILABLE");
  // The running job may finish; cancelling it lets the drain end now.
  EXPECT_EQ(HttpPost(*test.http, "/v1/jobs/" + id + ":cancel", "").status, 200);
  shutdown.join();
  EXPECT_EQ(HttpGet(*test.http, "/healthz").status, -1) << "HTTP stops with the server";
}

}  // namespace
}  // namespace getme::server::testing
