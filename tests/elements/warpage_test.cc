// Warpage of quadrilateral faces and elements and the combined criterion q_γ (Sec. 4.4) against
// closed forms.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "element_type_tags.h"
#include "getme/elements/element_quality.h"
#include "random_elements.h"
#include "reference_kernels.h"
#include "regular_elements.h"

namespace getme::test {
namespace {

constexpr double kWarpageTolerance = 1e-12;

TEST(QuadWarpageTest, PlanarQuadrilateralsHaveNoWarpage) {
  UnitRandom random(2001);
  for (int trial = 0; trial < 100; ++trial) {
    // A convex quadrilateral in the plane z = 0 (a perturbed rectangle), then placed anywhere.
    const double w = random.Uniform(0.2, 3.0);
    const double h = random.Uniform(0.2, 3.0);
    const Points flat = {{random.Uniform(-0.1, 0.1), random.Uniform(-0.1, 0.1), 0},
                         {w + random.Uniform(-0.1, 0.1), random.Uniform(-0.1, 0.1), 0},
                         {w + random.Uniform(-0.1, 0.1), h + random.Uniform(-0.1, 0.1), 0},
                         {random.Uniform(-0.1, 0.1), h + random.Uniform(-0.1, 0.1), 0}};
    const Points q = random.RandomSimilarity()(flat);
    EXPECT_NEAR(QuadWarpage(q[0], q[1], q[2], q[3]), 0.0, kWarpageTolerance) << "trial " << trial;
  }
}

TEST(QuadWarpageTest, SymmetricallyTwistedSquare) {
  // Nodes (0,0,0) (1,0,h) (1,1,0) (0,1,h): n0 = (−h,−h,1), n1 = (−h,h,1), n2 = (h,h,1),
  // n3 = (h,−h,1), so n̂0·n̂2 = n̂1·n̂3 = (1 − 2h²)/(1 + 2h²) and w = 1 − ((1 − 2h²)/(1 + 2h²))³.
  // h = 1/2 gives cos = 1/3 and w = 26/27.
  for (double h : {0.01, 0.2, 0.5, 1.0, 3.0}) {
    const double cosine = (1.0 - 2.0 * h * h) / (1.0 + 2.0 * h * h);
    const double expected = 1.0 - cosine * cosine * cosine;
    EXPECT_NEAR(QuadWarpage(Vec3(0, 0, 0), Vec3(1, 0, h), Vec3(1, 1, 0), Vec3(0, 1, h)), expected,
                kWarpageTolerance)
        << "h = " << h;
  }
  EXPECT_NEAR(QuadWarpage(Vec3(0, 0, 0), Vec3(1, 0, 0.5), Vec3(1, 1, 0), Vec3(0, 1, 0.5)),
              26.0 / 27.0, kWarpageTolerance);
}

TEST(QuadWarpageTest, OneLiftedCornerUsesTheSmallerCosine) {
  // Unit square with node 3 lifted to (0,1,h): n0 = (0,−h,1), n1 = (0,0,1), n2 = (h,0,1),
  // n3 = (h,−h,1). n̂0·n̂2 = 1/(1 + h²) ≤ n̂1·n̂3 = 1/√(1 + 2h²), so w = 1 − (1 + h²)^(−3).
  // (Taking the larger cosine instead would give 1 − (1 + 2h²)^(−3/2): 0.8075 instead of 0.875
  // at h = 1.)
  for (double h : {0.1, 0.5, 1.0, 2.0}) {
    const double expected = 1.0 - std::pow(1.0 + h * h, -3.0);
    EXPECT_NEAR(QuadWarpage(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, h)), expected,
                kWarpageTolerance)
        << "h = " << h;
  }
  EXPECT_NEAR(QuadWarpage(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 1)), 0.875,
              kWarpageTolerance);
}

TEST(QuadWarpageTest, IndependentOfPlacementAndStartingNode) {
  UnitRandom random(2002);
  const Points quad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.7}};
  const double expected = 1.0 - std::pow(1.0 + 0.49, -3.0);
  for (int trial = 0; trial < 50; ++trial) {
    const Points q = random.RandomSimilarity()(quad);
    for (int start = 0; start < 4; ++start) {
      EXPECT_NEAR(QuadWarpage(q[start], q[(start + 1) % 4], q[(start + 2) % 4], q[(start + 3) % 4]),
                  expected, 1e-11)
          << "trial " << trial << ", start " << start;
    }
  }
}

