// A sliding boundary and kept layers through the service (issue 15): the server builds the
// input's surface and layer columns from the uploaded mesh as the CLI does from its file, so a job
// with BOUNDARY_SLIDE and keep_layers returns the coordinates of the in-process Smooth with a
// SurfaceSlide bit for bit, and its result carries the same slide and layer reports; a bad
// boundary request is refused before the mesh is smoothed, naming the fields.
#include <cmath>
#include <cstring>
#include <memory>

#include "getme/meshgen/layered_hex_block.h"
#include "getme/parallel/thread_pool.h"
#include "getme/smoothing/smoother.h"
#include "getme_surface/boundary_surface_counts.h"
#include "getme_surface/layer_report.h"
#include "getme_surface/surface_slide.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"
#include "server_test_support.h"

namespace getme::server::testing {
namespace {

using ::testing::HasSubstr;

// A hexahedral boundary-layer block on the wall z = 0 (layers 1 % thick at the wall, growing
// 1.3 x, columns leaning; the generator getme-meshgen hex-layers uses), each interior column
// shifted sideways as a whole, so that a sliding wall has an irregular grid to even out (as
// tests/surface/kept_layers_test.cc does).
Mesh LayerBlock() {
  constexpr int kCells = 6;
  constexpr int kLayers = 10;
  absl::StatusOr<Mesh> mesh = meshgen::LayeredHexBlock(kCells, kCells, kLayers, 0.01, 1.3, 0.3, 7);
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  constexpr NodeId kPerLevel = (kCells + 1) * (kCells + 1);
  for (int j = 1; j < kCells; ++j) {
    for (int i = 1; i < kCells; ++i) {
      const double dx = 0.2 * std::sin(7.0 * i + 3.0 * j);
      const double dy = 0.2 * std::cos(5.0 * i + 11.0 * j);
      for (int k = 0; k <= kLayers; ++k) {
        const NodeId node = i + (kCells + 1) * j + kPerLevel * k;
        mesh->x()[node] += dx;
        mesh->y()[node] += dy;
      }
    }
  }
  return std::move(*mesh);
}

// What the CLI's local mode does with --boundary slide --keep-layers
// (client/cli/smooth_command.cc).
struct LocalSlideRun {
  Mesh mesh;
  SmoothingResult result;
  surface::BoundarySurfaceCounts features;
  surface::LayerReport layers;
};

LocalSlideRun SmoothLocallyWithSlide(const v1::Mesh& wire, const SmoothingParams& params) {
  LocalSlideRun run{FromWire(wire), {}, {}, {}};
  surface::SlideOptions options;
  options.feature_angle_degrees = params.feature_angle_degrees;
  options.slide_boundary = params.slide_boundary;
  options.keep_layers = params.keep_layers;
  absl::StatusOr<std::unique_ptr<surface::SurfaceSlide>> slide =
      surface::SurfaceSlide::Build(run.mesh, options);
  EXPECT_TRUE(slide.ok()) << slide.status();
  if (!slide.ok()) return run;
  ThreadPool pool(1);
  const surface::LayerHeights before = surface::MeasureKeptLayers(run.mesh, **slide, pool);
  absl::StatusOr<SmoothingResult> result = Smooth(run.mesh, params, {}, nullptr, slide->get());
  EXPECT_TRUE(result.ok()) << result.status();
  if (!result.ok()) return run;
  run.result = *std::move(result);
  run.features = surface::CountFeatures((*slide)->surface());
  run.layers = surface::MakeLayerReport(**slide, before,
                                        surface::MeasureKeptLayers(run.mesh, **slide, pool));
  return run;
}

void ExpectSameState(const v1::LayerState& remote, const surface::LayerState& local) {
  EXPECT_EQ(remote.first_min(), local.first_min);
  EXPECT_EQ(remote.first_mean(), local.first_mean);
  EXPECT_EQ(remote.first_max(), local.first_max);
  EXPECT_EQ(remote.mean_lean_degrees(), local.mean_lean_degrees);
  EXPECT_EQ(remote.q_min(), local.q_min);
  EXPECT_EQ(remote.q_mean(), local.q_mean);
}

TEST(BoundaryServiceTest, SlideWithKeptLayersIsBitIdenticalToTheLocalEngineWithItsReports) {
  TestServer test = StartTestServer();
  const v1::Mesh wire = ToWire(LayerBlock());
  SmoothingParams local_params;
  local_params.threads = 1;
  local_params.slide_boundary = true;
  local_params.keep_layers = true;
  const LocalSlideRun local = SmoothLocallyWithSlide(wire, local_params);
  ASSERT_TRUE(local.result.boundary_slide.has_value());

  v1::SmoothingParameters parameters;
  parameters.set_boundary(v1::BOUNDARY_SLIDE);
  parameters.set_keep_layers(true);
  parameters.set_threads(2);  // results must not depend on the thread count
  const SmoothOutcome remote = CallSmooth(*test.stub, SmoothRequests(wire, parameters));
  ASSERT_TRUE(remote.status.ok()) << remote.status.error_message();
  ASSERT_TRUE(remote.have_result);
  ExpectBitIdenticalCoordinates(local.mesh, remote.mesh);

  const v1::SmoothResult& result = remote.result;
  EXPECT_EQ(result.boundary(), v1::BOUNDARY_SLIDE);
  EXPECT_EQ(result.after().q_mean(), local.result.after.q_mean);
  EXPECT_EQ(result.iterations_layers(), local.result.iterations_layers);
  EXPECT_GT(result.iterations_layers(), 0);
  ASSERT_GE(result.phases_size(), 1);
  EXPECT_EQ(result.phases(0).phase(), v1::PHASE_LAYERS);

  ASSERT_TRUE(result.has_boundary_slide());
  const v1::BoundarySlideReport& slide = result.boundary_slide();
  EXPECT_EQ(slide.sliding_nodes(), local.result.boundary_slide->sliding_nodes);
  EXPECT_EQ(slide.slid_nodes(), local.result.boundary_slide->slid_nodes);
  EXPECT_EQ(slide.max_distance(), local.result.boundary_slide->max_distance);
  EXPECT_EQ(slide.layer_nodes(), local.result.boundary_slide->layer_nodes);
  EXPECT_GT(slide.slid_nodes(), 0);
  EXPECT_LE(slide.max_distance(), 1e-9);
  EXPECT_GT(slide.layer_nodes(), 0);
  // A box: its 12 edges are the feature curves, its 8 corners stay.
  EXPECT_EQ(slide.feature_curves(), 12);
  EXPECT_EQ(slide.corners(), 8);
  EXPECT_EQ(slide.feature_edges(), local.features.feature_edges);

  ASSERT_TRUE(result.has_layers());
  const v1::LayerReport& layers = result.layers();
  EXPECT_EQ(layers.columns(), 36);  // one per wall face
  EXPECT_EQ(layers.layers(), local.layers.layers);
  EXPECT_EQ(layers.column_elements(), local.layers.column_elements);
  EXPECT_EQ(layers.layer_nodes(), local.layers.layer_nodes);
  EXPECT_EQ(layers.ends_boundary(), local.layers.ends_boundary);
  ExpectSameState(layers.before(), local.layers.before);
  ExpectSameState(layers.after(), local.layers.after);
  EXPECT_EQ(layers.max_height_change(), local.layers.max_height_change);
  EXPECT_LE(layers.max_height_change(), 0.01);  // issue 15: heights within 1 %
  EXPECT_LT(layers.after().mean_lean_degrees(), layers.before().mean_lean_degrees());
}

TEST(BoundaryServiceTest, AHeldBoundaryReportsNoSlideAndPlainJobsNothingNew) {
  TestServer test = StartTestServer();
  const v1::Mesh wire = ToWire(LayerBlock());
  v1::SmoothingParameters parameters;
  parameters.set_keep_layers(true);  // held boundary, kept layers
  parameters.set_simultaneous_max_iterations(20);
  SmoothOutcome remote = CallSmooth(*test.stub, SmoothRequests(wire, parameters));
  ASSERT_TRUE(remote.status.ok()) << remote.status.error_message();
  EXPECT_EQ(remote.result.boundary(), v1::BOUNDARY_FIXED);
  EXPECT_TRUE(remote.result.has_layers());
  EXPECT_GT(remote.result.boundary_slide().layer_nodes(), 0);
  EXPECT_EQ(remote.result.boundary_slide().feature_edges(), 0);  // no surface counts: no slide
  EXPECT_EQ(remote.result.boundary_slide().corners(), 0);

  parameters = {};
  parameters.set_free_boundary(true);
  parameters.set_simultaneous_max_iterations(20);
  remote = CallSmooth(*test.stub, SmoothRequests(wire, parameters));
  ASSERT_TRUE(remote.status.ok()) << remote.status.error_message();
  EXPECT_EQ(remote.result.boundary(), v1::BOUNDARY_FREE);
  EXPECT_FALSE(remote.result.has_boundary_slide());
  EXPECT_FALSE(remote.result.has_layers());
  EXPECT_EQ(remote.result.iterations_layers(), 0);
}

TEST(BoundaryServiceTest, BadBoundaryRequestsAreInvalidArgumentsNamingTheFields) {
  TestServer test = StartTestServer();
  const v1::Mesh wire = ToWire(LayerBlock());
  const auto expect_refused = [&](const v1::SmoothingParameters& parameters,
                                  std::initializer_list<const char*> fields) {
    const SmoothOutcome outcome = CallSmooth(*test.stub, SmoothRequests(wire, parameters));
    EXPECT_EQ(outcome.status.error_code(), grpc::StatusCode::INVALID_ARGUMENT)
        << outcome.status.error_message();
    for (const char* field : fields) EXPECT_THAT(outcome.status.error_message(), HasSubstr(field));
    EXPECT_FALSE(outcome.have_result);
  };
  v1::SmoothingParameters parameters;
  parameters.set_boundary(v1::BOUNDARY_SLIDE);
  parameters.set_feature_angle_degrees(200);
  expect_refused(parameters, {"feature_angle_degrees = 200"});
  parameters.clear_feature_angle_degrees();
  parameters.set_free_boundary(true);
  expect_refused(parameters, {"parameters.free_boundary = true", "BOUNDARY_SLIDE"});
  parameters = {};
  parameters.set_boundary(v1::BOUNDARY_FREE);
  parameters.set_keep_layers(true);
  expect_refused(parameters, {"parameters.keep_layers", "BOUNDARY_FREE"});
}

}  // namespace
}  // namespace getme::server::testing
