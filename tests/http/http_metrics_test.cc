// GET /metrics: Prometheus text format 0.0.4 whose numbers follow what the server did.
#include <unistd.h>

#include <cstring>
#include <map>
#include <memory>
#include <string>

#include "getme_server/process_memory.h"
#include "gmock/gmock.h"
#include "grpcpp/client_context.h"
#include "gtest/gtest.h"
#include "http_test_support.h"
#include "server_process.h"

namespace getme::server::testing {
namespace {

TEST(HttpMetricsTest, CountersFollowRpcsJobsAndWork) {
  ServerOptions options = TestOptions();
  options.workers = 3;
  HttpTestServer test = StartHttpTestServer(options);
  const auto before = ScrapeMetrics(*test.http);
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
  absl::SleepFor(absl::Milliseconds(200));  // the cancelled job's duration is over 0.2 s
  WaitForProgress(*test.grpc.stub, running->job_id());  // its rate has something to count
  auto during = ScrapeMetrics(*test.http);
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
  const auto after = ScrapeMetrics(*test.http);
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
  EXPECT_EQ(ScrapeMetrics(*test.http).at("getme_element_iterations_total"),
            static_cast<double>(smoothed.result.after().elements() *
                                smoothed.result.iterations_simultaneous()));
}

// The server runs in this process: its memory gauges must follow a block this test allocates.
TEST(HttpMetricsTest, MemoryGaugesFollowTheProcess) {
  constexpr double kMiB = 1 << 20;
  HttpTestServer test = StartHttpTestServer();
  const auto before = ScrapeMetrics(*test.http);
  ASSERT_TRUE(before.contains("process_resident_memory_bytes"));
  // VmRSS from /proc/<pid>/status; the gauge reads /proc/self/statm.
  const double own_resident = 1024.0 * ResidentKiB(getpid());
  EXPECT_NEAR(before.at("process_resident_memory_bytes"), own_resident,
              0.1 * own_resident + 4 * kMiB);
  if constexpr (!kHeapCountsKnown) {
    EXPECT_FALSE(before.contains("getme_heap_in_use_bytes")) << "a sanitizer's allocator";
    return;
  }

  // 64 MiB is above glibc's largest mmap threshold: a mapping of its own, unmapped on free.
  constexpr std::size_t kBlock = 64 << 20;
  auto block = std::make_unique_for_overwrite<char[]>(kBlock);
  std::memset(block.get(), 1, kBlock);  // resident, not only reserved
  const auto holding = ScrapeMetrics(*test.http);
  EXPECT_NEAR(holding.at("getme_heap_in_use_bytes") - before.at("getme_heap_in_use_bytes"),
              static_cast<double>(kBlock), 2 * kMiB);
  EXPECT_GE(
      holding.at("process_resident_memory_bytes") - before.at("process_resident_memory_bytes"),
      0.95 * kBlock);
  block.reset();
  const auto after = ScrapeMetrics(*test.http);
  EXPECT_NEAR(after.at("getme_heap_in_use_bytes"), before.at("getme_heap_in_use_bytes"), 2 * kMiB);
  EXPECT_LE(after.at("process_resident_memory_bytes"),
            holding.at("process_resident_memory_bytes") - 0.95 * kBlock);
}

}  // namespace
}  // namespace getme::server::testing
