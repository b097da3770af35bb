// Smoothing with a sliding boundary (surface/getme_surface/surface_slide.h through Smooth's
// BoundarySlide, issue 15): on a cube of hexahedra whose nodes, boundary ones included, were
// displaced within their faces and edges, the boundary nodes stay on the cube's faces and edges
// (checked from the coordinates, independently of the projector), the corners do not move, no
// element inverts, q_min rises above the fixed-boundary run's, and every thread count gives the
// same bits.

#include "getme_surface/surface_slide.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "absl/strings/str_cat.h"
#include "getme/meshgen/hybrid_block.h"
#include "getme/parallel/thread_pool.h"
#include "getme/smoothing/result_check.h"
#include "getme/smoothing/smoother.h"
#include "getme/smoothing/smoothing_context.h"
#include "getme/smoothing/worst_cluster.h"
#include "surface_test_meshes.h"

namespace getme::surface {
namespace {

constexpr int kSlideCells = 4;

bool OnBound(double c) { return c == 0.0 || c == kSlideCells; }

// HexCube(kSlideCells) with every coordinate that is not on the cube's bounds moved by up to 0.3: a
// face node moves within its face, an edge node along its edge, corners stay.
Mesh DisplacedCube(std::uint64_t seed) {
  Mesh mesh = test::HexCube(kSlideCells);
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> offset(-0.3, 0.3);
  for (auto coordinate : {mesh.x(), mesh.y(), mesh.z()}) {
    for (double& c : coordinate) {
      if (!OnBound(c)) c += offset(random);
    }
  }
  return mesh;
}

int BoundCount(const Mesh& mesh, NodeId node) {
  return OnBound(mesh.x()[node]) + OnBound(mesh.y()[node]) + OnBound(mesh.z()[node]);
}

TEST(SurfaceSlideTest, BoundaryNodesSlideOnTheirFacesAndEdgesAndLiftQMin) {
  SmoothingParams params;
  params.threads = 2;
  Mesh fixed = DisplacedCube(3);
  Mesh sliding = DisplacedCube(3);
  const Mesh input = DisplacedCube(3);
  absl::StatusOr<std::unique_ptr<SurfaceSlide>> slide = SurfaceSlide::Build(sliding);
  ASSERT_TRUE(slide.ok()) << slide.status();
  EXPECT_EQ((*slide)->surface().corner_count, 8);
  absl::StatusOr<SmoothingResult> fixed_result = Smooth(fixed, params);
  params.slide_boundary = true;
  absl::StatusOr<SmoothingResult> slid_result = Smooth(sliding, params, {}, nullptr, slide->get());
  ASSERT_TRUE(fixed_result.ok()) << fixed_result.status();
  ASSERT_TRUE(slid_result.ok()) << slid_result.status();
  EXPECT_EQ(slid_result->after.invalid, 0);
  EXPECT_GT(slid_result->after.q_min, fixed_result->after.q_min);
  ::testing::Test::RecordProperty("q_min_fixed", std::to_string(fixed_result->after.q_min));
  ::testing::Test::RecordProperty("q_min_slide", std::to_string(slid_result->after.q_min));

  // The cube spans [0, kSlideCells]³ with a diagonal of about 7: 1e-9 of it.
  const double tolerance = 1e-9 * std::sqrt(3.0) * kSlideCells;
  std::int64_t moved_boundary = 0;
  for (NodeId node = 0; node < input.node_count(); ++node) {
    const int bounds = BoundCount(input, node);
    if (bounds == 0) continue;
    const double in[3] = {input.x()[node], input.y()[node], input.z()[node]};
    const double out[3] = {sliding.x()[node], sliding.y()[node], sliding.z()[node]};
    for (int c = 0; c < 3; ++c) {
      if (OnBound(in[c])) {
        // The coordinate that puts the node on its face (or edge) stays there.
        EXPECT_NEAR(out[c], in[c], tolerance) << "node " << node << " left its face";
      } else {
        // The other coordinates stay within the cube.
        EXPECT_GE(out[c], -tolerance) << "node " << node;
        EXPECT_LE(out[c], kSlideCells + tolerance) << "node " << node;
      }
    }
    if (bounds == 3) {
      EXPECT_EQ(out[0], in[0]);
      EXPECT_EQ(out[1], in[1]);
      EXPECT_EQ(out[2], in[2]);
    }
    if (out[0] != in[0] || out[1] != in[1] || out[2] != in[2]) ++moved_boundary;
  }
  EXPECT_GT(moved_boundary, 0);
  ASSERT_TRUE(slid_result->boundary_slide.has_value());
  EXPECT_FALSE(fixed_result->boundary_slide.has_value());
  // Sliding: every boundary node but the 8 corners (6 (k-1)² face and 12 (k-1) edge nodes).
  EXPECT_EQ(slid_result->boundary_slide->sliding_nodes, 6 * 9 + 12 * 3);
  EXPECT_EQ(slid_result->boundary_slide->slid_nodes, moved_boundary);
  EXPECT_LE(slid_result->boundary_slide->max_distance, tolerance);
}

// A file that fixes its whole boundary (Mesquite's corpus does) leaves `slide` nothing to slide:
// the run is then the held run, bit for bit, and reports no sliding node. (It ran the sequential
// substep and the polish a second time, and ended elsewhere: cub_fru.vtk at q_min 0.219 instead
// of 0.199.)
TEST(SurfaceSlideTest, WithEveryBoundaryNodeFixedSlidingIsTheFixedRun) {
  SmoothingParams params;
  params.threads = 2;
  Mesh fixed = DisplacedCube(7);
  Mesh sliding = DisplacedCube(7);
  for (Mesh* mesh : {&fixed, &sliding}) {
    for (NodeId node = 0; node < mesh->node_count(); ++node) {
      if (mesh->is_boundary(node)) mesh->set_fixed(node, true);
    }
  }
  absl::StatusOr<std::unique_ptr<SurfaceSlide>> slide = SurfaceSlide::Build(sliding);
  ASSERT_TRUE(slide.ok()) << slide.status();
  absl::StatusOr<SmoothingResult> fixed_result = Smooth(fixed, params);
  params.slide_boundary = true;
  absl::StatusOr<SmoothingResult> slid_result = Smooth(sliding, params, {}, nullptr, slide->get());
  ASSERT_TRUE(fixed_result.ok()) << fixed_result.status();
  ASSERT_TRUE(slid_result.ok()) << slid_result.status();
  ASSERT_TRUE(slid_result->boundary_slide.has_value());
  EXPECT_EQ(slid_result->boundary_slide->sliding_nodes, 0);
  EXPECT_EQ(slid_result->phases.size(), fixed_result->phases.size());
  EXPECT_EQ(slid_result->after.q_min, fixed_result->after.q_min);
  for (NodeId node = 0; node < fixed.node_count(); ++node) {
    ASSERT_EQ(sliding.x()[node], fixed.x()[node]) << "node " << node;
    ASSERT_EQ(sliding.y()[node], fixed.y()[node]) << "node " << node;
    ASSERT_EQ(sliding.z()[node], fixed.z()[node]) << "node " << node;
  }
}

// The result check holds a sliding node to where it belongs, not merely to the surface: an edge
// node of the cube moved along its edge passes, moved onto one of its two faces (still on the
// surface, off its feature curve) is an Internal error naming it. A face node passes within its
// face and fails off the surface.
TEST(SurfaceSlideTest, TheResultCheckKeepsEachNodeOnItsOwnCurveOrFace) {
  Mesh mesh = test::HexCube(2);
  absl::StatusOr<std::unique_ptr<SurfaceSlide>> slide = SurfaceSlide::Build(mesh);
  ASSERT_TRUE(slide.ok()) << slide.status();
  const BoundarySurface& surface = (*slide)->surface();
  // Node (1, 0, 0) is the middle of the edge y = z = 0; node (1, 1, 0) the middle of face z = 0.
  const NodeId edge_node = 1;
  const NodeId face_node = 1 + 3 * 1;
  ASSERT_EQ(surface.kind[edge_node], BoundaryNodeKind::kFeature);
  ASSERT_EQ(surface.kind[face_node], BoundaryNodeKind::kSurface);
  std::vector<std::uint8_t> movable(static_cast<std::size_t>(mesh.node_count()), 1);
  std::vector<std::uint8_t> sliding(static_cast<std::size_t>(mesh.node_count()), 0);
  sliding[edge_node] = sliding[face_node] = 1;
  const ResultCheck check(mesh, movable, slide->get(), sliding);
  ThreadPool pool(1);
  const auto check_now = [&] { return check.Check(mesh, EvaluateMeshQuality(mesh, pool)); };

  mesh.x()[edge_node] = 1.2;  // along its edge
  EXPECT_TRUE(check_now().ok()) << check_now();
  mesh.y()[edge_node] = 0.2;  // onto face z = 0, off the edge
  const absl::Status off_curve = check_now();
  EXPECT_EQ(off_curve.code(), absl::StatusCode::kInternal) << off_curve;
  EXPECT_NE(off_curve.message().find(absl::StrCat("node ", edge_node, " ")), std::string::npos)
      << off_curve;
  mesh.x()[edge_node] = 1.0;
  mesh.y()[edge_node] = 0.0;
  EXPECT_TRUE(check_now().ok()) << check_now();
  mesh.x()[face_node] = 0.8;
  EXPECT_TRUE(check_now().ok()) << check_now();
  mesh.z()[face_node] = 0.1;
  const absl::Status off_surface = check_now();
  EXPECT_EQ(off_surface.code(), absl::StatusCode::kInternal) << off_surface;
  EXPECT_NE(off_surface.message().find(absl::StrCat("node ", face_node, " ")), std::string::npos)
      << off_surface;
}

TEST(SurfaceSlideTest, SlidingNeedsItsSurfaceAndAHeldBoundary) {
  Mesh mesh = DisplacedCube(3);
  SmoothingParams params;
  params.slide_boundary = true;
  absl::StatusOr<SmoothingResult> result = Smooth(mesh, params);
  EXPECT_EQ(result.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(result.status().message().find("BoundarySlide"), std::string::npos) << result.status();
  params.fix_boundary = false;
  EXPECT_NE(params.Validate().message().find("slide_boundary"), std::string::npos);
  params = SmoothingParams();
  params.feature_angle_degrees = 181.0;
  EXPECT_EQ(params.Validate().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(params.Validate().message().find("feature_angle_degrees"), std::string::npos);
}

TEST(SurfaceSlideTest, SameBitsForEveryThreadCount) {
  std::vector<std::vector<double>> results;
  for (int threads : {1, 2, 3}) {
    Mesh mesh = DisplacedCube(5);
    absl::StatusOr<std::unique_ptr<SurfaceSlide>> slide = SurfaceSlide::Build(mesh);
    ASSERT_TRUE(slide.ok()) << slide.status();
    SmoothingParams params;
    params.threads = threads;
    params.slide_boundary = true;
    absl::StatusOr<SmoothingResult> result = Smooth(mesh, params, {}, nullptr, slide->get());
    ASSERT_TRUE(result.ok()) << result.status();
    std::vector<double> coordinates(mesh.x().begin(), mesh.x().end());
    coordinates.insert(coordinates.end(), mesh.y().begin(), mesh.y().end());
    coordinates.insert(coordinates.end(), mesh.z().begin(), mesh.z().end());
    results.push_back(std::move(coordinates));
  }
  EXPECT_EQ(results[1], results[0]);
  EXPECT_EQ(results[2], results[0]);
}

TEST(SurfaceSlideTest, EveryMethodKeepsTheBoundaryOnTheSurface) {
  for (Method method :
       {Method::kSmartLaplace, Method::kSimultaneous, Method::kSequential, Method::kGetme}) {
    Mesh mesh = DisplacedCube(7);
    const Mesh input = DisplacedCube(7);
    absl::StatusOr<std::unique_ptr<SurfaceSlide>> slide = SurfaceSlide::Build(mesh);
    ASSERT_TRUE(slide.ok()) << slide.status();
    SmoothingParams params;
    params.threads = 2;
    params.method = method;
    params.slide_boundary = true;
    absl::StatusOr<SmoothingResult> result = Smooth(mesh, params, {}, nullptr, slide->get());
    // Success includes the result check's own test: every sliding node on the input's surface.
    ASSERT_TRUE(result.ok()) << static_cast<int>(method) << ": " << result.status();
    for (NodeId node = 0; node < input.node_count(); ++node) {
      if (BoundCount(input, node) == 3) {
        EXPECT_EQ(mesh.x()[node], input.x()[node]);
        EXPECT_EQ(mesh.y()[node], input.y()[node]);
        EXPECT_EQ(mesh.z()[node], input.z()[node]);
      }
    }
  }
}

}  // namespace
}  // namespace getme::surface

namespace getme::surface {
namespace {

TEST(SurfaceSlideTest, TheWorstClusterStageMovesSlidingNodesAlongTheirFaces) {
  // The polish's worst-cluster stage called on the displaced cube with every interior node fixed,
  // so that the sliding boundary nodes are the only free ones: its L-BFGS moves them, along their
  // faces and edges (checked from the coordinates), and lifts q_min.
  Mesh mesh = DisplacedCube(11);
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    if (BoundCount(mesh, node) == 0) mesh.set_fixed(node, true);
  }
  const Mesh input = mesh;
  absl::StatusOr<std::unique_ptr<SurfaceSlide>> slide = SurfaceSlide::Build(mesh);
  ASSERT_TRUE(slide.ok()) << slide.status();
  SmoothingParams params;
  params.slide_boundary = true;
  ThreadPool pool(2);
  const ProgressCallback no_progress;
  SmoothingContext context(mesh, params, pool, no_progress, nullptr, slide->get());
  SmoothingContext::Summary current = context.Summarize();
  const double q_min_before = current.q_min;
  PhaseSummary summary{Phase::kPolish, 0, 0.0, 0.0, 0.0, 0};
  ASSERT_TRUE(RunWorstCluster(context, current, summary).ok());
  EXPECT_GT(current.q_min, q_min_before);
  EXPECT_EQ(current.invalid, 0);
  std::int64_t moved = 0;
  for (NodeId node = 0; node < input.node_count(); ++node) {
    const double in[3] = {input.x()[node], input.y()[node], input.z()[node]};
    const double out[3] = {mesh.x()[node], mesh.y()[node], mesh.z()[node]};
    for (int c = 0; c < 3; ++c) {
      if (OnBound(in[c]) || BoundCount(input, node) == 0) {
        EXPECT_NEAR(out[c], in[c], 1e-12) << "node " << node;
      }
    }
    moved += out[0] != in[0] || out[1] != in[1] || out[2] != in[2];
  }
  EXPECT_GT(moved, 0);
}

}  // namespace
}  // namespace getme::surface

namespace getme::surface {
namespace {

// The distance in the plane from (x, y) to the boundary of the regular `sides`-gon of radius 1
// around the origin (PolygonPrism's section), computed edge by edge.
double DistanceToPolygon(double x, double y, int sides) {
  double best = HUGE_VAL;
  for (int s = 0; s < sides; ++s) {
    const double a0 = 2.0 * M_PI * s / sides;
    const double a1 = 2.0 * M_PI * (s + 1) / sides;
    const double ax = std::cos(a0), ay = std::sin(a0);
    const double ex = std::cos(a1) - ax, ey = std::sin(a1) - ay;
    const double t = std::clamp(((x - ax) * ex + (y - ay) * ey) / (ex * ex + ey * ey), 0.0, 1.0);
    best = std::min(best, std::hypot(x - ax - t * ex, y - ay - t * ey));
  }
  return best;
}

TEST(SurfaceSlideTest, SlidingNeverLeavesTheSurfaceOfRandomBoxesAndCylinders) {
  // A property over random meshes: whatever the smoother does, every boundary node of a box
  // (meshgen's hybrid block, all four element types) stays on its face, and every node of a
  // faceted cylinder whose side nodes were moved up or down stays on the side facets or its cap;
  // both checked from the coordinates alone.
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    absl::StatusOr<Mesh> box = meshgen::HybridBlock(4, 4, 4, 0.3, seed);
    ASSERT_TRUE(box.ok());
    const Mesh box_input = *box;
    absl::StatusOr<std::unique_ptr<SurfaceSlide>> box_slide = SurfaceSlide::Build(*box);
    ASSERT_TRUE(box_slide.ok());
    SmoothingParams params;
    params.threads = 2;
    params.slide_boundary = true;
    ASSERT_TRUE(Smooth(*box, params, {}, nullptr, box_slide->get()).ok());
    for (NodeId node = 0; node < box_input.node_count(); ++node) {
      const double in[3] = {box_input.x()[node], box_input.y()[node], box_input.z()[node]};
      const double out[3] = {box->x()[node], box->y()[node], box->z()[node]};
      for (int c = 0; c < 3; ++c) {
        if (in[c] == 0.0 || in[c] == 4.0) {
          EXPECT_NEAR(out[c], in[c], 1e-12) << "node " << node;
        }
        EXPECT_GE(out[c], -1e-12);
        EXPECT_LE(out[c], 4.0 + 1e-12);
      }
    }

    constexpr int kSides = 16;
    constexpr double kHeight = 3.0;
    Mesh cylinder = test::PolygonPrism(kSides, 6, kHeight);
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> shift(-0.15, 0.15);
    for (double& z : cylinder.z()) {
      if (z > 0.0 && z < kHeight) z += shift(random);
    }
    const Mesh cylinder_input = cylinder;
    absl::StatusOr<std::unique_ptr<SurfaceSlide>> cylinder_slide = SurfaceSlide::Build(cylinder);
    ASSERT_TRUE(cylinder_slide.ok());
    ASSERT_TRUE(Smooth(cylinder, params, {}, nullptr, cylinder_slide->get()).ok());
    std::int64_t moved = 0;
    for (NodeId node = 0; node < cylinder_input.node_count(); ++node) {
      const double x_in = cylinder_input.x()[node], y_in = cylinder_input.y()[node];
      const double z_in = cylinder_input.z()[node];
      const double x = cylinder.x()[node], y = cylinder.y()[node], z = cylinder.z()[node];
      if (z_in == 0.0 || z_in == kHeight) {
        EXPECT_NEAR(z, z_in, 1e-12) << "node " << node;
      }
      if (std::hypot(x_in, y_in) > 0.5) {  // a rim node: on the side facets
        EXPECT_LE(DistanceToPolygon(x, y, kSides), 1e-12) << "node " << node;
        EXPECT_GE(z, -1e-12);
        EXPECT_LE(z, kHeight + 1e-12);
        moved += x != x_in || y != y_in || z != z_in;
      }
    }
    EXPECT_GT(moved, 0);
  }
}

// The tangent spaces the polish restricts a sliding node's Newton step to (issue 15): read from the
// node's boundary faces at their current corners, they span what the interface's default reads
// off three projections, and on a displaced cube they are the cube's faces and edges exactly.
TEST(SurfaceSlideTest, TangentSpacesAreTheFacesAndEdgesTheNodesSlideOn) {
  const Mesh cube = DisplacedCube(5);
  absl::StatusOr<std::unique_ptr<SurfaceSlide>> slide = SurfaceSlide::Build(cube);
  ASSERT_TRUE(slide.ok()) << slide.status();
  const auto projector = [](const std::array<Vec3, 2>& basis, int count) {
    Eigen::Matrix3d p = Eigen::Matrix3d::Zero();
    for (int k = 0; k < count; ++k) p += basis[k] * basis[k].transpose();
    return p;
  };
  int checked[3] = {0, 0, 0};
  for (NodeId node = 0; node < cube.node_count(); ++node) {
    if (!(*slide)->Slides(node)) continue;
    std::array<Vec3, 2> basis, reference;
    const int count = (*slide)->TangentSpace(cube, node, basis);
    const int reference_count = (*slide)->BoundarySlide::TangentSpace(cube, node, reference);
    // One coordinate on the cube's bounds: a face (two directions); two: an edge (one).
    const int bounds = BoundCount(cube, node);
    ASSERT_EQ(count, 3 - bounds) << "node " << node;
    ASSERT_EQ(reference_count, count) << "node " << node;
    for (int k = 0; k < count; ++k) {
      EXPECT_NEAR(basis[k].norm(), 1.0, 1e-12);
      for (int axis = 0; axis < 3; ++axis) {
        const double c = axis == 0 ? cube.x()[node] : axis == 1 ? cube.y()[node] : cube.z()[node];
        // No component across a bound the node lies on.
        if (OnBound(c)) {
          EXPECT_NEAR(basis[k][axis], 0.0, 1e-12) << "node " << node;
        }
      }
    }
    if (count == 2) {
      EXPECT_NEAR(basis[0].dot(basis[1]), 0.0, 1e-12);
    }
    EXPECT_LE((projector(basis, count) - projector(reference, count)).norm(), 1e-6)
        << "node " << node;
    ++checked[count];
  }
  EXPECT_GT(checked[1], 0);
  EXPECT_GT(checked[2], 0);
}

}  // namespace
}  // namespace getme::surface