TEST(QuadWarpageTest, ReflexCornerCountsAsMaximallyWarped) {
  // Planar but folded over the diagonal (1,3): node 0 at (0.9,0.9,0) makes a reflex corner, so
  // n0 = (0,0,−0.8) opposes n2 = (0,0,1) while n1, n3 = (0,0,0.1): n̂0·n̂2 = −1 and w = 1 − (−1) = 2.
  EXPECT_NEAR(QuadWarpage(Vec3(0.9, 0.9, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)), 2.0,
              kWarpageTolerance);
}

TEST(QuadWarpageTest, DegenerateCornerCountsAsMaximallyWarped) {
  // Two coincident nodes leave a corner without a normal; the kernel documents w = 2 for it.
  EXPECT_EQ(QuadWarpage(Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)), 2.0);
}

template <typename Tag>
class ElementWarpageTest : public ::testing::Test {};
TYPED_TEST_SUITE(ElementWarpageTest, AllElementTypes, ElementTypeName);

// Element warpage is the maximum over the quadrilateral faces of the paper's face list.
TYPED_TEST(ElementWarpageTest, IsTheMaximumOverQuadrilateralFaces) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(2100 + TypeIndex(kType));
  for (int trial = 0; trial < 200; ++trial) {
    const ElementNodes<kType> nodes = random.ElementInUnitCube<kType>();
    double expected = 0.0;
    int quad_faces = 0;
    for (const IndexTuple& f : Paper(kType).faces) {
      if (f.size() != 4) continue;
      ++quad_faces;
      expected =
          std::max(expected, QuadWarpage(nodes[f[0]], nodes[f[1]], nodes[f[2]], nodes[f[3]]));
    }
    EXPECT_EQ(Warpage<kType>(nodes), expected) << "trial " << trial;
    if (kType == ElementType::kTetrahedron) {
      EXPECT_EQ(quad_faces, 0);
      EXPECT_EQ(Warpage<kType>(nodes), 0.0) << "trial " << trial;
    }
  }
}

TEST(ElementWarpageTest, HexahedronWithOneLiftedTopNode) {
  // Lifting node 6 of the unit cube along z keeps it in the side planes x = 1 and y = 1, so only
  // the top face (4,7,6,5) warps, by the one-lifted-corner value 1 − (1 + h²)^(−3).
  for (double h : {0.1, 0.5, 1.0}) {
    Points p = RegularElementPoints(ElementType::kHexahedron);
    p[6].z() += h;
    EXPECT_NEAR(Warpage<ElementType::kHexahedron>(ToNodes<ElementType::kHexahedron>(p)),
                1.0 - std::pow(1.0 + h * h, -3.0), kWarpageTolerance)
        << "h = " << h;
  }
}

TEST(ElementWarpageTest, HexahedronTakesTheWorseOfTwoWarpedFaces) {
  // Lift node 6 along z (warps only the top face) and push node 0 along −x (warps only the face
  // x = 0, (3,0,4,7)); both are one-displaced-corner squares, so w(E) = max of the two values.
  Points p = RegularElementPoints(ElementType::kHexahedron);
  p[6].z() += 0.3;
  p[0].x() -= 0.8;
  const double top = 1.0 - std::pow(1.0 + 0.09, -3.0);
  const double side = 1.0 - std::pow(1.0 + 0.64, -3.0);
  EXPECT_NEAR(Warpage<ElementType::kHexahedron>(ToNodes<ElementType::kHexahedron>(p)),
              std::max(top, side), kWarpageTolerance);
}

TEST(ElementWarpageTest, PyramidWarpsOnlyThroughItsBase) {
  // Moving the apex never warps anything; lifting a base corner warps the base.
  Points p = RegularElementPoints(ElementType::kPyramid);
  p[4] += Eigen::Vector3d(0.3, -0.2, 0.5);
  EXPECT_EQ(Warpage<ElementType::kPyramid>(ToNodes<ElementType::kPyramid>(p)), 0.0);
  p[3].z() += 0.5;
  EXPECT_NEAR(Warpage<ElementType::kPyramid>(ToNodes<ElementType::kPyramid>(p)),
              1.0 - std::pow(1.25, -3.0), kWarpageTolerance);
}

