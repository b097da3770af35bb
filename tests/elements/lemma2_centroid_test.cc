// Lemma 2 and the paragraph after it: the mean base point q_b' equals the centroid q for
// tetrahedra, hexahedra and prisms; the hexahedral transformation preserves the centroid; for
// tetrahedra, pyramids and prisms it does not in general; eq. (8) restores it for all types.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "element_type_tags.h"
#include "getme/elements/transform.h"
#include "random_elements.h"
#include "reference_kernels.h"
#include "regular_elements.h"

namespace getme::test {
namespace {

constexpr double kTolerance = 1e-12;
const std::vector<double> kSigmas = {0.5, 1.0, 1.86, 2.74};

template <typename Tag>
class MeanBasePointTest : public ::testing::Test {};
using TypesWithCentroidBasePoints = ::testing::Types<TetTag, HexTag, PrismTag>;
TYPED_TEST_SUITE(MeanBasePointTest, TypesWithCentroidBasePoints, ElementTypeName);

// The base points are reconstructed from eqs. (1), (3) and (5) in reference_kernels.h; the prism's
// holds for every τ, so σ (which sets τ) must not matter. Invalid elements are included: the
// lemma is pure linear algebra.
TYPED_TEST(MeanBasePointTest, MeanBasePointIsTheCentroid) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(505 + TypeIndex(kType));
  for (int trial = 0; trial < 200; ++trial) {
    const Points p = ToPoints<kType>(random.ElementInUnitCube<kType>());
    for (double sigma : kSigmas) {
      const Eigen::Vector3d q_b = Mean(ReferenceBasePoints(kType, p, sigma));
      EXPECT_LT((q_b - Mean(p)).norm(), kTolerance) << "trial " << trial << ", sigma " << sigma;
    }
  }
}

// q_b' = q ties to the library: its transformed nodes minus the σ-scaled normals are those base
// points.
TYPED_TEST(MeanBasePointTest, LibraryNodesMinusNormalTermsAverageToTheCentroid) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(606 + TypeIndex(kType));
  for (int trial = 0; trial < 200; ++trial) {
    const ElementNodes<kType> nodes = random.ValidElementInUnitCube<kType>();
    const Points n = ReferenceDualNormals(kType, ToPoints<kType>(nodes));
    for (double sigma : kSigmas) {
      const ElementNodes<kType> transformed = TransformElement<kType>(nodes, sigma);
      Eigen::Vector3d q_b = Eigen::Vector3d::Zero();
      for (std::size_t k = 0; k < n.size(); ++k) {
        q_b += transformed[k] - sigma * n[k] / std::sqrt(n[k].norm());
      }
      q_b /= static_cast<double>(n.size());
      EXPECT_LT((q_b - Centroid<kType>(nodes)).norm(), kTolerance)
          << "trial " << trial << ", sigma " << sigma;
    }
  }
}

TEST(HexahedronCentroidTest, TransformationPreservesTheCentroid) {
  constexpr ElementType kHex = ElementType::kHexahedron;
  UnitRandom random(707);
  for (int trial = 0; trial < 200; ++trial) {
    const ElementNodes<kHex> nodes = random.ElementInUnitCube<kHex>();
    for (double sigma : kSigmas) {
      const ElementNodes<kHex> transformed = TransformElement<kHex>(nodes, sigma);
      EXPECT_LT((Centroid<kHex>(transformed) - Centroid<kHex>(nodes)).norm(), kTolerance)
          << "trial " << trial << ", sigma " << sigma;
    }
  }
}

