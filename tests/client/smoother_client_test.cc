// SmootherClient against an in-process server: results bit-identical to the local engine,
// progress in order, a mesh over gRPC's 4 MB limit both ways, jobs, cancellation, error codes.

#include "remote/smoother_client.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "getme/smoothing/smoother.h"
#include "getme_wire/engine_mesh.h"
#include "getme_wire/params.h"
#include "getme_wire/progress.h"
#include "remote/grid_upload.h"
#include "test_meshes.h"
#include "test_server.h"

namespace getme::remote {
namespace {

using testing::DistortedHexBlock;
using wire::FromWireProgress;
using wire::ToWireMesh;
using wire::ToWireParameters;

struct LocalRun {
  std::vector<double> coordinates;
  std::vector<ProgressEvent> events;
  SmoothingResult result;
};

LocalRun SmoothLocally(Mesh mesh, const SmoothingParams& params) {
  LocalRun run;
  absl::StatusOr<SmoothingResult> result =
      Smooth(mesh, params, [&](const ProgressEvent& event) { run.events.push_back(event); });
  EXPECT_TRUE(result.ok()) << result.status();
  if (result.ok()) run.result = *result;
  for (std::int64_t node = 0; node < mesh.node_count(); ++node) {
    run.coordinates.insert(run.coordinates.end(), {mesh.x()[node], mesh.y()[node], mesh.z()[node]});
  }
  return run;
}

SmoothJobOptions JobFor(const SmoothingParams& params, bool coordinates_only = true) {
  SmoothJobOptions job;
  job.parameters = ToWireParameters(params);
  job.result_options.set_coordinates_only(coordinates_only);
  return job;
}

class SmootherClientTest : public ::testing::Test {
 protected:
  void SetUp() override {
    server_ = testing::StartTestServer();
    ASSERT_NE(server_, nullptr);
    client_ = std::make_unique<SmootherClient>(
        SmootherClient::CreateChannel(testing::TargetOf(*server_)));
  }
  void TearDown() override {
    if (server_) server_->Shutdown(absl::Seconds(1));
  }

