#include "getme/meshgen/plate_with_holes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesh_checks.h"

namespace getme::meshgen {
namespace {

using ::getme::NodePosition;
using ::getme::testing::CensusFaces;
using ::getme::testing::CheckBlockFaces;
using ::getme::testing::ElementCentroid;
using ::getme::testing::InvalidElements;

constexpr std::int64_t kPlateTestElements = 10'000;

// One 10k-element plate shared by the tests.
class PlateWithHolesTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    absl::StatusOr<PlateLayout> layout = PlateLayoutFor(kPlateTestElements);
    ASSERT_TRUE(layout.ok()) << layout.status();
    layout_ = new PlateLayout(*layout);
    absl::StatusOr<Mesh> mesh = PlateWithHoles({.target_elements = kPlateTestElements});
    ASSERT_TRUE(mesh.ok()) << mesh.status();
    mesh_ = new Mesh(*std::move(mesh));
  }
  static void TearDownTestSuite() {
    delete mesh_;
    delete layout_;
  }
  static const Mesh* mesh_;
  static const PlateLayout* layout_;
};
const Mesh* PlateWithHolesTest::mesh_ = nullptr;
const PlateLayout* PlateWithHolesTest::layout_ = nullptr;

TEST_F(PlateWithHolesTest, EveryElementIsValidAndAllThreeTypesArePresent) {
  EXPECT_TRUE(InvalidElements(*mesh_).empty());
  EXPECT_GT(mesh_->element_count(ElementType::kHexahedron), 0);
  EXPECT_GT(mesh_->element_count(ElementType::kPyramid), 0);
  EXPECT_GT(mesh_->element_count(ElementType::kTetrahedron), 0);
  EXPECT_EQ(mesh_->element_count(ElementType::kPrism), 0);
}

TEST_F(PlateWithHolesTest, ElementCountIsWithinTenPercentOfTheTarget) {
  EXPECT_LE(std::llabs(mesh_->element_count() - kPlateTestElements), kPlateTestElements / 10);
}

// Watertight: every face is shared by two elements except those on the box surface, which add up
// to the box's area; so the holes are filled, and the plate's surface is inside the mesh.
TEST_F(PlateWithHolesTest, OnlyTheBoxSurfaceIsBoundary) {
  const auto report = CheckBlockFaces(*mesh_, layout_->nx, layout_->ny, layout_->nz);
  EXPECT_EQ(report.overused_faces, 0);
  EXPECT_EQ(report.inner_boundary_faces, 0);
  const double nx = layout_->nx, ny = layout_->ny, nz = layout_->nz;
  EXPECT_NEAR(report.boundary_area, 2.0 * (nx * ny + ny * nz + nz * nx), 1e-9);
}

// The pyramid layer: every pyramid's base is a hexahedron's face and every hexahedron face is
// shared with a hexahedron, a pyramid or nothing else.
TEST_F(PlateWithHolesTest, PyramidsJoinTheHexahedraToTheTetrahedra) {
  std::int64_t pyramid_bases_on_hexahedra = 0;
  for (const auto& [key, use] : CensusFaces(*mesh_)) {
    if (use.nodes.size() != 4 || use.elements.size() != 2) continue;
    const ElementType a = mesh_->type(use.elements[0]), b = mesh_->type(use.elements[1]);
    ASSERT_TRUE(a == ElementType::kHexahedron || b == ElementType::kHexahedron);
    pyramid_bases_on_hexahedra += (a == ElementType::kPyramid || b == ElementType::kPyramid);
  }
  EXPECT_EQ(pyramid_bases_on_hexahedra, mesh_->element_count(ElementType::kPyramid));
}

