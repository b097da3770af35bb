// Regular elements (unit edges, paper node order) are valid with mean ratio 1, their mirror images
// are invalid, and the transformation maps them to regular elements for every σ — the sharpest
// check of the tables and of τ in eq. (5) (paper Sec. 2.1, the paragraph after eq. (5)).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "element_type_tags.h"
#include "getme/elements/element_quality.h"
#include "getme/elements/transform.h"
#include "random_elements.h"
#include "reference_kernels.h"
#include "regular_elements.h"

namespace getme::test {
namespace {

constexpr double kTolerance = 1e-12;

// The σ values the brief names, plus the remaining defaults of Section 4 and two extremes.
const std::vector<double> kSigmas = {0.5, 1.0, 1.86, 2.74, 0.1, 0.77, 0.81, 0.85, 1.59, 3.45};

template <typename Tag>
class RegularElementTest : public ::testing::Test {};
TYPED_TEST_SUITE(RegularElementTest, AllElementTypes, ElementTypeName);

// Every edge (from the paper's faces) has the element's mean edge length, up to kTolerance
// relative.
template <ElementType kType>
void ExpectAllEdgesEqual(const ElementNodes<kType>& nodes, const std::string& context) {
  const double mean = MeanEdgeLength<kType>(nodes);
  ASSERT_GT(mean, 0.0) << context;
  for (const auto& [a, b] : PaperEdges(kType)) {
    const double length = (nodes[b] - nodes[a]).norm();
    EXPECT_NEAR(length / mean, 1.0, kTolerance)
        << context << ": edge (" << a << ", " << b << ") has length " << length
        << ", mean edge length " << mean;
  }
}

// Proportional distance matrices: the element is similar to the unit regular element, including
// the diagonals and the apex position that the edge check alone would not see.
template <ElementType kType>
void ExpectSimilarToRegular(const ElementNodes<kType>& nodes, const std::string& context) {
  const Eigen::MatrixXd regular = DistanceMatrix(RegularElementPoints(kType));
  const Eigen::MatrixXd actual = DistanceMatrix(ToPoints<kType>(nodes));
  const double scale = MeanEdgeLength<kType>(nodes);
  const double deviation = (actual / scale - regular).cwiseAbs().maxCoeff();
  EXPECT_LT(deviation, kTolerance) << context << ": distance matrix / mean edge length\n"
                                   << actual / scale << "\nregular\n"
                                   << regular;
}

TYPED_TEST(RegularElementTest, EveryNodeTetrahedronIsCongruentToTheTarget) {
  constexpr ElementType kType = TypeParam::kType;
  const Points p = RegularElementPoints(kType);
  const Eigen::Matrix3d target = Paper(kType).target;
  for (int k = 0; k < static_cast<int>(Paper(kType).node_tets.size()); ++k) {
    const Eigen::Matrix3d d = NodeTetEdges(kType, p, k);
    // Equal Gram matrices and equal determinants: D(T_k) = R W with a rotation R.
    EXPECT_LT((d.transpose() * d - target.transpose() * target).cwiseAbs().maxCoeff(), kTolerance)
        << "node tetrahedron " << k;
    EXPECT_NEAR(d.determinant(), target.determinant(), kTolerance) << "node tetrahedron " << k;
    EXPECT_NEAR(NodeTetDeterminant<kType>(ToNodes<kType>(p), k), target.determinant(), kTolerance)
        << "library determinant of node tetrahedron " << k;
  }
}

TYPED_TEST(RegularElementTest, HasUnitEdges) {
  constexpr ElementType kType = TypeParam::kType;
  const ElementNodes<kType> regular = RegularElement<kType>();
  EXPECT_NEAR(MeanEdgeLength<kType>(regular), 1.0, kTolerance);
  ExpectAllEdgesEqual<kType>(regular, "regular element");
}

TYPED_TEST(RegularElementTest, IsValidWithMeanRatioOne) {
  constexpr ElementType kType = TypeParam::kType;
  const ElementNodes<kType> regular = RegularElement<kType>();
  EXPECT_TRUE(IsValid<kType>(regular));
  EXPECT_NEAR(MeanRatio<kType>(regular), 1.0, kTolerance);
  EXPECT_NEAR(ReferenceMeanRatio(kType, RegularElementPoints(kType)), 1.0, kTolerance);
  EXPECT_NEAR(QualityGamma<kType>(regular, 2.0), 1.0, kTolerance);
  EXPECT_EQ(Warpage<kType>(regular), 0.0);
}

TYPED_TEST(RegularElementTest, MirrorImageIsInvalidWithMeanRatioZero) {
  constexpr ElementType kType = TypeParam::kType;
  const ElementNodes<kType> mirrored = ToNodes<kType>(Mirrored(RegularElementPoints(kType)));
  EXPECT_FALSE(IsValid<kType>(mirrored));
  EXPECT_EQ(MeanRatio<kType>(mirrored), 0.0);
  for (int k = 0; k < static_cast<int>(Paper(kType).node_tets.size()); ++k) {
    EXPECT_NEAR(NodeTetDeterminant<kType>(mirrored, k), -Paper(kType).target.determinant(),
                kTolerance)
        << "node tetrahedron " << k;
  }
}

TYPED_TEST(RegularElementTest, TransformAloneYieldsASimilarRegularElement) {
  constexpr ElementType kType = TypeParam::kType;
  const ElementNodes<kType> regular = RegularElement<kType>();
  for (double sigma : kSigmas) {
    const std::string context = "sigma " + std::to_string(sigma);
    const ElementNodes<kType> transformed = TransformElement<kType>(regular, sigma);
    EXPECT_TRUE(IsValid<kType>(transformed)) << context;
    EXPECT_NEAR(MeanRatio<kType>(transformed), 1.0, kTolerance) << context;
    ExpectAllEdgesEqual<kType>(transformed, context);
    ExpectSimilarToRegular<kType>(transformed, context);
  }
}

TYPED_TEST(RegularElementTest, StaysRegularUnderTransformAndScaling) {
  constexpr ElementType kType = TypeParam::kType;
  const ElementNodes<kType> regular = RegularElement<kType>();
  const Vec3 centroid = Centroid<kType>(regular);
  for (double sigma : kSigmas) {
    const std::string context = "sigma " + std::to_string(sigma);
    const ElementNodes<kType> step =
        ScaleAndRelax<kType>(regular, TransformElement<kType>(regular, sigma), 1.0);
    EXPECT_NEAR(MeanRatio<kType>(step), 1.0, kTolerance) << context;
    EXPECT_NEAR(ReferenceMeanRatio(kType, ToPoints<kType>(step)), 1.0, kTolerance) << context;
    EXPECT_NEAR(MeanEdgeLength<kType>(step), 1.0, kTolerance) << context;
    ExpectAllEdgesEqual<kType>(step, context);
    ExpectSimilarToRegular<kType>(step, context);
    EXPECT_LT((Centroid<kType>(step) - centroid).norm(), kTolerance) << context;
  }
}

TYPED_TEST(RegularElementTest, StaysRegularInAnyPlacement) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(20240601 + TypeIndex(kType));
  for (int trial = 0; trial < 20; ++trial) {
    const Similarity placement = random.RandomSimilarity();
    const ElementNodes<kType> placed = ToNodes<kType>(placement(RegularElementPoints(kType)));
    // Coordinates are of size |t| + ζ, so absolute rounding errors scale with that.
    const double size = placement.translation.norm() + placement.scale;
    for (double sigma : kSigmas) {
      const std::string context =
          "trial " + std::to_string(trial) + ", sigma " + std::to_string(sigma);
      const ElementNodes<kType> step = RegularizingStep<kType>(placed, sigma, 1.0);
      EXPECT_NEAR(MeanRatio<kType>(step), 1.0, kTolerance * size / placement.scale) << context;
      EXPECT_NEAR(MeanEdgeLength<kType>(step) / placement.scale, 1.0,
                  kTolerance * size / placement.scale)
          << context;
      EXPECT_LT((Centroid<kType>(step) - Centroid<kType>(placed)).norm(), kTolerance * size)
          << context;
    }
  }
}

TYPED_TEST(RegularElementTest, StaysRegularOverRepeatedSteps) {
  constexpr ElementType kType = TypeParam::kType;
  ElementNodes<kType> nodes = RegularElement<kType>();
  for (int step = 1; step <= 50; ++step) {
    nodes = RegularizingStep<kType>(nodes, 1.0, 1.0);
    EXPECT_NEAR(MeanRatio<kType>(nodes), 1.0, kTolerance) << "step " << step;
  }
  ExpectAllEdgesEqual<kType>(nodes, "after 50 steps");
  ExpectSimilarToRegular<kType>(nodes, "after 50 steps");
}

// The pyramid's and prism's τ are what keeps them regular: with the tetrahedron's choice b_k = c_k
// for every node (τ = 2/3), a regular pyramid or prism does not stay regular. This guards the test
// above against passing for a reason unrelated to τ.
TEST(RegularElementTauTest, CentroidBasePointsWouldBreakPyramidAndPrismRegularity) {
  for (ElementType type : {ElementType::kPyramid, ElementType::kPrism}) {
    const Points regular = RegularElementPoints(type);
    const Points d = DualNodes(type, regular);
    const Points n = ReferenceDualNormals(type, regular);
    Points transformed;
    for (std::size_t k = 0; k < regular.size(); ++k) {
      const IndexTuple& face = Paper(type).dual_faces[k];
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for (int node : face) centroid += d[node];
      centroid /= static_cast<double>(face.size());
      transformed.push_back(centroid + n[k] / std::sqrt(n[k].norm()));
    }
    const std::vector<double> lengths = EdgeLengths(type, transformed);
    const auto [shortest, longest] = std::minmax_element(lengths.begin(), lengths.end());
    EXPECT_GT(*longest / *shortest - 1.0, 1e-3) << TypeName(type);
  }
}

}  // namespace
}  // namespace getme::test
