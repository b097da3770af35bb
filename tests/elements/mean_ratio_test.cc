// Mean ratio (Def. 3) and validity (Def. 2) against values computed by hand and against a plain
// Eigen evaluation of eq. (10) with W⁻¹ and det from Eigen.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "element_type_tags.h"
#include "getme/elements/element_quality.h"
#include "random_elements.h"
#include "reference_kernels.h"
#include "regular_elements.h"

namespace getme::test {
namespace {

constexpr double kMeanRatioTolerance = 1e-12;

// 3 s^(2/3) / (2 + s²): the mean ratio of S = diag(1, 1, s), det S = s, ‖S‖_F² = 2 + s².
double StretchedMeanRatio(double s) { return 3.0 * std::cbrt(s * s) / (2.0 + s * s); }

TEST(MeanRatioTest, CornerTetrahedron) {
  // D = I, so S = W⁻¹ with det S = 1/det W = 1/((√3/2)·√(2/3)) = √2 and
  // ‖W⁻¹‖_F² = 1 + 1/3 + 1/6 + 4/3 + 1/6 + 3/2 = 9/2 (rows (1, −1/√3, −1/√6), (0, 2/√3, −1/√6),
  // (0, 0, √(3/2))). q = 3·(√2)^(2/3) / (9/2) = 2^(4/3)/3 ≈ 0.839947.
  // Cross-check with the edge form for tetrahedra, q = 12 (3V)^(2/3) / Σ l²: V = 1/6,
  // Σ l² = 3·1 + 3·2 = 9, q = 12 · 2^(−2/3) / 9 = 2^(4/3)/3.
  const ElementNodes<ElementType::kTetrahedron> corner = {Vec3(0, 0, 0), Vec3(1, 0, 0),
                                                          Vec3(0, 1, 0), Vec3(0, 0, 1)};
  const double expected = std::pow(2.0, 4.0 / 3.0) / 3.0;
  EXPECT_TRUE(IsValid<ElementType::kTetrahedron>(corner));
  EXPECT_NEAR(MeanRatio<ElementType::kTetrahedron>(corner), expected, kMeanRatioTolerance);
  EXPECT_NEAR(expected, 0.8399473665965822, 1e-15);
}

// For tetrahedra Def. 3 equals 12 (3V)^(2/3) / Σ l² (V the volume, l the six edge lengths): a
// formula that involves neither W nor node tetrahedra.
TEST(MeanRatioTest, RandomTetrahedraMatchTheEdgeLengthForm) {
  UnitRandom random(7);
  for (int trial = 0; trial < 1000; ++trial) {
    const auto tet = random.ValidElementInUnitCube<ElementType::kTetrahedron>();
    const double volume = (tet[1] - tet[0]).dot((tet[2] - tet[0]).cross(tet[3] - tet[0])) / 6.0;
    double squared_edges = 0.0;
    for (int i = 0; i < 4; ++i) {
      for (int j = i + 1; j < 4; ++j) squared_edges += (tet[i] - tet[j]).squaredNorm();
    }
    const double expected = 12.0 * std::cbrt(9.0 * volume * volume) / squared_edges;
    EXPECT_NEAR(MeanRatio<ElementType::kTetrahedron>(tet), expected, kMeanRatioTolerance)
        << "trial " << trial;
  }
}

TEST(MeanRatioTest, HexahedronStretchedAlongZ) {
  // Every node tetrahedron spans ±e_x, ±e_y, ±a e_z with positive orientation: S = D, det = a,
  // ‖S‖_F² = 2 + a², so q = 3 a^(2/3) / (2 + a²).
  for (double a : {0.01, 0.25, 0.5, 1.0, 2.0, 3.0, 10.0}) {
    Points p = RegularElementPoints(ElementType::kHexahedron);
    for (Eigen::Vector3d& node : p) node.z() *= a;
    const auto hex = ToNodes<ElementType::kHexahedron>(p);
    EXPECT_TRUE(IsValid<ElementType::kHexahedron>(hex)) << "a = " << a;
    EXPECT_NEAR(MeanRatio<ElementType::kHexahedron>(hex), StretchedMeanRatio(a),
                kMeanRatioTolerance)
        << "a = " << a;
  }
}

TEST(MeanRatioTest, RightPrismWithEquilateralBase) {
  // D(T_k) = W diag(1, 1, h) up to a rotation (W's third column is the unit height), and W is
  // block diagonal, so S = diag(I₂, h) and q = 3 h^(2/3) / (2 + h²).
  for (double h : {0.012, 0.1, 0.5, 1.0, 1.5, 4.0}) {
    Points p = RegularElementPoints(ElementType::kPrism);
    for (Eigen::Vector3d& node : p) node.z() *= h;
    const auto prism = ToNodes<ElementType::kPrism>(p);
    EXPECT_TRUE(IsValid<ElementType::kPrism>(prism)) << "h = " << h;
    EXPECT_NEAR(MeanRatio<ElementType::kPrism>(prism), StretchedMeanRatio(h), kMeanRatioTolerance)
        << "h = " << h;
  }
}

TEST(MeanRatioTest, PyramidWithApexHeight) {
  // Unit square base, apex above its centre at height h: D = W + (h − √2/2) e₃e₃ᵗ, so
  // S = D W⁻¹ = I + (h − √2/2) e₃ (e₃ᵗ W⁻¹) = diag(1, 1, √2 h) since row 3 of W⁻¹ is (0, 0, √2).
  // With s = √2 h: q = 3 s^(2/3) / (2 + s²); the regular pyramid has h = √2/2, s = 1.
  for (double h : {0.05, 0.3, std::sqrt(0.5), 1.0, 2.0}) {
    Points p = RegularElementPoints(ElementType::kPyramid);
    p[4].z() = h;
    const auto pyramid = ToNodes<ElementType::kPyramid>(p);
    EXPECT_TRUE(IsValid<ElementType::kPyramid>(pyramid)) << "h = " << h;
    EXPECT_NEAR(MeanRatio<ElementType::kPyramid>(pyramid), StretchedMeanRatio(std::sqrt(2.0) * h),
                kMeanRatioTolerance)
        << "h = " << h;
  }
}

template <typename Tag>
class MeanRatioTypedTest : public ::testing::Test {};
TYPED_TEST_SUITE(MeanRatioTypedTest, AllElementTypes, ElementTypeName);

TYPED_TEST(MeanRatioTypedTest, FlatElementIsInvalidWithQualityZero) {
  constexpr ElementType kType = TypeParam::kType;
  Points p = RegularElementPoints(kType);
  for (Eigen::Vector3d& node : p) node.z() = 0.0;
  const auto flat = ToNodes<kType>(p);
  EXPECT_FALSE(IsValid<kType>(flat));
  EXPECT_EQ(MeanRatio<kType>(flat), 0.0);
  EXPECT_EQ(QualityGamma<kType>(flat, 0.25), 0.0);
}

TYPED_TEST(MeanRatioTypedTest, NearlyFlatValidElementHasSmallPositiveQuality) {
  constexpr ElementType kType = TypeParam::kType;
  Points p = RegularElementPoints(kType);
  for (Eigen::Vector3d& node : p) node.z() *= 1e-3;
  const auto thin = ToNodes<kType>(p);
  EXPECT_TRUE(IsValid<kType>(thin));
  const double q = MeanRatio<kType>(thin);
  EXPECT_GT(q, 0.0);
  EXPECT_LT(q, 0.05);
  EXPECT_NEAR(q, ReferenceMeanRatio(kType, p), kMeanRatioTolerance);
}

TYPED_TEST(MeanRatioTypedTest, CollapsedNodeIsInvalid) {
  constexpr ElementType kType = TypeParam::kType;
  Points p = RegularElementPoints(kType);
  p[1] = p[0];
  const auto collapsed = ToNodes<kType>(p);
  EXPECT_FALSE(IsValid<kType>(collapsed));
  EXPECT_EQ(MeanRatio<kType>(collapsed), 0.0);
}

// Random elements, valid or not: every node tetrahedron determinant equals Eigen's determinant of
// D(T_k) built from the paper's N, validity is "all positive", and the mean ratio equals eq. (10)
// evaluated with Eigen's W⁻¹ (0 when invalid).
TYPED_TEST(MeanRatioTypedTest, RandomElementsMatchEigenEvaluation) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(11 + TypeIndex(kType));
  int valid_count = 0;
  for (int trial = 0; trial < 400000 && valid_count < 500; ++trial) {
    const ElementNodes<kType> nodes = random.ElementInUnitCube<kType>();
    const Points p = ToPoints<kType>(nodes);
    bool all_positive = true;
    for (int k = 0; k < static_cast<int>(Paper(kType).node_tets.size()); ++k) {
      const double expected = NodeTetEdges(kType, p, k).determinant();
      all_positive = all_positive && expected > 0.0;
      ASSERT_NEAR(NodeTetDeterminant<kType>(nodes, k), expected, kMeanRatioTolerance)
          << "trial " << trial << ", node tetrahedron " << k;
    }
    ASSERT_EQ(IsValid<kType>(nodes), all_positive) << "trial " << trial;
    const double q = MeanRatio<kType>(nodes);
    if (!all_positive) {
      ASSERT_EQ(q, 0.0) << "trial " << trial;
      continue;
    }
    ++valid_count;
    const double expected = ReferenceMeanRatio(kType, p);
    ASSERT_GT(expected, 0.0) << "trial " << trial;
    ASSERT_LE(expected, 1.0 + kMeanRatioTolerance) << "trial " << trial;
    ASSERT_NEAR(q, expected, kMeanRatioTolerance) << "trial " << trial;
  }
  EXPECT_EQ(valid_count, 500) << "too few valid random " << TypeName(kType) << " elements";
}

TYPED_TEST(MeanRatioTypedTest, NeverExceedsOneForRotatedRegularElements) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(13 + TypeIndex(kType));
  for (int trial = 0; trial < 1000; ++trial) {
    const auto placed = ToNodes<kType>(random.RandomSimilarity()(RegularElementPoints(kType)));
    const double q = MeanRatio<kType>(placed);
    ASSERT_LE(q, 1.0) << "trial " << trial;
    ASSERT_GT(q, 1.0 - 1e-10) << "trial " << trial;
    // 1 − q feeds (1 − q)^η in the simultaneous substep; it must not be NaN.
    ASSERT_FALSE(std::isnan(std::pow(1.0 - q, 0.25))) << "trial " << trial;
  }
}

}  // namespace
}  // namespace getme::test