// The hexahedra are the drilled plate: inside the slab, none in a hole (a cube is drilled when its
// centre is; nodes move at most 0.2 per axis, centroids 0.3 across), other elements filling the
// holes, and as many hexahedra as the slab's volume minus the holes' up to the cubes the holes'
// rims cut (a band of half a cube diagonal around each rim).
TEST_F(PlateWithHolesTest, HexahedraFillThePlateOutsideTheDrillHoles) {
  const PlateLayout& plate = *layout_;
  std::array<std::int64_t, 2> tets_in_hole{};
  for (ElementId e = 0; e < mesh_->element_count(); ++e) {
    const Vec3 c = ElementCentroid(*mesh_, e);
    for (std::size_t h = 0; h < plate.holes.size(); ++h) {
      const DrillHole& hole = plate.holes[h];
      const double from_axis = std::hypot(c.x() - hole.x, c.y() - hole.y);
      if (mesh_->type(e) == ElementType::kHexahedron) {
        ASSERT_GT(from_axis, hole.radius - 0.3) << "hexahedron " << e;
      } else if (from_axis < hole.radius - 0.3 && c.z() > plate.z0 && c.z() < plate.z1) {
        ++tets_in_hole[h];
      }
    }
    if (mesh_->type(e) != ElementType::kHexahedron) continue;
    ASSERT_GT(c.z(), plate.z0 - 0.2);
    ASSERT_LT(c.z(), plate.z1 + 0.2);
  }
  EXPECT_GT(tets_in_hole[0], 0);
  EXPECT_GT(tets_in_hole[1], 0);
  const double thickness = plate.z1 - plate.z0;
  double drilled = 0.0, rims = 0.0;
  for (const DrillHole& hole : plate.holes) {
    drilled += std::numbers::pi * hole.radius * hole.radius * thickness;
    rims += 2.0 * std::numbers::pi * hole.radius * std::sqrt(0.5) * thickness;
  }
  const double slab = double(plate.x1 - plate.x0) * (plate.y1 - plate.y0) * thickness;
  EXPECT_NEAR(mesh_->element_count(ElementType::kHexahedron), slab - drilled, rims);
}

// Boundary nodes are the box's: the plate and hole surfaces are free for the smoother.
TEST_F(PlateWithHolesTest, BoundaryNodesLieOnTheBox) {
  std::int64_t boundary = 0;
  for (NodeId node = 0; node < mesh_->node_count(); ++node) {
    if (!mesh_->is_boundary(node)) continue;
    ++boundary;
    const Vec3 p = NodePosition(*mesh_, node);
    ASSERT_TRUE(p.x() == 0 || p.y() == 0 || p.z() == 0 || p.x() == layout_->nx ||
                p.y() == layout_->ny || p.z() == layout_->nz)
        << "node " << node;
  }
  const std::int64_t nx = layout_->nx, ny = layout_->ny, nz = layout_->nz;
  EXPECT_EQ(boundary, (nx + 1) * (ny + 1) * (nz + 1) - (nx - 1) * (ny - 1) * (nz - 1));
}

// The type mix stays near the paper's (17 % hexahedra, 7 % pyramids, 77 % tetrahedra) at every
// size, a little richer in tetrahedra for small plates, whose one-cube side margins weigh more.
// Counting needs no mesh, so large sizes are cheap to check.
TEST(PlateWithHolesSizeTest, CountsHitTheTargetAndTheTypeMixStaysNearThePapers) {
  for (const std::int64_t target : {10'000, 34'050, 100'000, 1'000'000}) {
    SCOPED_TRACE(::testing::Message() << "target " << target);
    absl::StatusOr<PlateLayout> layout = PlateLayoutFor(target);
    ASSERT_TRUE(layout.ok()) << layout.status();
    const CubeFillCounts counts = CountCubeFill(FillPlate(*layout));
    const double n = static_cast<double>(counts.elements());
    EXPECT_NEAR(n, target, 0.1 * target);
    const double hex_share = counts.hexahedra / n;
    EXPECT_GT(hex_share, target < 100'000 ? 0.08 : 0.14);
    EXPECT_LT(hex_share, 0.19);
    EXPECT_NEAR(counts.pyramids / n, 0.068, 0.012);
    EXPECT_GT(counts.tetrahedra / n, 0.74);
    EXPECT_LT(counts.tetrahedra / n, 0.86);
  }
}

TEST(PlateWithHolesSizeTest, SameSeedSameMeshOtherSeedOtherCoordinates) {
  absl::StatusOr<Mesh> a = PlateWithHoles({.target_elements = 8000, .seed = 5});
  absl::StatusOr<Mesh> b = PlateWithHoles({.target_elements = 8000, .seed = 5});
  absl::StatusOr<Mesh> c = PlateWithHoles({.target_elements = 8000, .seed = 6});
  ASSERT_TRUE(a.ok() && b.ok() && c.ok());
  EXPECT_TRUE(std::ranges::equal(a->x(), b->x()));
  EXPECT_TRUE(std::ranges::equal(a->y(), b->y()));
  EXPECT_TRUE(std::ranges::equal(a->z(), b->z()));
  ASSERT_EQ(a->element_count(), c->element_count());
  for (ElementId e = 0; e < a->element_count(); ++e) {
    ASSERT_TRUE(std::ranges::equal(a->element_nodes(e), c->element_nodes(e)));
  }
  EXPECT_FALSE(std::ranges::equal(a->x(), c->x()));
}

TEST(PlateWithHolesSizeTest, RejectsTargetsBelowTheSmallestPlate) {
  const absl::Status status = PlateWithHoles({.target_elements = 1000}).status();
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(status.message().find("1000"), std::string_view::npos) << status;
}

}  // namespace
}  // namespace getme::meshgen
