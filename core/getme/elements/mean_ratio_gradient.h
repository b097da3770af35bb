#pragma once

// The mean ratio q(E) of Def. 3 / eq. (10) and its gradient with respect to every node of the
// element at once, for the worst-cluster stage (smoothing/worst_cluster.h), which moves all free
// nodes around the worst elements together and so needs ∂q/∂p_i for each of them.
//
// With u_k = 1/q_k = |S_k|_F² / (3 det(S_k)^{2/3}) per node tetrahedron T_k (the inverse terms of
// mean_ratio_derivatives.h, whose header derives ∇u_k for one corner t_m of T_k),
//   q(E) = (1/K) Σ_k q_k,   ∇_{p_{t_m}} q_k = −q_k² ∇_{p_{t_m}} u_k,
// and node i's gradient is the sum over the node tetrahedra that have i as a corner.

#include <array>
#include <cmath>

#include "getme/elements/cube_root.h"
#include "getme/elements/element_quality.h"
#include "getme/elements/element_tables.h"
#include "getme/elements/mean_ratio_derivatives.h"
#include "getme/elements/vec3.h"

namespace getme {

template <ElementType kType>
struct MeanRatioGradientResult {
  // q(E), unclamped, or kInvalidQuality (and the gradient left zero) for an invalid element.
  double quality = kInvalidQuality;
  std::array<Vec3, ElementTable<kType>::kNodes> gradient{};
};

// `needed` has bit i set for each node i whose gradient the caller uses; the others are left zero
// (a stage that moves only free nodes skips the rest of the work).
template <ElementType kType>
inline MeanRatioGradientResult<kType> MeanRatioWithGradient(const ElementNodes<kType>& p,
                                                            unsigned needed = ~0u) {
  using Table = ElementTable<kType>;
  constexpr auto& w = Table::kTargetInverse;
  constexpr double kDetWInverse = w[0][0] * w[1][1] * w[2][2];
  constexpr double kInverseTets = 1.0 / static_cast<double>(Table::kNodeTets.size());
  // Row m of E W⁻¹ for the tetrahedron's corners m = 0..3 (E's rows: (−1, −1, −1), e_1ᵗ, e_2ᵗ,
  // e_3ᵗ), constant per element type.
  const std::array<Vec3, 4> b = {
      -Vec3(w[0][0] + w[1][0] + w[2][0], w[0][1] + w[1][1] + w[2][1], w[0][2] + w[1][2] + w[2][2]),
      Vec3(w[0][0], w[0][1], w[0][2]), Vec3(w[1][0], w[1][1], w[1][2]),
      Vec3(w[2][0], w[2][1], w[2][2])};

  MeanRatioGradientResult<kType> result;
  for (Vec3& g : result.gradient) g.setZero();
  double quality = 0.0;
  for (const auto& t : Table::kNodeTets) {
    internal::NodeTetFrame frame;
    if (!internal::MakeNodeTetFrame<kType>(p, t, frame)) {
      for (Vec3& g : result.gradient) g.setZero();
      return result;
    }
    const auto& [d0, d1, d2, d1xd2, s0, s1, s2, det_s, frobenius2] = frame;
    const Vec3 d2xd0 = d2.cross(d0);
    const Vec3 d0xd1 = d0.cross(d1);
    const double root = CubeRoot(det_s * det_s);
    const double q_k = 3.0 * root / frobenius2;
    quality += q_k;
    // ∇u_k = a (∇N − (2/3)(N/δ) v) with a = 1/(3 δ^{2/3}), ∇N = 2 S b_m, v = ∂δ/∂p_{t_m}; the
    // factor −q_k² a turns it into ∇q_k.
    const double scale = -q_k * q_k / (3.0 * root);
    const double n_over_det = frobenius2 / det_s;
    // ∂det D/∂p_{t_m}: det D = d0 · (d1 × d2) is linear in each edge, p_{t_0} enters all three.
    const std::array<Vec3, 4> ddet = {-(d1xd2 + d2xd0 + d0xd1), d1xd2, d2xd0, d0xd1};
    for (int m = 0; m < 4; ++m) {
      if (((needed >> t[m]) & 1u) == 0) continue;
      const Vec3 grad_n = 2.0 * (s0 * b[m][0] + s1 * b[m][1] + s2 * b[m][2]);
      const Vec3 v = kDetWInverse * ddet[m];
      result.gradient[t[m]] += scale * (grad_n - (2.0 / 3.0) * n_over_det * v);
    }
  }
  for (Vec3& g : result.gradient) g *= kInverseTets;
  result.quality = quality * kInverseTets;
  return result;
}

}  // namespace getme
