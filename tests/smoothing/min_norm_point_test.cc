// Wolfe's minimum-norm point of a convex hull (core/getme/smoothing/min_norm_point.h) against
// answers known in closed form, and against the optimality condition checked independently:
// x = Σλ_j g_j is the hull's nearest point to the origin iff g_j · x ≥ |x|² for every j.

#include "getme/smoothing/min_norm_point.h"

#include <gtest/gtest.h>

#include <random>

namespace getme {
namespace {

Eigen::MatrixXd Gram(const Eigen::MatrixXd& columns) { return columns.transpose() * columns; }

void ExpectWeightsOnTheSimplex(const MinNormPoint& point) {
  EXPECT_GE(point.weights.minCoeff(), 0.0);
  EXPECT_NEAR(point.weights.sum(), 1.0, 1e-12);
}

TEST(MinNormPointTest, TwoPointsGiveTheNearestPointOfTheirSegment) {
  // (1, 1) and (1, −3): the segment x = 1 passes the origin's foot (1, 0) at λ = (3/4, 1/4).
  Eigen::MatrixXd columns(2, 2);
  columns << 1.0, 1.0, 1.0, -3.0;
  const MinNormPoint point = MinNormPointOfHull(Gram(columns));
  ExpectWeightsOnTheSimplex(point);
  EXPECT_NEAR(point.weights[0], 0.75, 1e-12);
  EXPECT_NEAR(point.weights[1], 0.25, 1e-12);
  EXPECT_NEAR(point.squared_norm, 1.0, 1e-12);
}

TEST(MinNormPointTest, AHullAroundTheOriginHasNormZero) {
  Eigen::MatrixXd columns(2, 3);
  columns << 1.0, -1.0, 0.0, 0.0, 1.0, -2.0;  // (1, 0), (−1, 1), (0, −2) surround the origin
  const MinNormPoint point = MinNormPointOfHull(Gram(columns));
  ExpectWeightsOnTheSimplex(point);
  EXPECT_NEAR(point.squared_norm, 0.0, 1e-12);
  EXPECT_NEAR((columns * point.weights).norm(), 0.0, 1e-9);
}

TEST(MinNormPointTest, AVertexNearestTheOriginIsTheAnswerWhenTheRestLieBeyondIt) {
  Eigen::MatrixXd columns(3, 3);
  columns << 1.0, 2.0, 1.5, 0.0, 1.0, -1.0, 0.0, 0.5, 2.0;
  const MinNormPoint point = MinNormPointOfHull(Gram(columns));
  EXPECT_NEAR(point.weights[0], 1.0, 1e-12);
  EXPECT_NEAR(point.squared_norm, 1.0, 1e-12);
}

TEST(MinNormPointTest, RandomHullsMeetTheOptimalityCondition) {
  std::mt19937_64 random(3);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const int dimension = 2 + trial % 9;
    const int count = 1 + trial % 13;
    Eigen::MatrixXd columns(dimension, count);
    // Shifted away from the origin in most trials, so that the answer is not always zero.
    const Eigen::VectorXd shift = Eigen::VectorXd::Constant(dimension, 0.3 * (trial % 4));
    for (int j = 0; j < count; ++j) {
      for (int i = 0; i < dimension; ++i) columns(i, j) = normal(random);
      columns.col(j) += shift;
    }
    const MinNormPoint point = MinNormPointOfHull(Gram(columns));
    ExpectWeightsOnTheSimplex(point);
    const Eigen::VectorXd x = columns * point.weights;
    EXPECT_NEAR(x.squaredNorm(), point.squared_norm, 1e-12 * (1.0 + x.squaredNorm()));
    // No vertex lies on the origin's side of the plane through x normal to x.
    for (int j = 0; j < count; ++j) {
      EXPECT_GE(columns.col(j).dot(x), x.squaredNorm() - 1e-9) << "trial " << trial;
    }
  }
}

TEST(MinNormPointTest, DependentVectorsStillGiveAPointOfTheHull) {
  // Four copies of two vectors: a singular Gram matrix.
  Eigen::MatrixXd columns(2, 4);
  columns << 1.0, 1.0, 1.0, 1.0, 1.0, -3.0, 1.0, -3.0;
  const MinNormPoint point = MinNormPointOfHull(Gram(columns));
  ExpectWeightsOnTheSimplex(point);
  EXPECT_NEAR(point.squared_norm, 1.0, 1e-9);
}

}  // namespace
}  // namespace getme