// Why q' = q for hexahedra: the dual octahedron is point-symmetric about q (d0 + d5 = d1 + d3 =
// d2 + d4 = 2q), opposite dual faces have opposite normals, and so the transformed hexahedron is
// point-symmetric too: p'_k + p'_opposite(k) = 2q for the space diagonals (0,6) (1,7) (2,4) (3,5).
TEST(HexahedronCentroidTest, TransformedHexahedronIsPointSymmetricAboutTheCentroid) {
  constexpr ElementType kHex = ElementType::kHexahedron;
  const int kOpposite[8] = {6, 7, 4, 5, 2, 3, 0, 1};
  UnitRandom random(808);
  for (int trial = 0; trial < 200; ++trial) {
    const ElementNodes<kHex> nodes = random.ElementInUnitCube<kHex>();
    const Vec3 q = Centroid<kHex>(nodes);
    const ElementNodes<kHex> transformed = TransformElement<kHex>(nodes, 1.0);
    for (int k = 0; k < 8; ++k) {
      EXPECT_LT((transformed[k] + transformed[kOpposite[k]] - 2.0 * q).norm(), kTolerance)
          << "trial " << trial << ", node " << k;
    }
  }
}

// Counterexamples (the paper: "as can be shown by simple counterexamples"): the centroid moves.
template <ElementType kType>
double CentroidShift(const Points& p, double sigma) {
  const ElementNodes<kType> nodes = ToNodes<kType>(p);
  return (Centroid<kType>(TransformElement<kType>(nodes, sigma)) - Centroid<kType>(nodes)).norm();
}

TEST(CentroidCounterexampleTest, CornerTetrahedronMovesItsCentroid) {
  // Three faces of area 1/2 and one of area √3/2: the normals, weighted by 1/sqrt(|n|), no longer
  // sum to zero.
  const Points corner = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  EXPECT_GT(CentroidShift<ElementType::kTetrahedron>(corner, 1.0), 1e-3);
}

TEST(CentroidCounterexampleTest, PrismWithRightTriangleBaseMovesItsCentroid) {
  const Points prism = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
  EXPECT_GT(CentroidShift<ElementType::kPrism>(prism, 1.0), 1e-3);
}

TEST(CentroidCounterexampleTest, PyramidWithApexOverACornerMovesItsCentroid) {
  const Points pyramid = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}};
  EXPECT_GT(CentroidShift<ElementType::kPyramid>(pyramid, 1.0), 1e-3);
}

// For pyramids not even the mean base point is the centroid.
TEST(CentroidCounterexampleTest, PyramidMeanBasePointIsNotTheCentroid) {
  const Points pyramid = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}};
  const Eigen::Vector3d q_b = Mean(ReferenceBasePoints(ElementType::kPyramid, pyramid, 1.0));
  EXPECT_GT((q_b - Mean(pyramid)).norm(), 1e-3);
}

template <typename Tag>
class CentroidRestorationTest : public ::testing::Test {};
TYPED_TEST_SUITE(CentroidRestorationTest, AllElementTypes, ElementTypeName);

// eq. (8) puts the centroid back and eq. (11) keeps it for any ρ, since both E and E'_s have
// centroid q; with ρ = 1 the mean edge length is the original one.
TYPED_TEST(CentroidRestorationTest, ScaleAndRelaxRestoresTheCentroid) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(909 + TypeIndex(kType));
  for (int trial = 0; trial < 200; ++trial) {
    const ElementNodes<kType> nodes = random.ValidElementInUnitCube<kType>();
    const Vec3 q = Centroid<kType>(nodes);
    for (double sigma : kSigmas) {
      const ElementNodes<kType> transformed = TransformElement<kType>(nodes, sigma);
      for (double rho : {1.0, 2.0 / 3.0, 0.01}) {
        const ElementNodes<kType> relaxed = ScaleAndRelax<kType>(nodes, transformed, rho);
        EXPECT_LT((Centroid<kType>(relaxed) - q).norm(), kTolerance)
            << "trial " << trial << ", sigma " << sigma << ", rho " << rho;
      }
      const ElementNodes<kType> scaled = ScaleAndRelax<kType>(nodes, transformed, 1.0);
      EXPECT_NEAR(MeanEdgeLength<kType>(scaled), MeanEdgeLength<kType>(nodes), kTolerance)
          << "trial " << trial << ", sigma " << sigma;
    }
  }
}

}  // namespace
}  // namespace getme::test
