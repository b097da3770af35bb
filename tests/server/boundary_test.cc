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

// A 4 × 4 × 4 cube of unit hexahedra on the wire (VTK order), whose top face z = 4 is split along
// x = 2 into two surface groups (tags 7 and 8) when `tagged`. Top nodes inside the face are moved
// up to 0.3 within it (along y only on the line x = 2), interior nodes up to 0.3 in each axis, so
// smoothing wants to move the top face's nodes. One more tagged quad lies inside the cube: an
// interface, which a file's tags have too, counted and left out.
v1::Mesh GroupedCube(bool tagged) {
  constexpr int n = 4;
  const auto id = [](int i, int j, int k) {
    return static_cast<std::uint32_t>(i + (n + 1) * (j + (n + 1) * k));
  };
  std::uint64_t state = 12345;
  const auto jitter = [&]() {  // deterministic, in [-0.3, 0.3]
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return 0.6 * static_cast<double>(state >> 11) / static_cast<double>(1ULL << 53) - 0.3;
  };
  v1::Mesh mesh;
  for (int k = 0; k <= n; ++k) {
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        double x = i, y = j, z = k;
        const bool inside_xy = i > 0 && i < n && j > 0 && j < n;
        if (inside_xy && k > 0 && k < n) {
          x += jitter();
          y += jitter();
          z += jitter();
        } else if (inside_xy && k == n) {
          if (i != n / 2) x += jitter();
          y += jitter();
        }
        mesh.add_coordinates(x);
        mesh.add_coordinates(y);
        mesh.add_coordinates(z);
      }
    }
  }
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        for (const std::uint32_t node :
             {id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
              id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)}) {
          mesh.add_hexahedra(node);
        }
      }
    }
  }
  if (!tagged) return mesh;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      for (const std::uint32_t node :
           {id(i, j, n), id(i + 1, j, n), id(i + 1, j + 1, n), id(i, j + 1, n)}) {
        mesh.add_group_quads(node);
      }
      mesh.add_quad_groups(i < n / 2 ? 7 : 8);
    }
  }
  for (const std::uint32_t node : {id(1, 1, 2), id(2, 1, 2), id(2, 2, 2), id(1, 2, 2)}) {
    mesh.add_group_quads(node);
  }
  mesh.add_quad_groups(9);
  return mesh;
}

TEST(BoundaryServiceTest, SurfaceGroupsOnTheWireKeepTheirNodes) {
  // The two groups' common line x = 2 is a feature curve: its nodes slide along it and keep x = 2
  // exactly (read from the result's coordinates). Without the groups the same nodes are ordinary
  // face nodes and move off the line, so the groups are what holds them.
  TestServer test = StartTestServer();
  v1::SmoothingParameters parameters;
  parameters.set_boundary(v1::BOUNDARY_SLIDE);
  parameters.set_threads(2);
  double largest_off_line[2] = {0.0, 0.0};
  for (const bool tagged : {false, true}) {
    const v1::Mesh wire = GroupedCube(tagged);
    const SmoothOutcome outcome = CallSmooth(*test.stub, SmoothRequests(wire, parameters));
    ASSERT_TRUE(outcome.status.ok()) << outcome.status.error_message();
    ASSERT_TRUE(outcome.result.has_boundary_slide());
    const v1::BoundarySlideReport& slide = outcome.result.boundary_slide();
    EXPECT_EQ(slide.surface_groups(), tagged ? 3 : 1);
    EXPECT_EQ(slide.interior_grouped_faces(), tagged ? 1 : 0);
    ASSERT_EQ(outcome.mesh.coordinates_size(), wire.coordinates_size());
    for (int j = 1; j < 4; ++j) {
      const int node = 2 + 5 * (j + 5 * 4);
      const double x = outcome.mesh.coordinates(3 * node);
      EXPECT_EQ(wire.coordinates(3 * node), 2.0);
      largest_off_line[tagged] = std::max(largest_off_line[tagged], std::abs(x - 2.0));
    }
  }
  EXPECT_EQ(largest_off_line[1], 0.0);
  EXPECT_GT(largest_off_line[0], 1e-3);
}

TEST(BoundaryServiceTest, BadSurfaceGroupsAreInvalidArgumentsNamingTheField) {
  TestServer test = StartTestServer();
  v1::SmoothingParameters parameters;
  parameters.set_boundary(v1::BOUNDARY_SLIDE);
  const auto expect_refused = [&](const v1::Mesh& wire, const char* message) {
    const SmoothOutcome outcome = CallSmooth(*test.stub, SmoothRequests(wire, parameters));
    EXPECT_EQ(outcome.status.error_code(), grpc::StatusCode::INVALID_ARGUMENT)
        << outcome.status.error_message();
    EXPECT_THAT(outcome.status.error_message(), HasSubstr(message));
    EXPECT_FALSE(outcome.have_result);
  };
  v1::Mesh wire = GroupedCube(true);
  wire.add_quad_groups(7);
  expect_refused(wire, "mesh.quad_groups has 18 tags but mesh.group_quads has 17 quads");
  wire = GroupedCube(true);
  wire.add_group_triangles(0);
  wire.add_group_triangles(1);
  expect_refused(wire, "mesh.group_triangles has 2 node indices, not a multiple of 3");
  wire = GroupedCube(true);
  wire.set_group_quads(5, 125);
  expect_refused(wire,
                 "mesh.group_quads[5] = 125 (quad 1) is out of range: the mesh has 125 nodes");
}

}  // namespace
}  // namespace getme::server::testing
