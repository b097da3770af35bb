#include "getme/meshgen/ring_in_block.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "mesh_checks.h"

namespace getme::meshgen {
namespace {

using ::getme::NodePosition;
using ::getme::testing::CensusFaces;
using ::getme::testing::ElementCentroid;
using ::getme::testing::EnclosedVolume;
using ::getme::testing::InvalidElements;
using ::getme::testing::MeanRatios;

constexpr std::int64_t kRingTestElements = 10'000;
// A grid point next to a cube lies within half a cube diagonal of the cube's centre.
const double kHalfDiagonal = std::sqrt(3.0) / 2.0;

double DistanceFromCircle(const RingLayout& ring, const Vec3& p) {
  return ring.DistanceFromCentreCircle(p.x(), p.y(), p.z());
}

// One 10k-element ring shared by the tests, and the same ring undistorted.
class RingInBlockTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    absl::StatusOr<RingLayout> layout = RingLayoutFor(kRingTestElements);
    ASSERT_TRUE(layout.ok()) << layout.status();
    layout_ = new RingLayout(*layout);
    absl::StatusOr<Mesh> mesh = RingInBlock({.target_elements = kRingTestElements});
    absl::StatusOr<Mesh> regular =
        RingInBlock({.target_elements = kRingTestElements, .distortion = 0.0});
    ASSERT_TRUE(mesh.ok()) << mesh.status();
    ASSERT_TRUE(regular.ok()) << regular.status();
    mesh_ = new Mesh(*std::move(mesh));
    regular_ = new Mesh(*std::move(regular));
  }
  static void TearDownTestSuite() {
    delete mesh_;
    delete regular_;
    delete layout_;
  }
  static const Mesh* mesh_;
  static const Mesh* regular_;
  static const RingLayout* layout_;
};
const Mesh* RingInBlockTest::mesh_ = nullptr;
const Mesh* RingInBlockTest::regular_ = nullptr;
const RingLayout* RingInBlockTest::layout_ = nullptr;

TEST_F(RingInBlockTest, EveryElementIsValidAndAllThreeTypesArePresent) {
  EXPECT_TRUE(InvalidElements(*mesh_).empty());
  EXPECT_GT(mesh_->element_count(ElementType::kHexahedron), 0);
  EXPECT_GT(mesh_->element_count(ElementType::kPyramid), 0);
  EXPECT_GT(mesh_->element_count(ElementType::kTetrahedron), 0);
  EXPECT_EQ(mesh_->element_count(ElementType::kPrism), 0);
  EXPECT_LE(std::llabs(mesh_->element_count() - kRingTestElements), kRingTestElements / 10);
}

// Watertight, and the only boundary besides the box is the ring's surface: every node of a
// boundary face off the box lies within half a cube diagonal of the torus (a staircase of cube
// faces between cubes whose centres are inside and outside the tube).
TEST_F(RingInBlockTest, BoundaryIsTheBoxAndTheRingSurface) {
  const RingLayout& ring = *layout_;
  std::int64_t ring_faces = 0;
  for (const auto& [key, face_use] : CensusFaces(*mesh_)) {
    // A plain reference: clang 14 cannot capture a structured binding in the lambdas below.
    const auto& use = face_use;
    ASSERT_LE(use.elements.size(), 2u);
    if (use.elements.size() == 2) continue;
    const auto on_box = [&](int axis, double plane) {
      return std::all_of(use.nodes.begin(), use.nodes.end(),
                         [&](NodeId n) { return NodePosition(*mesh_, n)[axis] == plane; });
    };
    if (on_box(0, 0) || on_box(1, 0) || on_box(2, 0) || on_box(0, ring.nx) || on_box(1, ring.ny) ||
        on_box(2, ring.nz)) {
      continue;
    }
    ++ring_faces;
    for (const NodeId n : use.nodes) {
      ASSERT_NEAR(DistanceFromCircle(ring, NodePosition(*mesh_, n)), ring.tube_radius,
                  kHalfDiagonal);
    }
  }
  // At least the ring's surface area in cube faces.
  const double torus_area =
      4.0 * std::numbers::pi * std::numbers::pi * ring.major_radius * ring.tube_radius;
  EXPECT_GT(ring_faces, torus_area);
}