  std::unique_ptr<server::SmootherServer> server_;
  std::unique_ptr<SmootherClient> client_;
};

TEST_F(SmootherClientTest, SmoothIsBitIdenticalToTheLocalEngineWithTheSameEvents) {
  const Mesh mesh = DistortedHexBlock(6, 0.2);
  SmoothingParams params;
  params.threads = 1;
  const LocalRun local = SmoothLocally(mesh, params);

  std::vector<v1::ProgressEvent> events;
  absl::StatusOr<RemoteSmoothResult> remote = client_->Smooth(
      ToWireMesh(mesh), JobFor(params), [&](const v1::ProgressEvent& e) { events.push_back(e); });
  ASSERT_TRUE(remote.ok()) << remote.status();
  const std::vector<double> coordinates(remote->mesh.coordinates().begin(),
                                        remote->mesh.coordinates().end());
  EXPECT_EQ(coordinates, local.coordinates);
  EXPECT_EQ(remote->result.nodes(), static_cast<std::uint64_t>(mesh.node_count()));
  EXPECT_EQ(remote->result.after().q_min(), local.result.after.q_min);
  EXPECT_EQ(remote->result.after().q_mean(), local.result.after.q_mean);
  EXPECT_EQ(remote->result.iterations_simultaneous(), local.result.iterations_simultaneous);
  EXPECT_EQ(remote->result.iterations_sequential(), local.result.iterations_sequential);

  // Unthrottled, the stream is the engine's events in order, then (if the last engine event is
  // not marked so) one closing event marked final.
  ASSERT_TRUE(events.size() == local.events.size() || events.size() == local.events.size() + 1)
      << events.size() << " events, the engine sent " << local.events.size();
  ASSERT_TRUE(events.back().final());
  for (std::size_t i = 0; i < local.events.size(); ++i) {
    const ProgressEvent converted = FromWireProgress(events[i]);
    EXPECT_EQ(converted.phase, local.events[i].phase) << "event " << i;
    EXPECT_EQ(converted.iteration, local.events[i].iteration) << "event " << i;
    EXPECT_EQ(converted.q_min, local.events[i].q_min) << "event " << i;
    EXPECT_EQ(converted.q_mean, local.events[i].q_mean) << "event " << i;
    EXPECT_EQ(converted.phase_done, local.events[i].phase_done) << "event " << i;
    if (i > 0) {
      EXPECT_GT(events[i].sequence(), events[i - 1].sequence()) << "event " << i;
    }
    if (i + 1 < events.size()) {
      EXPECT_FALSE(events[i].final()) << "event " << i;
    }
  }
  EXPECT_GT(remote->result.after().q_mean(), remote->result.before().q_mean());
}

TEST_F(SmootherClientTest, MeshOverFourMegabytesRoundTripsBothWays) {
  // 51^3 = 132651 nodes: 3.2 MB of coordinates plus 125000 hexahedra (~3 MB of indices).
  const Mesh mesh = DistortedHexBlock(50, 0.2);
  const v1::Mesh wire = ToWireMesh(mesh);
  ASSERT_GT(wire.ByteSizeLong(), 4u << 20);
  SmoothingParams params;
  params.method = Method::kSimultaneous;
  params.simultaneous_max_iterations = 2;
  params.threads = 1;
  const LocalRun local = SmoothLocally(mesh, params);
  absl::StatusOr<RemoteSmoothResult> remote =
      client_->Smooth(wire, JobFor(params, /*coordinates_only=*/false), {});
  ASSERT_TRUE(remote.ok()) << remote.status();
  const std::vector<double> coordinates(remote->mesh.coordinates().begin(),
                                        remote->mesh.coordinates().end());
  EXPECT_TRUE(coordinates == local.coordinates) << "coordinates differ from the local engine";
  // The full result carries the unchanged topology.
  EXPECT_TRUE(std::equal(remote->mesh.hexahedra().begin(), remote->mesh.hexahedra().end(),
                         wire.hexahedra().begin(), wire.hexahedra().end()));
}

TEST_F(SmootherClientTest, SubmitWatchAndFetchAJob) {
  const Mesh mesh = DistortedHexBlock(5, 0.2, 7);
  SmoothingParams params;
  params.threads = 1;
  const LocalRun local = SmoothLocally(mesh, params);
  absl::StatusOr<v1::Job> job = client_->SubmitJob(ToWireMesh(mesh), JobFor(params));
  ASSERT_TRUE(job.ok()) << job.status();
  ASSERT_FALSE(job->job_id().empty());
  bool saw_final = false;
  ASSERT_TRUE(
      client_
          ->WatchJob(job->job_id(),
                     [&](const v1::ProgressEvent& e) { saw_final = saw_final || e.final(); })
          .ok());
  EXPECT_TRUE(saw_final);
  absl::StatusOr<v1::Job> finished = client_->GetJob(job->job_id());
  ASSERT_TRUE(finished.ok()) << finished.status();
  EXPECT_EQ(finished->state(), v1::JOB_STATE_SUCCEEDED);
  absl::StatusOr<std::vector<v1::Job>> jobs = client_->ListJobs();
  ASSERT_TRUE(jobs.ok()) << jobs.status();
  EXPECT_TRUE(std::any_of(jobs->begin(), jobs->end(),
                          [&](const v1::Job& j) { return j.job_id() == job->job_id(); }));
  absl::StatusOr<RemoteSmoothResult> result = client_->GetResult(job->job_id());
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_TRUE(std::vector<double>(result->mesh.coordinates().begin(),
                                  result->mesh.coordinates().end()) == local.coordinates);
}

TEST_F(SmootherClientTest, CancelFlagStopsARunningSmoothCall) {
  const Mesh mesh = DistortedHexBlock(40, 0.2);
  SmoothingParams params;
  params.threads = 1;
  std::atomic<bool> cancel{false};
  CallOptions call;
  call.cancel = &cancel;
  int events = 0;
  const auto started = std::chrono::steady_clock::now();
  absl::StatusOr<RemoteSmoothResult> result = client_->Smooth(
      ToWireMesh(mesh), JobFor(params),
      [&](const v1::ProgressEvent&) {
        if (++events == 2) cancel.store(true);
      },
      call);
  EXPECT_EQ(result.status().code(), absl::StatusCode::kCancelled) << result.status();
  EXPECT_GE(events, 2);
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(60));
}

TEST_F(SmootherClientTest, DeadlineExceededEndsTheCall) {
  const Mesh mesh = DistortedHexBlock(40, 0.2);
  CallOptions call;
  call.timeout = absl::Milliseconds(300);
  absl::StatusOr<RemoteSmoothResult> result =
      client_->Smooth(ToWireMesh(mesh), JobFor(SmoothingParams()), {}, call);
  EXPECT_EQ(result.status().code(), absl::StatusCode::kDeadlineExceeded) << result.status();
}

TEST_F(SmootherClientTest, ServerErrorsArriveWithTheirCodes) {
  v1::Mesh bad = ToWireMesh(DistortedHexBlock(2, 0.1));
  bad.set_hexahedra(3, 999);  // node index out of range
  absl::StatusOr<RemoteSmoothResult> smoothed = client_->Smooth(bad, JobFor(SmoothingParams()), {});
  EXPECT_EQ(smoothed.status().code(), absl::StatusCode::kInvalidArgument) << smoothed.status();
  EXPECT_NE(smoothed.status().message().find("999"), std::string::npos) << smoothed.status();
  absl::StatusOr<v1::QualityReport> quality = client_->EvaluateQuality(bad, 0);
  EXPECT_EQ(quality.status().code(), absl::StatusCode::kInvalidArgument) << quality.status();
  EXPECT_EQ(client_->GetJob("no-such-job").status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(client_->CancelJob("no-such-job").status().code(), absl::StatusCode::kNotFound);
}

TEST_F(SmootherClientTest, EvaluateQualityMatchesTheLocalEvaluation) {
  const Mesh mesh = DistortedHexBlock(4, 0.2);
  ThreadPool pool(1);
  const MeshQuality local = EvaluateMeshQuality(mesh, pool);
  absl::StatusOr<v1::QualityReport> remote = client_->EvaluateQuality(ToWireMesh(mesh), 0);
  ASSERT_TRUE(remote.ok()) << remote.status();
  EXPECT_EQ(remote->elements(), local.elements);
  EXPECT_EQ(remote->q_min(), local.q_min);
  EXPECT_EQ(remote->q_mean(), local.q_mean);
  EXPECT_EQ(std::vector<std::int64_t>(remote->histogram().begin(), remote->histogram().end()),
            local.histogram);
}

TEST(SmootherClientUnreachable, ReportsUnavailable) {
  SmootherClient client(SmootherClient::CreateChannel("127.0.0.1:1"));
  absl::StatusOr<std::vector<v1::Job>> jobs = client.ListJobs();
  EXPECT_EQ(jobs.status().code(), absl::StatusCode::kUnavailable) << jobs.status();
}

}  // namespace
}  // namespace getme::remote
