// The sliding nodes' own triangle lists (surface/getme_surface/node_triangles.h) against a
// brute-force search over every triangle of the surface, on a faceted sphere and a faceted
// cylinder. Nodes walk as the smoothers move them: each step starts from where the node is (a
// point of the surface) and goes back to the surface. Steps of every length up to more than a
// list's reach are taken, so the lists answer some queries and must refuse others; an answer
// must be the nearest point of the whole surface, wherever the walk has taken the node.

#include "getme_surface/node_triangles.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "brute_force_nearest.h"
#include "getme_surface/surface_projector.h"
#include "surface_test_meshes.h"

namespace getme::surface {
namespace {

using test::BruteForceDistance;
using test::Triangle3;

struct Walks {
  std::int64_t answered = 0;
  std::int64_t refused = 0;
};

Walks WalkEveryNode(const Mesh& mesh, double longest_step) {
  Walks walks;
  const auto at = [&](NodeId n) { return Vec3(mesh.x()[n], mesh.y()[n], mesh.z()[n]); };
  absl::StatusOr<BoundarySurface> surface = ExtractBoundarySurface(mesh);
  EXPECT_TRUE(surface.ok()) << surface.status();
  absl::StatusOr<SurfaceProjector> projector = SurfaceProjector::Build(mesh, *surface);
  EXPECT_TRUE(projector.ok()) << projector.status();
  if (!surface.ok() || !projector.ok()) return walks;

  std::vector<std::vector<std::int64_t>> faces_of(static_cast<std::size_t>(mesh.node_count()));
  std::vector<Triangle3> triangles;
  for (std::size_t f = 0; f < surface->faces.size(); ++f) {
    const BoundaryFace& face = surface->faces[f];
    for (int k = 0; k < face.size; ++k) faces_of[face.nodes[k]].push_back(std::int64_t(f));
    triangles.push_back({at(face.nodes[0]), at(face.nodes[1]), at(face.nodes[2])});
    if (face.size == 4)
      triangles.push_back({at(face.nodes[0]), at(face.nodes[2]), at(face.nodes[3])});
  }
  std::vector<std::int64_t> offsets = {0}, flat;
  std::vector<bool> listed(static_cast<std::size_t>(mesh.node_count()), false);
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    flat.insert(flat.end(), faces_of[node].begin(), faces_of[node].end());
    offsets.push_back(static_cast<std::int64_t>(flat.size()));
    listed[node] = surface->kind[node] == BoundaryNodeKind::kSurface;
  }
  const NodeTriangles lists(mesh, *surface, projector->group_grids(), listed, offsets, flat);
  EXPECT_GT(lists.listed_nodes(), 0);

  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> length(0.0, longest_step);
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    if (!listed[node]) continue;
    const TriangleGrid& grid = projector->group_grids()[surface->support[node]];
    Vec3 position = at(node);
    for (int step = 0; step < 40; ++step) {
      const Vec3 direction = Vec3(unit(random), unit(random), unit(random)).normalized();
      const Vec3 moved = position + length(random) * direction;
      const std::optional<Vec3> nearest = lists.Nearest(grid, node, moved, position);
      const double expected = BruteForceDistance(moved, triangles);
      if (!nearest) {
        ++walks.refused;
        position = projector->OnGroup(surface->support[node], moved, &position);
        continue;
      }
      ++walks.answered;
      EXPECT_NEAR((*nearest - moved).norm(), expected, 1e-12 * (1.0 + expected))
          << "node " << node << ", step " << step;
      EXPECT_LE(BruteForceDistance(*nearest, triangles), 1e-12) << "node " << node;
      position = *nearest;
    }
  }
  return walks;
}

// The sphere's 80 faces meet at less than the feature angle: every boundary node is a surface
// node of one group. Steps of up to 0.15 (an edge is about 0.55) take half the walks' queries out
// of the lists' reach.
TEST(NodeTrianglesTest, AnswersOnAFacetedSphereAreTheNearestPointsOfTheWholeSurface) {
  const Walks walks = WalkEveryNode(test::FacetedSphere(), 0.15);
  EXPECT_GT(walks.answered, 400);
  EXPECT_GT(walks.refused, 400);
}

// The cylinder's side nodes are surface nodes between two feature rims; its caps are planes.
// Steps of up to 0.25 (a layer is 0.5 high) take two thirds of the queries out of reach.
TEST(NodeTrianglesTest, AnswersOnAFacetedCylinderAreTheNearestPointsOfTheWholeSurface) {
  const Walks walks = WalkEveryNode(test::PolygonPrism(12, 4, 2.0), 0.25);
  EXPECT_GT(walks.answered, 200);
  EXPECT_GT(walks.refused, 500);
}

}  // namespace
}  // namespace getme::surface
