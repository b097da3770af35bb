#include "getme/meshgen/cube_fill.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "mesh_checks.h"

namespace getme::meshgen {
namespace {

using ::getme::NodePosition;
using ::getme::testing::CensusFaces;
using ::getme::testing::FaceArea;
using ::getme::testing::InvalidElements;

struct HandCase {
  const char* name;
  CubeFillGrid grid;
  std::int64_t hexahedra, pyramids, tetrahedra, nodes;
};

// Counts derived by hand from the fill rules (cube_fill.h).
std::vector<HandCase> HandCases() {
  std::vector<HandCase> cases;
  // hex | tets | hex in a row: the middle cube keeps pyramids towards both hexahedra and splits
  // its other four faces; 4·2·2 grid points and one centre.
  CubeFillGrid row(3, 1, 1, CubeFill::kHexahedron);
  row.set(1, 0, 0, CubeFill::kCentredTets);
  cases.push_back({"hex-tets-hex", row, 2, 2, 8, 16 + 1});
  // 2×2×2 centred-tet cubes: 12 tetrahedra each, 27 grid points and 8 centres.
  cases.push_back({"all tets", CubeFillGrid(2, 2, 2, CubeFill::kCentredTets), 0, 0, 96, 27 + 8});
  // 3×3×3 hexahedra around an empty centre: 26 hexahedra, all 64 grid points used.
  CubeFillGrid hollow(3, 3, 3, CubeFill::kHexahedron);
  hollow.set(1, 1, 1, CubeFill::kEmpty);
  cases.push_back({"hollow hex", hollow, 26, 0, 0, 64});
  // 3×3×3 centred-tet cubes around a hexahedron: six pyramids face it, 26·12 − 2·6 tetrahedra.
  CubeFillGrid core(3, 3, 3, CubeFill::kCentredTets);
  core.set(1, 1, 1, CubeFill::kHexahedron);
  cases.push_back({"hex core", core, 1, 6, 300, 64 + 26});
  // A 2×2×1 grid with empty cubes on one diagonal, so the two hexahedra meet along an edge only:
  // its 3·3·2 grid points except the two outer corners of each empty cube.
  CubeFillGrid diagonal(2, 2, 1, CubeFill::kHexahedron);
  diagonal.set(0, 0, 0, CubeFill::kEmpty);
  diagonal.set(1, 1, 0, CubeFill::kEmpty);
  cases.push_back({"edge-touching holes", diagonal, 2, 0, 0, 18 - 4});
  return cases;
}

TEST(CubeFillTest, CountsMatchTheRulesAndTheBuiltMesh) {
  for (const HandCase& c : HandCases()) {
    SCOPED_TRACE(c.name);
    const CubeFillCounts counts = CountCubeFill(c.grid);
    EXPECT_EQ(counts.hexahedra, c.hexahedra);
    EXPECT_EQ(counts.pyramids, c.pyramids);
    EXPECT_EQ(counts.tetrahedra, c.tetrahedra);
    EXPECT_EQ(counts.nodes, c.nodes);
    absl::StatusOr<Mesh> mesh = MeshCubeFill(c.grid, 0.0, 1);
    ASSERT_TRUE(mesh.ok()) << mesh.status();
    EXPECT_EQ(mesh->element_count(ElementType::kHexahedron), c.hexahedra);
    EXPECT_EQ(mesh->element_count(ElementType::kPyramid), c.pyramids);
    EXPECT_EQ(mesh->element_count(ElementType::kTetrahedron), c.tetrahedra);
    EXPECT_EQ(mesh->node_count(), c.nodes);
  }
}

CubeFillGrid RandomFill(int nx, int ny, int nz, std::uint64_t seed) {
  std::mt19937_64 engine(seed);
  CubeFillGrid grid(nx, ny, nz, CubeFill::kEmpty);
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) grid.set(i, j, k, static_cast<CubeFill>(engine() % 3));
    }
  }
  return grid;
}

// Cube faces between a filled cube and an empty one or the outside: the boundary area that a
// conforming mesh of the fill must have.
std::int64_t FilledEmptyFaces(const CubeFillGrid& grid) {
  std::int64_t faces = 0;
  constexpr std::array<std::array<int, 3>, 6> kSteps = {
      {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
  for (int k = 0; k < grid.nz(); ++k) {
    for (int j = 0; j < grid.ny(); ++j) {
      for (int i = 0; i < grid.nx(); ++i) {
        if (grid.at(i, j, k) == CubeFill::kEmpty) continue;
        for (const auto& s : kSteps) {
          faces += grid.at(i + s[0], j + s[1], k + s[2]) == CubeFill::kEmpty;
        }
      }
    }
  }
  return faces;
}

// Any mix of empty, hexahedron and centred-tet cubes, holes touching at edges and corners
// included, gives a valid conforming mesh whose boundary is exactly the filled/empty interface.
TEST(CubeFillTest, RandomFillsConformAndTheirBoundaryIsTheFilledEmptyInterface) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    const CubeFillGrid grid = RandomFill(5, 4, 3, seed);
    absl::StatusOr<Mesh> mesh = MeshCubeFill(grid, 0.0, seed);
    ASSERT_TRUE(mesh.ok()) << mesh.status();
    EXPECT_TRUE(InvalidElements(*mesh).empty());
    std::int64_t shared = 0, boundary = 0;
    double boundary_area = 0.0;
    for (const auto& [key, use] : CensusFaces(*mesh)) {
      ASSERT_LE(use.elements.size(), 2u);
      if (use.elements.size() == 2) {
        ++shared;
        continue;
      }
      ++boundary;
      boundary_area += FaceArea(*mesh, use.nodes);
      // A boundary face lies in a grid plane: all its nodes share one integer coordinate.
      bool in_grid_plane = false;
      for (int axis = 0; axis < 3; ++axis) {
        const double value = NodePosition(*mesh, use.nodes[0])[axis];
        bool same = value == std::round(value);
        for (const NodeId node : use.nodes) same &= NodePosition(*mesh, node)[axis] == value;
        in_grid_plane |= same;
      }
      EXPECT_TRUE(in_grid_plane);
    }
    EXPECT_NEAR(boundary_area, static_cast<double>(FilledEmptyFaces(grid)), 1e-9);
    const CubeFillCounts counts = CountCubeFill(grid);
    EXPECT_EQ(2 * shared + boundary,
              6 * counts.hexahedra + 5 * counts.pyramids + 4 * counts.tetrahedra);
  }
}

