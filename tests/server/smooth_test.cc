// Smooth / SubmitJob / GetResult against the local engine: same coordinates bit for bit, the same
// progress events in the same order, and meshes beyond gRPC's 4 MB message limit both ways.
#include <cstring>
#include <vector>

#include "getme/smoothing/progress.h"
#include "getme/smoothing/smoother.h"
#include "gtest/gtest.h"
#include "server_test_support.h"

namespace getme::server::testing {
namespace {

struct LocalRun {
  Mesh mesh;
  SmoothingResult result;
  std::vector<ProgressEvent> events;
};

LocalRun SmoothLocally(const v1::Mesh& wire, SmoothingParams params) {
  LocalRun run{FromWire(wire), {}, {}};
  auto result =
      Smooth(run.mesh, params, [&run](const ProgressEvent& event) { run.events.push_back(event); });
  EXPECT_TRUE(result.ok()) << result.status();
  if (result.ok()) run.result = *result;
  return run;
}

TEST(SmoothTest, RemoteResultIsBitIdenticalToTheLocalEngine) {
  TestServer test = StartTestServer();
  const v1::Mesh wire = ToWire(SmallHybridMesh());
  ASSERT_GT(wire.wedges_size(), 0);
  ASSERT_GT(wire.pyramids_size(), 0);
  ASSERT_GT(wire.hexahedra_size(), 0);

  SmoothingParams local_params;
  local_params.threads = 1;
  const LocalRun local = SmoothLocally(wire, local_params);

  v1::SmoothingParameters parameters;
  parameters.set_threads(2);  // results must not depend on the thread count
  SmoothOutcome remote = CallSmooth(*test.stub, SmoothRequests(wire, parameters));
  ASSERT_TRUE(remote.status.ok()) << remote.status.error_message();
  ASSERT_TRUE(remote.have_result);
  ExpectBitIdenticalCoordinates(local.mesh, remote.mesh);
  // Topology comes back unchanged, in VTK order.
  EXPECT_EQ(remote.mesh.wedges_size(), wire.wedges_size());
  for (int i = 0; i < wire.wedges_size(); ++i) ASSERT_EQ(remote.mesh.wedges(i), wire.wedges(i));
  EXPECT_EQ(remote.mesh.tetrahedra_size(), wire.tetrahedra_size());
  EXPECT_EQ(remote.mesh.pyramids_size(), wire.pyramids_size());

  EXPECT_EQ(remote.result.after().q_min(), local.result.after.q_min);
  EXPECT_EQ(remote.result.after().q_mean(), local.result.after.q_mean);
  EXPECT_EQ(remote.result.before().q_mean(), local.result.before.q_mean);
  EXPECT_EQ(remote.result.threads(), 2);
  EXPECT_EQ(remote.result.nodes(), static_cast<std::uint64_t>(local.mesh.node_count()));
  EXPECT_EQ(remote.result.after().wedges().count(), wire.wedges_size() / 6);
  EXPECT_EQ(remote.result.iterations_simultaneous(), local.result.iterations_simultaneous);
  EXPECT_EQ(remote.result.iterations_sequential(), local.result.iterations_sequential);
  EXPECT_FALSE(remote.result.job_id().empty());
  EXPECT_GT(remote.result.after().q_mean(), remote.result.before().q_mean());
}

TEST(SmoothTest, ProgressEventsMatchTheLocalEngineInOrderWithTheFinalEventLast) {
  TestServer test = StartTestServer();  // progress_interval 0: every event is forwarded
  const v1::Mesh wire = ToWire(SmallHybridMesh());
  SmoothingParams local_params;
  local_params.threads = 1;
  local_params.sequential_cycle = 50;
  const LocalRun local = SmoothLocally(wire, local_params);

  v1::SmoothingParameters parameters;
  parameters.set_sequential_cycle(50);
  SmoothOutcome remote = CallSmooth(*test.stub, SmoothRequests(wire, parameters));
  ASSERT_TRUE(remote.status.ok()) << remote.status.error_message();

  // One event per engine event, then the job's final event.
  ASSERT_EQ(remote.events.size(), local.events.size() + 1);
  for (std::size_t i = 0; i < local.events.size(); ++i) {
    const v1::ProgressEvent& event = remote.events[i];
    const ProgressEvent& expected = local.events[i];
    EXPECT_EQ(event.sequence(), i + 1);
    EXPECT_EQ(event.job_id(), remote.result.job_id());
    EXPECT_EQ(event.iteration(), expected.iteration) << "event " << i;
    EXPECT_EQ(event.q_min(), expected.q_min) << "event " << i;
    EXPECT_EQ(event.q_mean(), expected.q_mean) << "event " << i;
    EXPECT_EQ(event.phase_done(), expected.phase_done) << "event " << i;
    EXPECT_FALSE(event.final());
  }
  // Phases in the order of the result, each closed by exactly one phase_done event.
  std::vector<v1::Phase> done_phases;
  for (const auto& event : remote.events) {
    if (event.phase_done()) done_phases.push_back(event.phase());
  }
  ASSERT_EQ(done_phases.size(), static_cast<std::size_t>(remote.result.phases_size()));
  for (int i = 0; i < remote.result.phases_size(); ++i) {
    EXPECT_EQ(done_phases[i], remote.result.phases(i).phase());
  }
  ASSERT_GE(done_phases.size(), 2u);
  EXPECT_EQ(done_phases[0], v1::PHASE_SIMULTANEOUS);
  EXPECT_EQ(done_phases[1], v1::PHASE_SEQUENTIAL);
  const v1::ProgressEvent& last = remote.events.back();
  EXPECT_TRUE(last.final());
  EXPECT_EQ(last.sequence(), remote.events.size());
  EXPECT_EQ(last.q_mean(), remote.result.after().q_mean());
}

TEST(SmoothTest, ThrottledWatchersStillGetEveryPhaseEndAndTheFinalEvent) {
  ServerOptions options = TestOptions();
  options.progress_interval = absl::Hours(1);
  TestServer test = StartTestServer(options);
  const v1::Mesh wire = ToWire(SmallHybridMesh());
  v1::SmoothingParameters parameters;
  parameters.set_sequential_cycle(20);
  SmoothOutcome remote = CallSmooth(*test.stub, SmoothRequests(wire, parameters));
  ASSERT_TRUE(remote.status.ok()) << remote.status.error_message();

  int phase_done = 0, intermediate = 0;
  std::uint64_t previous_sequence = 0;
  for (const auto& event : remote.events) {
    EXPECT_GT(event.sequence(), previous_sequence);
    previous_sequence = event.sequence();
    if (event.phase_done()) ++phase_done;
    if (!event.phase_done() && !event.final()) ++intermediate;
  }
  EXPECT_EQ(phase_done, remote.result.phases_size());
  EXPECT_LE(intermediate, 1) << "one intermediate event per hour at most";
  EXPECT_TRUE(remote.events.back().final());
  // Events were skipped: the sequence numbers show the gap.
  EXPECT_GT(remote.events.back().sequence(), remote.events.size());
}

TEST(SmoothTest, SubmitWatchAndGetResultMatchSmooth) {
  TestServer test = StartTestServer();
  const v1::Mesh wire = ToWire(SmallHybridMesh());
  SmoothingParams local_params;
  const LocalRun local = SmoothLocally(wire, local_params);

  v1::ResultOptions result_options;
  result_options.set_coordinates_only(true);
  result_options.set_histogram_bins(7);
  auto job = Submit(*test.stub, SmoothRequests(wire, {}, result_options));
  ASSERT_TRUE(job.ok()) << job.status();
  EXPECT_EQ(job->method(), v1::METHOD_GETME);
  EXPECT_EQ(job->elements(), static_cast<std::uint64_t>(local.mesh.element_count()));

  grpc::ClientContext watch_context;
  v1::WatchJobRequest watch;
  watch.set_job_id(job->job_id());
  auto reader = test.stub->WatchJob(&watch_context, watch);
  std::vector<v1::ProgressEvent> events;
  v1::ProgressEvent event;
  while (reader->Read(&event)) events.push_back(event);
  ASSERT_TRUE(reader->Finish().ok());
  ASSERT_FALSE(events.empty());
  EXPECT_TRUE(events.back().final());

  v1::Job done = GetJob(*test.stub, job->job_id());
  EXPECT_EQ(done.state(), v1::JOB_STATE_SUCCEEDED);
  EXPECT_TRUE(done.result_available());
  EXPECT_GT(done.finished_unix_seconds(), 0);

  SmoothOutcome result = CallGetResult(*test.stub, job->job_id());
  ASSERT_TRUE(result.status.ok()) << result.status.error_message();
  EXPECT_TRUE(result.events.empty());
  EXPECT_TRUE(result.result.coordinates_only());
  EXPECT_EQ(result.result.after().histogram_size(), 7);
  EXPECT_EQ(result.result.before().histogram_size(), 7);
  std::int64_t histogram_total = 0;
  for (auto count : result.result.after().histogram()) histogram_total += count;
  EXPECT_EQ(histogram_total, local.mesh.element_count());
  EXPECT_EQ(result.mesh.tetrahedra_size(), 0) << "coordinates only";
  ExpectBitIdenticalCoordinates(local.mesh, result.mesh);

  // Fetched once: the result is gone now.
  SmoothOutcome again = CallGetResult(*test.stub, job->job_id());
  EXPECT_EQ(again.status.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_NE(again.status.error_message().find("already fetched"), std::string::npos);
  EXPECT_FALSE(GetJob(*test.stub, job->job_id()).result_available());
}

TEST(SmoothTest, MeshOverFourMegabytesRoundTripsInChunks) {
  TestServer test = StartTestServer();
  // 6 * 40^3 = 384,000 tetrahedra: about 6 MB of wire mesh.
  const v1::Mesh wire = ToWire(TetBlock(40, 0.2));
  ASSERT_GT(wire.ByteSizeLong(), std::size_t{4} << 20);
  v1::SmoothingParameters parameters;
  parameters.set_method(v1::METHOD_SIMULTANEOUS);
  parameters.set_simultaneous_max_iterations(2);
  parameters.set_threads(2);

  for (bool coordinates_only : {true, false}) {
    v1::ResultOptions result_options;
    result_options.set_coordinates_only(coordinates_only);
    SmoothOutcome remote = CallSmooth(*test.stub, SmoothRequests(wire, parameters, result_options));
    ASSERT_TRUE(remote.status.ok()) << remote.status.error_message();
    EXPECT_GT(remote.chunks, 1);
    EXPECT_LT(remote.largest_message_bytes, std::size_t{2} << 20);
    ASSERT_EQ(remote.mesh.coordinates_size(), wire.coordinates_size());
    // Interior nodes moved, boundary nodes stayed.
    int moved = 0;
    for (int i = 0; i < wire.coordinates_size(); ++i) {
      moved += remote.mesh.coordinates(i) != wire.coordinates(i);
    }
    EXPECT_GT(moved, wire.coordinates_size() / 4);
    if (coordinates_only) {
      EXPECT_EQ(remote.mesh.tetrahedra_size(), 0);
    } else {
      ASSERT_EQ(remote.mesh.tetrahedra_size(), wire.tetrahedra_size());
      for (int i = 0; i < wire.tetrahedra_size(); ++i) {
        ASSERT_EQ(remote.mesh.tetrahedra(i), wire.tetrahedra(i)) << "index " << i;
      }
      EXPECT_GT(remote.mesh.ByteSizeLong(), std::size_t{4} << 20);
    }
  }
}

TEST(SmoothTest, EvaluateQualityMatchesTheLocalEvaluation) {
  TestServer test = StartTestServer();
  const Mesh mesh = SmallHybridMesh();
  const v1::Mesh wire = ToWire(mesh);
  ThreadPool pool(1);
  const MeshQuality expected = EvaluateMeshQuality(FromWire(wire), pool, {.histogram_bins = 5});

  grpc::ClientContext context;
  v1::QualityReport report;
  auto writer = test.stub->EvaluateQuality(&context, &report);
  v1::EvaluateQualityRequest header;
  header.mutable_header()->set_histogram_bins(5);
  ASSERT_TRUE(writer->Write(header));
  for (v1::MeshChunk& chunk : SplitIntoChunks(wire, 4096)) {
    v1::EvaluateQualityRequest request;
    *request.mutable_chunk() = std::move(chunk);
    ASSERT_TRUE(writer->Write(request));
  }
  writer->WritesDone();
  grpc::Status status = writer->Finish();
  ASSERT_TRUE(status.ok()) << status.error_message();
  EXPECT_EQ(report.elements(), expected.elements);
  EXPECT_EQ(report.q_min(), expected.q_min);
  EXPECT_EQ(report.q_mean(), expected.q_mean);
  EXPECT_EQ(report.warpage_max(), expected.warpage_max);
  EXPECT_EQ(report.wedges().count(), expected.by_type[TypeIndex(ElementType::kPrism)].count);
  EXPECT_EQ(report.pyramids().q_mean(), expected.by_type[TypeIndex(ElementType::kPyramid)].q_mean);
  ASSERT_EQ(report.histogram_size(), 5);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(report.histogram(i), expected.histogram[i]);
}

}  // namespace
}  // namespace getme::server::testing
