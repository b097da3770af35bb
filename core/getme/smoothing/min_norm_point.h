#pragma once

// The point of smallest norm in the convex hull of a few vectors, given only their Gram matrix:
// the weights λ ≥ 0, Σλ = 1, that minimise λᵀKλ. It is the steepest-ascent direction of a
// minimum of smooth functions (the worst-cluster stage's min q over its elements, worst_cluster.h):
// among the directions that raise every active element, the one that raises the least-raised the
// most (Freitag and Plassmann's max-min step for mesh smoothing uses the same point).
//
// Solved by Wolfe's algorithm (P. Wolfe, "Finding the nearest point in a polytope", Math.
// Programming 11, 1976): a corral of vectors whose affine minimum-norm point lies inside their
// hull grows by the vector most opposed to the current point, and shrinks when the affine point
// falls outside. Exact up to rounding in finitely many steps; capped here, since a singular Gram
// matrix (dependent vectors) can make it cycle.

#include <Eigen/Core>

namespace getme {

struct MinNormPoint {
  Eigen::VectorXd weights;  // λ: non-negative, summing to 1
  double squared_norm = 0;  // λᵀKλ
};

// `gram` must be symmetric positive semi-definite and at least 1 × 1.
MinNormPoint MinNormPointOfHull(const Eigen::MatrixXd& gram);

}  // namespace getme
