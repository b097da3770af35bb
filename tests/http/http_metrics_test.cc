// GET /metrics: Prometheus text format 0.0.4 whose numbers follow what the server did.
#include <map>
#include <regex>
#include <string>

#include "absl/strings/numbers.h"
#include "absl/strings/str_split.h"
#include "gmock/gmock.h"
#include "grpcpp/client_context.h"
#include "gtest/gtest.h"
#include "http_test_support.h"

namespace getme::server::testing {
namespace {

// Every sample line "name{labels} value" by "name{labels}"; fails the test on a line that is
// neither a sample nor a # HELP / # TYPE comment, or a sample without a TYPE before it.
std::map<std::string, double> ParseMetrics(const std::string& text) {
  const std::regex sample(
      R"re(([a-zA-Z_:][a-zA-Z0-9_:]*)(\{([a-zA-Z_][a-zA-Z0-9_]*="([^"\\]|\\.)*",?)*\})? (\S+))re");
  const std::regex type(R"(# TYPE ([a-zA-Z_:][a-zA-Z0-9_:]*) (counter|gauge|histogram))");
  std::map<std::string, double> samples;
  std::string typed;
  for (absl::string_view view : absl::StrSplit(text, '\n', absl::SkipEmpty())) {
    const std::string line(view);
    std::smatch match;
    if (std::regex_match(line, match, type)) {
      typed = match[1];
    } else if (line.starts_with("# HELP ")) {
      continue;
    } else if (std::regex_match(line, match, sample)) {
      EXPECT_TRUE(match[1].str().starts_with(typed)) << line << " has no # TYPE";
      double value = 0;
      EXPECT_TRUE(absl::SimpleAtod(match[5].str(), &value)) << line;
      samples[match[1].str() + match[2].str()] = value;
    } else {
      ADD_FAILURE() << "not Prometheus text: " << line;
    }
  }
  return samples;
}

std::map<std::string, double> Scrape(httplib::Client& client) {
  const HttpReply reply = HttpGet(client, "/metrics");
  EXPECT_EQ(reply.status, 200);
  EXPECT_EQ(reply.content_type, "text/plain; version=0.0.4");
  return ParseMetrics(reply.body);
}

TEST(HttpMetricsTest, CountersFollowRpcsJobsAndWork) {
  ServerOptions options = TestOptions();
  options.workers = 3;
  HttpTestServer test = StartHttpTestServer(options);
  const auto before = Scrape(*test.http);
  EXPECT_EQ(before.at("getme_workers"), 3);
  EXPECT_EQ(before.at("getme_ready"), 1);
  EXPECT_EQ(before.at("getme_element_iterations_total"), 0);

  {
    grpc::ClientContext context;
    v1::GetJobRequest request;
    request.set_job_id("nope");
    v1::Job job;
    EXPECT_EQ(test.grpc.stub->GetJob(&context, request, &job).error_code(),
              grpc::StatusCode::NOT_FOUND);
  }
  v1::SmoothingParameters parameters;
  parameters.set_method(v1::METHOD_SIMULTANEOUS);
  const SmoothOutcome smoothed =
      CallSmooth(*test.grpc.stub, SmoothRequests(ToWire(SmallHybridMesh()), parameters));
  ASSERT_TRUE(smoothed.status.ok());

  // A long job, running while we scrape, then cancelled.
  auto running =
      Submit(*test.grpc.stub, SmoothRequests(ToWire(TetBlock(4, 0.3)), LongRunningParameters()));
  ASSERT_TRUE(running.ok());
  WaitForState(*test.grpc.stub, running->job_id(), v1::JOB_STATE_RUNNING);
  absl::SleepFor(absl::Milliseconds(200));
  auto during = Scrape(*test.http);
  EXPECT_EQ(during.at("getme_active_workers"), 1);
  EXPECT_EQ(during.at(R"(getme_jobs{state="running"})"), 1);
  EXPECT_EQ(during.at(R"(getme_jobs{state="succeeded"})"), 1);
  EXPECT_GT(during.at("getme_element_iterations_per_second"), 0);
  EXPECT_EQ(during.at(R"(getme_rpcs_total{method="/getme.v1.Smoother/GetJob",code="NOT_FOUND"})"),
            1);
  EXPECT_EQ(during.at(R"(getme_rpcs_total{method="/getme.v1.Smoother/Smooth",code="OK"})"), 1);
  EXPECT_EQ(during.at(R"(getme_jobs_finished_total{state="succeeded"})"), 1);
  // The finished simultaneous job transformed every element once per iteration.
  EXPECT_GE(during.at("getme_element_iterations_total"),
            static_cast<double>(smoothed.result.after().elements() *
                                smoothed.result.iterations_simultaneous()));

  ASSERT_EQ(HttpPost(*test.http, "/v1/jobs/" + running->job_id() + ":cancel", "").status, 200);
  WaitForState(*test.grpc.stub, running->job_id(), v1::JOB_STATE_CANCELLED);
  const auto after = Scrape(*test.http);
  EXPECT_EQ(after.at("getme_active_workers"), 0);
  EXPECT_EQ(after.at(R"(getme_jobs_finished_total{state="cancelled"})"), 1);
  EXPECT_EQ(after.at("getme_job_duration_seconds_count"), 2);
  EXPECT_EQ(after.at(R"(getme_job_duration_seconds_bucket{le="+Inf"})"), 2);
  EXPECT_LE(after.at(R"(getme_job_duration_seconds_bucket{le="0.1"})"), 2);
  EXPECT_GT(after.at("getme_job_duration_seconds_sum"), 0.2);
  EXPECT_GT(after.at("getme_element_iterations_total"),
            during.at("getme_element_iterations_total"));
  EXPECT_EQ(after.at(R"(getme_http_requests_total{route="/v1/jobs/{id}:cancel",status="200"})"), 1);
  EXPECT_EQ(after.at(R"(getme_http_requests_total{route="/metrics",status="200"})"), 2);
}

TEST(HttpMetricsTest, ElementIterationsOfASimultaneousJobAreElementsTimesIterations) {
  HttpTestServer test = StartHttpTestServer();
  v1::SmoothingParameters parameters;
  parameters.set_method(v1::METHOD_SIMULTANEOUS);
  const SmoothOutcome smoothed =
      CallSmooth(*test.grpc.stub, SmoothRequests(ToWire(SmallHybridMesh()), parameters));
  ASSERT_TRUE(smoothed.status.ok());
  ASSERT_EQ(smoothed.result.iterations_untangle(), 0);
  EXPECT_EQ(Scrape(*test.http).at("getme_element_iterations_total"),
            static_cast<double>(smoothed.result.after().elements() *
                                smoothed.result.iterations_simultaneous()));
}

}  // namespace
}  // namespace getme::server::testing
