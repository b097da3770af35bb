// The input's boundary surface (surface/getme_surface/boundary_surface.h) on meshes whose answer is
// known: a cube of hexahedra and one of tetrahedra (12 feature edges, 8 corners), a face split
// into two groups, a faceted cylinder (closed feature curves without corners, or every side edge
// a feature below its facet angle), and the errors for bad groups and angles.

#include "getme_surface/boundary_surface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "getme/meshgen/jittered_tet_block.h"
#include "surface_test_meshes.h"

namespace getme::surface {
namespace {

std::int64_t CountKind(const BoundarySurface& surface, BoundaryNodeKind kind) {
  return std::count(surface.kind.begin(), surface.kind.end(), kind);
}

// On a cube [0, n]³: a node is a corner with three coordinates on {0, n}, on a feature edge with
// two, on a face with one.
int CoordinatesOnTheBoundary(const Mesh& mesh, NodeId node, double n) {
  int count = 0;
  for (double c : {mesh.x()[node], mesh.y()[node], mesh.z()[node]}) {
    count += c == 0.0 || c == n ? 1 : 0;
  }
  return count;
}

void ExpectCubeClassification(const Mesh& mesh, const BoundarySurface& surface, double n) {
  // 12 edges of n segments each, one curve per cube edge between two corners.
  EXPECT_EQ(surface.feature_edges.size(), 12u * static_cast<std::size_t>(n));
  EXPECT_EQ(surface.curve_count, 12);
  EXPECT_EQ(surface.corner_count, 8);
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    const BoundaryNodeKind expected[] = {BoundaryNodeKind::kInterior, BoundaryNodeKind::kSurface,
                                         BoundaryNodeKind::kFeature, BoundaryNodeKind::kCorner};
    ASSERT_EQ(surface.kind[node], expected[CoordinatesOnTheBoundary(mesh, node, n)])
        << "node " << node;
  }
  // Each feature edge joins two nodes that share two boundary coordinates (the same cube edge).
  for (std::size_t e = 0; e < surface.feature_edges.size(); ++e) {
    const auto [a, b] = surface.feature_edges[e];
    int shared = 0;
    for (auto coordinate : {mesh.x(), mesh.y(), mesh.z()}) {
      const double ca = coordinate[a];
      shared += (ca == 0.0 || ca == n) && coordinate[b] == ca ? 1 : 0;
    }
    EXPECT_EQ(shared, 2) << "feature edge " << a << "-" << b;
  }
}

TEST(BoundarySurfaceTest, HexCubeHasTwelveFeatureCurvesAndEightCorners) {
  const Mesh mesh = test::HexCube(3);
  absl::StatusOr<BoundarySurface> surface = ExtractBoundarySurface(mesh);
  ASSERT_TRUE(surface.ok()) << surface.status();
  EXPECT_EQ(surface->faces.size(), 54u);
  EXPECT_EQ(mesh.boundary_face_count(), 54);
  EXPECT_EQ(surface->group_count, 1);
  ExpectCubeClassification(mesh, *surface, 3.0);
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    if (surface->kind[node] == BoundaryNodeKind::kSurface) {
      EXPECT_EQ(surface->support[node], 0);
    }
  }
}

TEST(BoundarySurfaceTest, TetCubeHasTheSameFeaturesAsTheHexCube) {
  // Coplanar triangles on each side meet at 0°, so only the cube's edges are features.
  absl::StatusOr<Mesh> mesh = meshgen::JitteredTetBlock(4, 4, 4, 0.0, 1);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  absl::StatusOr<BoundarySurface> surface = ExtractBoundarySurface(*mesh);
  ASSERT_TRUE(surface.ok()) << surface.status();
  double n = 0.0;
  for (NodeId node = 0; node < mesh->node_count(); ++node) n = std::max(n, mesh->x()[node]);
  ExpectCubeClassification(*mesh, *surface, n);
}

