// Nearest points on the input's boundary (surface/getme_surface/surface_projector.h) against an
// independent brute-force search over every boundary triangle, on a faceted sphere and a faceted
// cylinder; feature nodes go to their curve, corners and interior nodes stay.

#include "getme_surface/surface_projector.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <thread>
#include <vector>

#include "brute_force_nearest.h"
#include "surface_test_meshes.h"

namespace getme::surface {
namespace {

using test::BruteForceDistance;
using test::Triangle3;

std::vector<Triangle3> Triangles(const Mesh& mesh, const BoundarySurface& surface, int group) {
  const auto at = [&](NodeId n) { return Vec3(mesh.x()[n], mesh.y()[n], mesh.z()[n]); };
  std::vector<Triangle3> triangles;
  for (const BoundaryFace& face : surface.faces) {
    if (group >= 0 && face.group != group) continue;
    // Any split of a planar quad covers it; these test meshes have planar quads only.
    triangles.push_back({at(face.nodes[0]), at(face.nodes[1]), at(face.nodes[2])});
    if (face.size == 4)
      triangles.push_back({at(face.nodes[0]), at(face.nodes[2]), at(face.nodes[3])});
  }
  return triangles;
}

void ExpectNearestAgreesWithBruteForce(const Mesh& mesh, double spread) {
  absl::StatusOr<BoundarySurface> surface = ExtractBoundarySurface(mesh);
  ASSERT_TRUE(surface.ok()) << surface.status();
  absl::StatusOr<SurfaceProjector> projector = SurfaceProjector::Build(mesh, *surface);
  ASSERT_TRUE(projector.ok()) << projector.status();
  const std::vector<Triangle3> triangles = Triangles(mesh, *surface, 0);
  // A boundary node, a different one each trial: a point of the surface to start a search from.
  std::vector<NodeId> boundary_nodes;
  for (const BoundaryFace& face : surface->faces) {
    boundary_nodes.insert(boundary_nodes.end(), face.nodes.begin(), face.nodes.begin() + face.size);
  }
  const auto mesh_point = [&](int trial) {
    const NodeId node =
        boundary_nodes[static_cast<std::size_t>(trial * 7919) % boundary_nodes.size()];
    return Vec3(mesh.x()[node], mesh.y()[node], mesh.z()[node]);
  };
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> coordinate(-spread, spread);
  for (int trial = 0; trial < 500; ++trial) {
    const Vec3 p(coordinate(random), coordinate(random), coordinate(random));
    const Vec3 nearest = projector->OnGroup(0, p);
    const double expected = BruteForceDistance(p, triangles);
    // The point found is as near as the nearest point of any triangle...
    EXPECT_NEAR((nearest - p).norm(), expected, 1e-12 * (1.0 + expected)) << "trial " << trial;
    // ...and lies on the surface.
    EXPECT_LE(BruteForceDistance(nearest, triangles), 1e-12) << "trial " << trial;
    EXPECT_NEAR(projector->DistanceToSurface(p), expected, 1e-12 * (1.0 + expected));
    // Started from a point of the surface (as a sliding node's move starts from where it was),
    // the search finds an equally near point, whichever point that is.
    const Vec3 start = mesh_point(trial);
    const Vec3 from_start = projector->OnGroup(0, p, &start);
    EXPECT_NEAR((from_start - p).norm(), expected, 1e-12 * (1.0 + expected)) << "trial " << trial;
    EXPECT_LE(BruteForceDistance(from_start, triangles), 1e-12) << "trial " << trial;
    // A short move from a point of the surface, as the smoothers make (the projector's grid
    // answers these; the tree the long ones above): the nearest point again, on the surface,
    // whose distance to the surface is zero.
    const Vec3 short_move = start + 0.02 * (p - start).normalized();
    const Vec3 after_short = projector->OnGroup(0, short_move, &start);
    const double short_expected = BruteForceDistance(short_move, triangles);
    EXPECT_NEAR((after_short - short_move).norm(), short_expected, 1e-12 * (1.0 + short_expected))
        << "trial " << trial;
    EXPECT_LE(BruteForceDistance(after_short, triangles), 1e-12) << "trial " << trial;
    EXPECT_LE(projector->DistanceToSurface(after_short), 1e-12) << "trial " << trial;
  }
}

TEST(SurfaceProjectorTest, NearestPointOnAFacetedSphereMatchesBruteForce) {
  ExpectNearestAgreesWithBruteForce(test::FacetedSphere(), 1.5);
}

TEST(SurfaceProjectorTest, NearestPointOnAFacetedCylinderMatchesBruteForce) {
  ExpectNearestAgreesWithBruteForce(test::PolygonPrism(12, 2, 1.5), 2.0);
}

TEST(SurfaceProjectorTest, FeatureNodesGoToTheirCurveCornersAndInteriorNodesStay) {
  const Mesh mesh = test::HexCube(3);
  absl::StatusOr<BoundarySurface> surface = ExtractBoundarySurface(mesh);
  ASSERT_TRUE(surface.ok()) << surface.status();
  absl::StatusOr<SurfaceProjector> projector = SurfaceProjector::Build(mesh, *surface);
  ASSERT_TRUE(projector.ok()) << projector.status();
  EXPECT_EQ(projector->group_count(), 1);
  EXPECT_EQ(projector->curve_count(), 12);
  const auto id = [](int i, int j, int k) { return i + 4 * (j + 4 * k); };
  // Node (1, 0, 0) lies on the cube edge y = z = 0: displaced anywhere, it comes back to that
  // edge (y = z = 0), at the displaced point's x clamped to the edge's [0, 3].
  const NodeId feature = id(1, 0, 0);
  ASSERT_EQ(surface->kind[feature], BoundaryNodeKind::kFeature);
  for (const Vec3& moved : {Vec3(1.3, 0.2, -0.1), Vec3(-0.5, 0.4, 0.3), Vec3(2.2, -0.3, 0.6)}) {
    const Vec3 back =
        projector->Project(BoundaryNodeKind::kFeature, surface->support[feature], moved);
    EXPECT_EQ(back[1], 0.0);
    EXPECT_EQ(back[2], 0.0);
    EXPECT_NEAR(back[0], std::clamp(moved[0], 0.0, 3.0), 1e-15);
  }
  // A node on the top face (z = 3) comes back to z = 3.
  const NodeId top = id(1, 2, 3);
  ASSERT_EQ(surface->kind[top], BoundaryNodeKind::kSurface);
  const Vec3 back = projector->Project(BoundaryNodeKind::kSurface, 0, Vec3(1.2, 1.9, 3.4));
  EXPECT_NEAR((back - Vec3(1.2, 1.9, 3.0)).norm(), 0.0, 1e-15);
  // Corners and interior nodes are not moved by the projector.
  const Vec3 anywhere(0.1, 0.2, 0.3);
  EXPECT_EQ(projector->Project(BoundaryNodeKind::kCorner, -1, anywhere), anywhere);
  EXPECT_EQ(projector->Project(BoundaryNodeKind::kInterior, -1, anywhere), anywhere);
}

// The trees are built at their first query, by whichever thread asks first (std::call_once):
// threads that all ask at once get the answers one thread gets alone. ThreadSanitizer checks the
// build's publication in the sanitizer runs.
TEST(SurfaceProjectorTest, ThreadsAskingAtOnceGetTheAnswersOfOneThread) {
  const Mesh mesh = test::FacetedSphere();
  absl::StatusOr<BoundarySurface> surface = ExtractBoundarySurface(mesh);
  ASSERT_TRUE(surface.ok()) << surface.status();
  std::vector<Vec3> points;
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
  for (int i = 0; i < 200; ++i) {
    points.emplace_back(coordinate(random), coordinate(random), coordinate(random));
  }
  absl::StatusOr<SurfaceProjector> alone = SurfaceProjector::Build(mesh, *surface);
  ASSERT_TRUE(alone.ok()) << alone.status();
  std::vector<Vec3> expected;
  for (const Vec3& p : points) expected.push_back(alone->OnGroup(0, p));

  absl::StatusOr<SurfaceProjector> shared = SurfaceProjector::Build(mesh, *surface);
  ASSERT_TRUE(shared.ok()) << shared.status();
  constexpr int kThreads = 4;
  std::vector<std::vector<Vec3>> answers(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (const Vec3& p : points) answers[t].push_back(shared->OnGroup(0, p));
      for (const Vec3& p : points)
        answers[t].push_back(Vec3::Constant(shared->DistanceToSurface(p)));
    });
  }
  for (std::thread& thread : threads) thread.join();
  for (int t = 0; t < kThreads; ++t) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      EXPECT_EQ(answers[t][i], expected[i]) << "thread " << t << ", point " << i;
      EXPECT_EQ(answers[t][points.size() + i][0], alone->DistanceToSurface(points[i]));
    }
  }
}

TEST(SurfaceProjectorTest, ASurfaceOfAnotherMeshIsRefused) {
  const Mesh mesh = test::HexCube(2);
  absl::StatusOr<BoundarySurface> surface = ExtractBoundarySurface(test::HexCube(3));
  ASSERT_TRUE(surface.ok()) << surface.status();
  absl::StatusOr<SurfaceProjector> projector = SurfaceProjector::Build(mesh, *surface);
  EXPECT_EQ(projector.status().code(), absl::StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace getme::surface
