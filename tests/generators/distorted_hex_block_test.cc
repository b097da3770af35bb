#include "getme/meshgen/distorted_hex_block.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mesh_checks.h"

namespace getme::meshgen {
namespace {

using ::getme::testing::CheckBlockFaces;
using ::getme::testing::InvalidElements;
using ::getme::testing::MeanRatios;

TEST(DistortedHexBlockTest, HasOneHexahedronPerCubeAndAGridOfNodes) {
  absl::StatusOr<Mesh> mesh = DistortedHexBlock(5, 4, 3, 0.3, 7);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EXPECT_EQ(mesh->element_count(), 5 * 4 * 3);
  EXPECT_EQ(mesh->element_count(ElementType::kHexahedron), 5 * 4 * 3);
  EXPECT_EQ(mesh->node_count(), 6 * 5 * 4);
}

TEST(DistortedHexBlockTest, EveryElementIsValidEvenForLargeDistortion) {
  for (const double distortion : {0.3, 0.6, 2.0}) {
    absl::StatusOr<Mesh> mesh = DistortedHexBlock(6, 6, 6, distortion, 11);
    ASSERT_TRUE(mesh.ok()) << mesh.status();
    EXPECT_TRUE(InvalidElements(*mesh).empty()) << "distortion " << distortion;
  }
}

TEST(DistortedHexBlockTest, FacesConformAndTheBoundaryIsTheBox) {
  absl::StatusOr<Mesh> mesh = DistortedHexBlock(4, 5, 6, 0.4, 3);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const auto report = CheckBlockFaces(*mesh, 4, 5, 6);
  EXPECT_EQ(report.overused_faces, 0);
  EXPECT_EQ(report.inner_boundary_faces, 0);
  // Each cube has 6 faces: interior faces are counted by two cubes, box faces by one.
  const int box_faces = 2 * (4 * 5 + 5 * 6 + 6 * 4);
  EXPECT_EQ(report.boundary_faces, box_faces);
  EXPECT_EQ(report.shared_faces, (6 * 4 * 5 * 6 - box_faces) / 2);
  EXPECT_NEAR(report.boundary_area, box_faces, 1e-9);
}

TEST(DistortedHexBlockTest, MovesInteriorNodesWithinTheDistortionAndKeepsBoundaryNodes) {
  constexpr double kDistortion = 0.35;
  absl::StatusOr<Mesh> mesh = DistortedHexBlock(5, 5, 5, kDistortion, 5);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  int moved = 0, interior = 0;
  for (int k = 0; k <= 5; ++k) {
    for (int j = 0; j <= 5; ++j) {
      for (int i = 0; i <= 5; ++i) {
        const NodeId node = i + 6 * (j + 6 * k);
        const double dx = mesh->x()[node] - i, dy = mesh->y()[node] - j, dz = mesh->z()[node] - k;
        const bool boundary = i == 0 || j == 0 || k == 0 || i == 5 || j == 5 || k == 5;
        if (boundary) {
          EXPECT_EQ(dx, 0.0);
          EXPECT_EQ(dy, 0.0);
          EXPECT_EQ(dz, 0.0);
          continue;
        }
        ++interior;
        EXPECT_LE(std::max({std::abs(dx), std::abs(dy), std::abs(dz)}), kDistortion);
        if (dx != 0.0 || dy != 0.0 || dz != 0.0) ++moved;
      }
    }
  }
  EXPECT_EQ(interior, 64);
  EXPECT_GE(moved, 60);
  const std::vector<double> q = MeanRatios(*mesh);
  EXPECT_LT(*std::min_element(q.begin(), q.end()), 0.9);
}

TEST(DistortedHexBlockTest, SameSeedGivesBitIdenticalCoordinatesAndOtherSeedsDiffer) {
  absl::StatusOr<Mesh> a = DistortedHexBlock(4, 4, 4, 0.4, 99);
  absl::StatusOr<Mesh> b = DistortedHexBlock(4, 4, 4, 0.4, 99);
  absl::StatusOr<Mesh> c = DistortedHexBlock(4, 4, 4, 0.4, 100);
  ASSERT_TRUE(a.ok() && b.ok() && c.ok());
  const auto coordinates = [](const Mesh& m) {
    std::vector<double> all(m.x().begin(), m.x().end());
    all.insert(all.end(), m.y().begin(), m.y().end());
    all.insert(all.end(), m.z().begin(), m.z().end());
    return all;
  };
  EXPECT_EQ(coordinates(*a), coordinates(*b));
  EXPECT_NE(coordinates(*a), coordinates(*c));
}

TEST(DistortedHexBlockTest, RejectsEmptyGridsAndNegativeDistortion) {
  EXPECT_EQ(DistortedHexBlock(0, 3, 3, 0.1, 1).status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(DistortedHexBlock(3, 3, 3, -0.1, 1).status().code(),
            absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(DistortedHexBlock(3, 3, 3, std::nan(""), 1).status().code(),
            absl::StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace getme::meshgen