TEST(BoundarySurfaceTest, TwoGroupsOnOnePlaneMeetAtAFeatureCurve) {
  // The top of HexCube(3) (z = 3): the faces with x < 1 in group 1, the others in group 2, the
  // remaining sides in group 0. The line x = 1 on top becomes a feature curve of 3 edges, and its
  // ends, where it meets the cube's top edges, become corners that split those edges' curves.
  const Mesh mesh = test::HexCube(3);
  std::vector<GroupedFace> groups;
  const auto id = [](int i, int j, int k) { return i + 4 * (j + 4 * k); };
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) {
      groups.push_back(
          {{id(i, j, 3), id(i + 1, j, 3), id(i + 1, j + 1, 3), id(i, j + 1, 3)}, 4, i < 1 ? 1 : 2});
    }
  }
  absl::StatusOr<BoundarySurface> surface = ExtractBoundarySurface(mesh, groups);
  ASSERT_TRUE(surface.ok()) << surface.status();
  EXPECT_EQ(surface->group_count, 3);
  EXPECT_EQ(surface->feature_edges.size(), 36u + 3u);
  EXPECT_EQ(surface->corner_count, 10);
  EXPECT_EQ(surface->curve_count, 12 + 2 + 1);
  EXPECT_EQ(surface->kind[id(1, 0, 3)], BoundaryNodeKind::kCorner);
  EXPECT_EQ(surface->kind[id(1, 3, 3)], BoundaryNodeKind::kCorner);
  EXPECT_EQ(surface->kind[id(1, 1, 3)], BoundaryNodeKind::kFeature);
  EXPECT_EQ(surface->kind[id(2, 1, 3)], BoundaryNodeKind::kSurface);
  EXPECT_EQ(surface->support[id(2, 1, 3)], 2);
  EXPECT_EQ(surface->support[id(1, 1, 1)], -1);  // interior
  // Both nodes of the group line lie on one curve.
  EXPECT_EQ(surface->support[id(1, 1, 3)], surface->support[id(1, 2, 3)]);
}

TEST(BoundarySurfaceTest, FacetedCylinderHasTwoClosedRimCurves) {
  // 16 sides: neighbouring side faces meet at 22.5°, below the default 45°; the rims (90°) are two
  // closed curves with no corner. Below 22.5° every side edge is a feature as well, and every rim
  // node, on three feature edges, a corner.
  const Mesh mesh = test::PolygonPrism(16, 3, 2.0);
  absl::StatusOr<BoundarySurface> surface = ExtractBoundarySurface(mesh);
  ASSERT_TRUE(surface.ok()) << surface.status();
  EXPECT_EQ(surface->feature_edges.size(), 32u);
  EXPECT_EQ(surface->curve_count, 2);
  EXPECT_EQ(surface->corner_count, 0);
  EXPECT_EQ(CountKind(*surface, BoundaryNodeKind::kFeature), 32);

  absl::StatusOr<BoundarySurface> sharp = ExtractBoundarySurface(mesh, {}, 20.0);
  ASSERT_TRUE(sharp.ok()) << sharp.status();
  EXPECT_EQ(sharp->feature_edges.size(), 32u + 16u * 3u);
  EXPECT_EQ(sharp->corner_count, 32);
  EXPECT_EQ(CountKind(*sharp, BoundaryNodeKind::kFeature), 16 * 2);  // side nodes between rims
}

TEST(BoundarySurfaceTest, BadGroupsAndAnglesAreNamed) {
  const Mesh mesh = test::HexCube(2);
  // Nodes 0, 1, 2 lie on one grid line: with 5 they are no face of any element.
  const std::vector<GroupedFace> not_a_face = {{{0, 1, 2, 5}, 4, 1}};
  absl::StatusOr<BoundarySurface> surface = ExtractBoundarySurface(mesh, not_a_face);
  EXPECT_EQ(surface.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(surface.status().message().find("grouped face 0 {0, 1, 2, 5}"), std::string::npos)
      << surface.status();
  // An interior face (x = 1, between the first two hexahedra) is no boundary face either; the
  // bottom quad 0-1-4-3 is one, but a group must not be negative.
  const std::vector<GroupedFace> interior = {{{1, 4, 13, 10}, 4, 1}};
  surface = ExtractBoundarySurface(mesh, interior);
  EXPECT_EQ(surface.status().code(), absl::StatusCode::kInvalidArgument);
  const std::vector<GroupedFace> negative = {{{0, 1, 4, 3}, 4, -2}};
  surface = ExtractBoundarySurface(mesh, negative);
  EXPECT_NE(surface.status().message().find("group -2"), std::string::npos) << surface.status();
  surface = ExtractBoundarySurface(mesh, {}, 200.0);
  EXPECT_EQ(surface.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(surface.status().message().find("feature_angle_degrees"), std::string::npos);
}

}  // namespace
}  // namespace getme::surface