TEST(CubeFillTest, DistortionMovesOnlyNodesOffTheBoundaryAndKeepsElementsValid) {
  CubeFillGrid grid(6, 5, 4, CubeFill::kCentredTets);
  for (int i = 1; i < 4; ++i) grid.set(i, 2, 2, CubeFill::kHexahedron);
  grid.set(3, 3, 1, CubeFill::kEmpty);  // an inner hole
  absl::StatusOr<Mesh> regular = MeshCubeFill(grid, 0.0, 3);
  absl::StatusOr<Mesh> distorted = MeshCubeFill(grid, 0.4, 3);
  ASSERT_TRUE(regular.ok() && distorted.ok());
  EXPECT_TRUE(InvalidElements(*distorted).empty());
  ASSERT_EQ(regular->node_count(), distorted->node_count());
  std::int64_t moved = 0;
  for (NodeId node = 0; node < regular->node_count(); ++node) {
    const Vec3 before = NodePosition(*regular, node);
    const Vec3 after = NodePosition(*distorted, node);
    if (regular->is_boundary(node)) {
      EXPECT_EQ(before, after) << "boundary node " << node;
    } else {
      moved += before != after;
      // Grid points move up to 0.4 per axis, centres (at half-integers) up to 0.2.
      const bool centre = before.x() != std::round(before.x());
      EXPECT_LE((after - before).lpNorm<Eigen::Infinity>(), centre ? 0.2 : 0.4) << node;
    }
  }
  EXPECT_GT(moved, 0);
  // The hole's walls are boundary: the eight corners of cube (3, 3, 1) are boundary nodes.
  std::int64_t hole_corners = 0;
  for (NodeId node = 0; node < regular->node_count(); ++node) {
    const Vec3 p = NodePosition(*regular, node);
    const bool corner =
        (p.x() == 3 || p.x() == 4) && (p.y() == 3 || p.y() == 4) && (p.z() == 1 || p.z() == 2);
    if (corner) hole_corners += regular->is_boundary(node);
  }
  EXPECT_EQ(hole_corners, 8);
}

// Nodes come layer by layer (grid points of layer k, then the centres above them), so an
// element's nodes are close in memory: z never decreases along the node ids.
TEST(CubeFillTest, NodeIdsFollowTheLayers) {
  absl::StatusOr<Mesh> mesh = MeshCubeFill(RandomFill(4, 4, 5, 9), 0.0, 1);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  for (NodeId node = 1; node < mesh->node_count(); ++node) {
    ASSERT_LE(mesh->z()[node - 1], mesh->z()[node]) << "node " << node;
  }
}

TEST(CubeFillTest, SameSeedSameMeshOtherSeedOtherCoordinates) {
  const CubeFillGrid grid = RandomFill(5, 5, 4, 2);
  absl::StatusOr<Mesh> a = MeshCubeFill(grid, 0.3, 11);
  absl::StatusOr<Mesh> b = MeshCubeFill(grid, 0.3, 11);
  absl::StatusOr<Mesh> c = MeshCubeFill(grid, 0.3, 12);
  ASSERT_TRUE(a.ok() && b.ok() && c.ok());
  EXPECT_TRUE(std::ranges::equal(a->x(), b->x()));
  EXPECT_TRUE(std::ranges::equal(a->y(), b->y()));
  EXPECT_TRUE(std::ranges::equal(a->z(), b->z()));
  EXPECT_FALSE(std::ranges::equal(a->x(), c->x()));
}

TEST(CubeFillTest, RejectsEmptyGridsAndBadDistortions) {
  EXPECT_EQ(MeshCubeFill(CubeFillGrid(2, 2, 2, CubeFill::kEmpty), 0.1, 1).status().code(),
            absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(MeshCubeFill(CubeFillGrid(2, 2, 2, CubeFill::kHexahedron), -0.1, 1).status().code(),
            absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(MeshCubeFill(CubeFillGrid(0, 2, 2, CubeFill::kHexahedron), 0.1, 1).status().code(),
            absl::StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace getme::meshgen