TEST(ElementWarpageTest, PrismWarpsOnlyWhenANodeLeavesItsSidePlanes) {
  // Lifting node 4 along z moves it within both side planes through it, (0,1,4,3) and (1,2,5,4):
  // the quadrilaterals stay planar (only the triangles tilt, and they do not count).
  Points p = RegularElementPoints(ElementType::kPrism);
  p[4].z() += 0.4;
  EXPECT_NEAR(Warpage<ElementType::kPrism>(ToNodes<ElementType::kPrism>(p)), 0.0,
              kWarpageTolerance);
  // Pushing node 3 by 0.5 perpendicular to face (0,1,4,3) (the plane y = 0) makes that face a unit
  // square with one displaced corner, w = 1 − 1.25^(−3); node 3 also leaves the plane of (2,0,3,5)
  // (obliquely, no closed form), and the element takes the larger of the two.
  Points q = RegularElementPoints(ElementType::kPrism);
  q[3].y() -= 0.5;
  const auto prism = ToNodes<ElementType::kPrism>(q);
  const double front = 1.0 - std::pow(1.25, -3.0);
  const double left = QuadWarpage(prism[2], prism[0], prism[3], prism[5]);
  EXPECT_NEAR(Warpage<ElementType::kPrism>(prism), std::max(front, left), kWarpageTolerance);
  EXPECT_GT(front, 0.0);
  EXPECT_GT(left, 0.0);
}

template <typename Tag>
class QualityGammaTest : public ::testing::Test {};
TYPED_TEST_SUITE(QualityGammaTest, AllElementTypes, ElementTypeName);

TYPED_TEST(QualityGammaTest, IsTheMinimumOfMeanRatioAndScaledWarpage) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(2200 + TypeIndex(kType));
  for (int trial = 0; trial < 200; ++trial) {
    const ElementNodes<kType> nodes = random.ValidElementInUnitCube<kType>();
    const double q = ReferenceMeanRatio(kType, ToPoints<kType>(nodes));
    const double w = Warpage<kType>(nodes);
    for (double gamma : {0.25, 1.0, 4.0}) {
      EXPECT_NEAR(QualityGamma<kType>(nodes, gamma), std::min(q, gamma * (1.0 - w / 2.0)),
                  kWarpageTolerance)
          << "trial " << trial << ", gamma " << gamma;
    }
  }
}

TEST(QualityGammaTest, ClosedFormCases) {
  // Regular hexahedron: q = 1, w = 0, so q_γ = min(1, γ).
  const auto cube = RegularElement<ElementType::kHexahedron>();
  EXPECT_NEAR(QualityGamma<ElementType::kHexahedron>(cube, 0.25), 0.25, kWarpageTolerance);
  EXPECT_NEAR(QualityGamma<ElementType::kHexahedron>(cube, 3.0), 1.0, kWarpageTolerance);
  // Flat-ish hexahedron stretched by a = 0.05: w = 0 and q = 3a^(2/3)/(2 + a²) ≈ 0.2035 < 0.25.
  Points thin = RegularElementPoints(ElementType::kHexahedron);
  for (Eigen::Vector3d& node : thin) node.z() *= 0.05;
  const double q_thin = 3.0 * std::cbrt(0.05 * 0.05) / (2.0 + 0.05 * 0.05);
  ASSERT_LT(q_thin, 0.25);
  EXPECT_NEAR(QualityGamma<ElementType::kHexahedron>(ToNodes<ElementType::kHexahedron>(thin), 0.25),
              q_thin, kWarpageTolerance);
  // Cube with node 6 lifted by 1: w = 7/8, so γ(1 − w/2) = 0.25 · 9/16 = 0.140625 decides.
  Points lifted = RegularElementPoints(ElementType::kHexahedron);
  lifted[6].z() += 1.0;
  const auto lifted_hex = ToNodes<ElementType::kHexahedron>(lifted);
  ASSERT_GT(MeanRatio<ElementType::kHexahedron>(lifted_hex), 0.140625);
  EXPECT_NEAR(QualityGamma<ElementType::kHexahedron>(lifted_hex, 0.25), 0.140625,
              kWarpageTolerance);
  // A tetrahedron is never warped: q_γ = min(q, γ).
  const auto tet = RegularElement<ElementType::kTetrahedron>();
  EXPECT_NEAR(QualityGamma<ElementType::kTetrahedron>(tet, 0.25), 0.25, kWarpageTolerance);
}

}  // namespace
}  // namespace getme::test
