#include "getme/smoothing/min_norm_point.h"

#include <Eigen/LU>
#include <algorithm>
#include <vector>

namespace getme {
namespace {

// Wolfe's algorithm ends in finitely many steps in exact arithmetic; these caps only stop a
// cycle that rounding on dependent vectors can cause.
constexpr int kMaxMajorSteps = 200;
constexpr int kMaxMinorSteps = 200;

}  // namespace

MinNormPoint MinNormPointOfHull(const Eigen::MatrixXd& gram) {
  const Eigen::Index k = gram.rows();
  const double scale = std::max(gram.diagonal().maxCoeff(), 0.0);
  // Optimality and zero weights are judged relative to the vectors' own size.
  const double tolerance = 1e-12 * scale;
  Eigen::VectorXd weights = Eigen::VectorXd::Zero(k);
  Eigen::Index first = 0;
  gram.diagonal().minCoeff(&first);
  weights[first] = 1.0;
  std::vector<Eigen::Index> corral = {first};
  for (int major = 0; major < kMaxMajorSteps; ++major) {
    const Eigen::VectorXd products = gram * weights;  // g_j · x for the current point x
    const double squared_norm = weights.dot(products);
    Eigen::Index entering = 0;
    const double lowest = products.minCoeff(&entering);
    // x is the hull's nearest point to the origin when no vector lies beyond its plane.
    if (lowest >= squared_norm - tolerance) break;
    if (std::find(corral.begin(), corral.end(), entering) != corral.end()) break;
    corral.push_back(entering);
    for (int minor = 0; minor < kMaxMinorSteps; ++minor) {
      // The corral's affine minimum-norm point: K_S μ + ν 1 = 0, 1ᵀμ = 1.
      const Eigen::Index s = static_cast<Eigen::Index>(corral.size());
      Eigen::MatrixXd system = Eigen::MatrixXd::Zero(s + 1, s + 1);
      for (Eigen::Index a = 0; a < s; ++a) {
        for (Eigen::Index b = 0; b < s; ++b) system(a, b) = gram(corral[a], corral[b]);
        system(a, s) = 1.0;
        system(s, a) = 1.0;
      }
      Eigen::VectorXd right = Eigen::VectorXd::Zero(s + 1);
      right[s] = 1.0;
      const Eigen::VectorXd affine = system.fullPivLu().solve(right);
      if ((affine.head(s).array() > 0.0).all()) {
        for (Eigen::Index a = 0; a < s; ++a) weights[corral[a]] = affine[a];
        break;
      }
      // The affine point is outside the corral's hull: walk from the current weights towards it
      // until a weight reaches zero, and drop the vectors whose weight did.
      double step = 1.0;
      for (Eigen::Index a = 0; a < s; ++a) {
        const double current = weights[corral[a]];
        if (affine[a] <= 0.0) step = std::min(step, current / (current - affine[a]));
      }
      for (Eigen::Index a = 0; a < s; ++a) {
        weights[corral[a]] += step * (affine[a] - weights[corral[a]]);
      }
      std::vector<Eigen::Index> kept;
      for (const Eigen::Index j : corral) {
        if (weights[j] > 1e-15) {
          kept.push_back(j);
        } else {
          weights[j] = 0.0;
        }
      }
      corral.swap(kept);
      if (corral.empty()) {  // only by rounding: restart from the best single vector
        weights.setZero();
        weights[first] = 1.0;
        corral = {first};
        break;
      }
    }
    weights /= weights.sum();
  }
  MinNormPoint result;
  result.squared_norm = weights.dot(gram * weights);
  result.weights = std::move(weights);
  return result;
}

}  // namespace getme