// The ring is carved out: the mesh fills the block minus the torus's volume, up to the staircase
// (measured 17 % of the torus volume at this size, where the tube is under three cubes across;
// the bound allows 25 %, a missing or misplaced hole is off by 100 %). Node moves keep the
// boundary, so the distorted mesh encloses exactly the volume of the regular one.
TEST_F(RingInBlockTest, MeshFillsTheBlockMinusTheRing) {
  const RingLayout& ring = *layout_;
  const double torus = 2.0 * std::numbers::pi * std::numbers::pi * ring.major_radius *
                       ring.tube_radius * ring.tube_radius;
  const double block = double(ring.nx) * ring.ny * ring.nz;
  EXPECT_NEAR(EnclosedVolume(*regular_), block - torus, 0.25 * torus);
  EXPECT_NEAR(EnclosedVolume(*mesh_), EnclosedVolume(*regular_), 1e-9 * block);
}

// In the regular mesh every element lies in its cube, within half a diagonal of the cube's
// centre, which decides the fill: hexahedra outside the band, other elements in it.
TEST_F(RingInBlockTest, TetrahedraAndPyramidsFillTheBandAroundTheRing) {
  const RingLayout& ring = *layout_;
  for (ElementId e = 0; e < regular_->element_count(); ++e) {
    const double distance = DistanceFromCircle(ring, ElementCentroid(*regular_, e));
    ASSERT_GT(distance, ring.tube_radius - kHalfDiagonal) << "element " << e;
    if (regular_->type(e) == ElementType::kHexahedron) {
      ASSERT_GT(distance, ring.band_radius - kHalfDiagonal) << "hexahedron " << e;
    } else {
      ASSERT_LT(distance, ring.band_radius + kHalfDiagonal) << "element " << e;
    }
  }
}

// The paper distorts its ring mesh strongly (q_mean 0.45, q_min 0.0005) keeping it valid.
TEST_F(RingInBlockTest, DistortionLowersQualityStronglyAndKeepsTheRingSurfaceFixed) {
  const std::vector<double> q = MeanRatios(*mesh_);
  const std::vector<double> q_regular = MeanRatios(*regular_);
  const double mean = std::accumulate(q.begin(), q.end(), 0.0) / q.size();
  const double mean_regular =
      std::accumulate(q_regular.begin(), q_regular.end(), 0.0) / q_regular.size();
  EXPECT_LT(mean, mean_regular - 0.15);
  EXPECT_LT(*std::min_element(q.begin(), q.end()), 0.05);
  for (NodeId node = 0; node < mesh_->node_count(); ++node) {
    if (!mesh_->is_boundary(node)) continue;
    ASSERT_EQ(NodePosition(*mesh_, node), NodePosition(*regular_, node)) << "node " << node;
  }
}

// Hexahedra stay at about the paper's 9 % at every size; pyramids, the band's surface, thin out
// as the resolution grows. Counting needs no mesh, so large sizes are cheap to check.
TEST(RingInBlockSizeTest, CountsHitTheTargetAndHexahedraKeepTheirShare) {
  for (const std::int64_t target : {10'000, 83'210, 1'000'000}) {
    SCOPED_TRACE(::testing::Message() << "target " << target);
    absl::StatusOr<RingLayout> layout = RingLayoutFor(target);
    ASSERT_TRUE(layout.ok()) << layout.status();
    const CubeFillCounts counts = CountCubeFill(FillRing(*layout));
    const double n = static_cast<double>(counts.elements());
    EXPECT_NEAR(n, target, 0.1 * target);
    EXPECT_NEAR(counts.hexahedra / n, 0.10, 0.025);
    EXPECT_GT(counts.pyramids / n, 0.005);
    EXPECT_LT(counts.pyramids / n, 0.08);
    EXPECT_GT(counts.tetrahedra / n, 0.80);
  }
}

TEST(RingInBlockSizeTest, SameSeedSameMeshOtherSeedOtherCoordinates) {
  absl::StatusOr<Mesh> a = RingInBlock({.target_elements = 10'000, .seed = 5});
  absl::StatusOr<Mesh> b = RingInBlock({.target_elements = 10'000, .seed = 5});
  absl::StatusOr<Mesh> c = RingInBlock({.target_elements = 10'000, .seed = 6});
  ASSERT_TRUE(a.ok() && b.ok() && c.ok());
  EXPECT_TRUE(std::ranges::equal(a->x(), b->x()));
  EXPECT_TRUE(std::ranges::equal(a->y(), b->y()));
  EXPECT_TRUE(std::ranges::equal(a->z(), b->z()));
  EXPECT_FALSE(std::ranges::equal(a->x(), c->x()));
}

TEST(RingInBlockSizeTest, RejectsTargetsBelowTheCoarsestRing) {
  EXPECT_EQ(RingInBlock({.target_elements = 500}).status().code(),
            absl::StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace getme::meshgen
