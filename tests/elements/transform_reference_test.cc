// The library's TransformElement, ScaleAndRelax and RegularizingStep against the step-by-step
// re-computation of Def. 1 and eqs. (8), (11) from the paper's tables (reference_kernels.h).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "element_type_tags.h"
#include "getme/elements/transform.h"
#include "random_elements.h"
#include "reference_kernels.h"

namespace getme::test {
namespace {

constexpr double kTransformTolerance = 1e-12;

template <typename Tag>
class TransformReferenceTest : public ::testing::Test {};
TYPED_TEST_SUITE(TransformReferenceTest, AllElementTypes, ElementTypeName);

TYPED_TEST(TransformReferenceTest, TransformMatchesDefinitionOne) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(1001 + TypeIndex(kType));
  for (int trial = 0; trial < 300; ++trial) {
    // Valid and invalid elements alike: Def. 1 needs only non-zero dual normals.
    const ElementNodes<kType> nodes = random.ElementInUnitCube<kType>();
    const double sigma = random.Uniform(0.05, 3.5);
    const Points expected = ReferenceTransform(kType, ToPoints<kType>(nodes), sigma);
    const Points actual = ToPoints<kType>(TransformElement<kType>(nodes, sigma));
    EXPECT_LT(MaxDistance(actual, expected), kTransformTolerance)
        << "trial " << trial << ", sigma " << sigma;
  }
}

TYPED_TEST(TransformReferenceTest, MeanEdgeLengthMatchesFaceEdges) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(1102 + TypeIndex(kType));
  for (int trial = 0; trial < 100; ++trial) {
    const ElementNodes<kType> nodes = random.ElementInUnitCube<kType>();
    EXPECT_NEAR(MeanEdgeLength<kType>(nodes),
                ReferenceMeanEdgeLength(kType, ToPoints<kType>(nodes)), kTransformTolerance)
        << "trial " << trial;
  }
}

TYPED_TEST(TransformReferenceTest, ScaleAndRelaxMatchesEquationsEightAndEleven) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(1203 + TypeIndex(kType));
  for (int trial = 0; trial < 300; ++trial) {
    const ElementNodes<kType> nodes = random.ValidElementInUnitCube<kType>();
    const double sigma = random.Uniform(0.05, 3.5);
    const double rho = random.Uniform(0.0, 1.0);
    const ElementNodes<kType> transformed = TransformElement<kType>(nodes, sigma);
    const Points expected =
        ReferenceScaleAndRelax(kType, ToPoints<kType>(nodes), ToPoints<kType>(transformed), rho);
    EXPECT_LT(MaxDistance(ToPoints<kType>(ScaleAndRelax<kType>(nodes, transformed, rho)), expected),
              kTransformTolerance)
        << "trial " << trial << ", sigma " << sigma << ", rho " << rho;
    EXPECT_LT(MaxDistance(ToPoints<kType>(RegularizingStep<kType>(nodes, sigma, rho)), expected),
              kTransformTolerance)
        << "trial " << trial << ", sigma " << sigma << ", rho " << rho;
  }
}

TYPED_TEST(TransformReferenceTest, RelaxationZeroKeepsTheElement) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(1304 + TypeIndex(kType));
  const ElementNodes<kType> nodes = random.ValidElementInUnitCube<kType>();
  const ElementNodes<kType> kept = RegularizingStep<kType>(nodes, 1.0, 0.0);
  EXPECT_EQ(MaxDistance(ToPoints<kType>(kept), ToPoints<kType>(nodes)), 0.0);
}

// An element collapsed to one point has zero dual normals; the step must leave it where it is
// rather than produce NaN coordinates that would spread through a mesh.
TYPED_TEST(TransformReferenceTest, CollapsedElementStaysFinite) {
  constexpr ElementType kType = TypeParam::kType;
  ElementNodes<kType> collapsed;
  collapsed.fill(Vec3(0.25, -1.5, 3.0));
  for (const Vec3& node : RegularizingStep<kType>(collapsed, 1.0, 1.0)) {
    EXPECT_TRUE(node.allFinite());
    EXPECT_LT((node - Vec3(0.25, -1.5, 3.0)).norm(), kTransformTolerance);
  }
}

}  // namespace
}  // namespace getme::test
