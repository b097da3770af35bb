#include "getme/meshgen/jittered_tet_block.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "mesh_checks.h"

namespace getme::meshgen {
namespace {

using ::getme::NodePosition;
using ::getme::testing::CheckBlockFaces;
using ::getme::testing::InvalidElements;
using ::getme::testing::MeanRatios;

TEST(JitteredTetBlockTest, HasSixTetrahedraPerCube) {
  absl::StatusOr<Mesh> mesh = JitteredTetBlock(3, 4, 5, 0.2, 1);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EXPECT_EQ(mesh->element_count(), 6 * 3 * 4 * 5);
  EXPECT_EQ(mesh->element_count(ElementType::kTetrahedron), 6 * 3 * 4 * 5);
  EXPECT_EQ(mesh->node_count(), 4 * 5 * 6);
}

TEST(JitteredTetBlockTest, UnjitteredTetrahedraAreValidAndFillTheBoxExactly) {
  absl::StatusOr<Mesh> mesh = JitteredTetBlock(3, 3, 2, 0.0, 1);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EXPECT_TRUE(InvalidElements(*mesh).empty());
  double volume = 0.0;
  for (ElementId e = 0; e < mesh->element_count(); ++e) {
    const auto n = mesh->element_nodes(e);
    const Vec3 p0 = NodePosition(*mesh, n[0]);
    volume += (NodePosition(*mesh, n[1]) - p0)
                  .dot((NodePosition(*mesh, n[2]) - p0).cross(NodePosition(*mesh, n[3]) - p0)) /
              6.0;
  }
  EXPECT_NEAR(volume, 18.0, 1e-12);
}

TEST(JitteredTetBlockTest, JitteredTetrahedraStayValidConformAndFillTheBox) {
  absl::StatusOr<Mesh> mesh = JitteredTetBlock(5, 5, 5, 0.45, 21);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EXPECT_TRUE(InvalidElements(*mesh).empty());
  const auto report = CheckBlockFaces(*mesh, 5, 5, 5);
  EXPECT_EQ(report.overused_faces, 0);
  EXPECT_EQ(report.inner_boundary_faces, 0);
  // Every box square is split into two triangles.
  EXPECT_EQ(report.boundary_faces, 2 * 6 * 25);
  EXPECT_NEAR(report.boundary_area, 6 * 25, 1e-9);
  // A conforming valid tet mesh of the box has the box's volume whatever the jitter.
  double volume = 0.0;
  for (ElementId e = 0; e < mesh->element_count(); ++e) {
    const auto n = mesh->element_nodes(e);
    const Vec3 p0 = NodePosition(*mesh, n[0]);
    volume += (NodePosition(*mesh, n[1]) - p0)
                  .dot((NodePosition(*mesh, n[2]) - p0).cross(NodePosition(*mesh, n[3]) - p0)) /
              6.0;
  }
  EXPECT_NEAR(volume, 125.0, 1e-9);
  const std::vector<double> q = MeanRatios(*mesh);
  EXPECT_LT(*std::min_element(q.begin(), q.end()), 0.5);
}

TEST(JitteredTetBlockTest, SameSeedGivesBitIdenticalCoordinates) {
  absl::StatusOr<Mesh> a = JitteredTetBlock(4, 3, 3, 0.3, 8);
  absl::StatusOr<Mesh> b = JitteredTetBlock(4, 3, 3, 0.3, 8);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_TRUE(std::ranges::equal(a->x(), b->x()));
  EXPECT_TRUE(std::ranges::equal(a->y(), b->y()));
  EXPECT_TRUE(std::ranges::equal(a->z(), b->z()));
}

}  // namespace
}  // namespace getme::meshgen
