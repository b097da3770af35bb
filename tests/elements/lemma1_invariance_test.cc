// Lemma 1: the transformation commutes with similarities x ↦ ζRx + t (det R = 1, ζ > 0), and the
// mean ratio is invariant under them.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "element_type_tags.h"
#include "getme/elements/element_quality.h"
#include "getme/elements/transform.h"
#include "random_elements.h"
#include "reference_kernels.h"

namespace getme::test {
namespace {

constexpr double kRelativeTolerance = 1e-12;
constexpr int kTrials = 200;

template <typename Tag>
class Lemma1InvarianceTest : public ::testing::Test {};
TYPED_TEST_SUITE(Lemma1InvarianceTest, AllElementTypes, ElementTypeName);

// The magnitude of the coordinates of ζ R x + t over an element, which bounds the absolute
// rounding error of any computation on them.
double CoordinateScale(const Similarity& similarity, const Points& p) {
  double max_norm = 0.0;
  for (const Eigen::Vector3d& x : p) max_norm = std::max(max_norm, x.norm());
  return similarity.scale * max_norm + similarity.translation.norm();
}

// A scale-free quantity (the mean ratio) of the image is known only to the relative precision of
// the image's shape: coordinate magnitude over element size, which grows when a small ζ meets a
// large t. Elements here have size ~1 before the map, ζ after it.
double ShapeTolerance(const Similarity& similarity, const Points& p) {
  return kRelativeTolerance * std::max(1.0, CoordinateScale(similarity, p) / similarity.scale);
}

TYPED_TEST(Lemma1InvarianceTest, TransformCommutesWithSimilarities) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(101 + TypeIndex(kType));
  for (int trial = 0; trial < kTrials; ++trial) {
    const ElementNodes<kType> nodes = random.ValidElementInUnitCube<kType>();
    const Similarity similarity = random.RandomSimilarity();
    const double sigma = random.Uniform(0.1, 3.5);
    const Points of_image = ToPoints<kType>(
        TransformElement<kType>(ToNodes<kType>(similarity(ToPoints<kType>(nodes))), sigma));
    const Points image_of = similarity(ToPoints<kType>(TransformElement<kType>(nodes, sigma)));
    const double scale =
        CoordinateScale(similarity, ToPoints<kType>(TransformElement<kType>(nodes, sigma)));
    EXPECT_LE(MaxDistance(of_image, image_of), kRelativeTolerance * scale)
        << "trial " << trial << ", sigma " << sigma << ", zeta " << similarity.scale;
  }
}

TYPED_TEST(Lemma1InvarianceTest, RegularizingStepCommutesWithSimilarities) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(202 + TypeIndex(kType));
  for (int trial = 0; trial < kTrials; ++trial) {
    const ElementNodes<kType> nodes = random.ValidElementInUnitCube<kType>();
    const Similarity similarity = random.RandomSimilarity();
    const double sigma = random.Uniform(0.1, 3.5);
    const double rho = random.Uniform(0.01, 1.0);
    const ElementNodes<kType> step = RegularizingStep<kType>(nodes, sigma, rho);
    const Points of_image = ToPoints<kType>(
        RegularizingStep<kType>(ToNodes<kType>(similarity(ToPoints<kType>(nodes))), sigma, rho));
    const Points image_of = similarity(ToPoints<kType>(step));
    EXPECT_LE(MaxDistance(of_image, image_of),
              kRelativeTolerance * CoordinateScale(similarity, ToPoints<kType>(step)))
        << "trial " << trial << ", sigma " << sigma << ", rho " << rho;
  }
}

TYPED_TEST(Lemma1InvarianceTest, MeanRatioIsInvariantUnderSimilarities) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(303 + TypeIndex(kType));
  for (int trial = 0; trial < kTrials; ++trial) {
    const ElementNodes<kType> nodes = random.ValidElementInUnitCube<kType>();
    const Similarity similarity = random.RandomSimilarity();
    const ElementNodes<kType> image = ToNodes<kType>(similarity(ToPoints<kType>(nodes)));
    EXPECT_TRUE(IsValid<kType>(image)) << "trial " << trial;
    const double tolerance = ShapeTolerance(similarity, ToPoints<kType>(nodes));
    EXPECT_NEAR(MeanRatio<kType>(image), MeanRatio<kType>(nodes), tolerance)
        << "trial " << trial << ", zeta " << similarity.scale;
    // And after a step, so that invariance holds along a whole regularization.
    const ElementNodes<kType> step = TransformElement<kType>(nodes, 1.0);
    const ElementNodes<kType> image_step = TransformElement<kType>(image, 1.0);
    EXPECT_NEAR(MeanRatio<kType>(image_step), MeanRatio<kType>(step), tolerance)
        << "trial " << trial << ", zeta " << similarity.scale;
  }
}

// Lemma 1 needs det R = +1: a mirror flips the dual normals (n ↦ −Mn), so the transformation of a
// mirror image is not the mirror image of the transformation. This guards the tests above against
// a similarity generator that only ever produced the identity's neighbourhood.
TYPED_TEST(Lemma1InvarianceTest, MirrorsAreNotSymmetriesOfTheTransformation) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(404 + TypeIndex(kType));
  const ElementNodes<kType> nodes = random.ValidElementInUnitCube<kType>();
  const Points of_mirror = ToPoints<kType>(
      TransformElement<kType>(ToNodes<kType>(Mirrored(ToPoints<kType>(nodes))), 1.0));
  const Points mirror_of = Mirrored(ToPoints<kType>(TransformElement<kType>(nodes, 1.0)));
  EXPECT_GT(MaxDistance(of_mirror, mirror_of), 0.1);
}

}  // namespace
}  // namespace getme::test
