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
#include <type_traits>

#include "getme/elements/cube_root.h"
#include "getme/elements/element_quality.h"
#include "getme/elements/element_tables.h"
#include "getme/elements/mean_ratio_derivatives.h"
#include "getme/elements/vec3.h"

namespace getme {

// Over lanes (lanes.h): kLaneCount<S> elements side by side, each lane with the bits the
// one-element function below gives, so the worst-cluster stage can evaluate several elements at a
// time (element_passes.h, MeanRatioGradientListPass). An invalid lane has quality
// kInvalidQuality and a zero gradient.
template <ElementType kType, typename S>
struct MeanRatioGradientOf {
  S quality;
  std::array<Point3<S>, ElementTable<kType>::kNodes> gradient;
};

// `needed` has bit i set for each node i whose gradient the caller uses. One element at a time
// (S = double) the others are left zero, so a stage that moves only free nodes skips the rest of
// the work; over lanes, whose elements need different nodes, every node's gradient is computed.
// A node's gradient has the same bits either way: its terms add in node-tetrahedron order.
template <ElementType kType, typename S>
GETME_LANE_INLINE MeanRatioGradientOf<kType, S> MeanRatioWithGradientOf(
    const LaneNodes<kType, S>& p, [[maybe_unused]] unsigned needed = ~0u) {
  using Table = ElementTable<kType>;
  constexpr auto& w = Table::kTargetInverse;
  constexpr double kDetWInverse = w[0][0] * w[1][1] * w[2][2];
  constexpr double kInverseTets = 1.0 / static_cast<double>(Table::kNodeTets.size());
  constexpr bool kOneElement = std::is_same_v<S, double>;
  // Row m of E W⁻¹ for the tetrahedron's corners m = 0..3 (E's rows: (−1, −1, −1), e_1ᵗ, e_2ᵗ,
  // e_3ᵗ), constant per element type.
  constexpr std::array<std::array<double, 3>, 4> b = {
      {{-(w[0][0] + w[1][0] + w[2][0]), -(w[0][1] + w[1][1] + w[2][1]),
        -(w[0][2] + w[1][2] + w[2][2])},
       {w[0][0], w[0][1], w[0][2]},
       {w[1][0], w[1][1], w[1][2]},
       {w[2][0], w[2][1], w[2][2]}}};

  MeanRatioGradientOf<kType, S> result;
  for (Point3<S>& g : result.gradient) g = {Splat<S>(0.0), Splat<S>(0.0), Splat<S>(0.0)};
  S quality = Splat<S>(0.0);
  auto valid = AllLanes<S>();
  for (const auto& t : Table::kNodeTets) {
    const NodeTetFrameOf<S> f = NodeTetFrameAt<kType, S>(p, t);
    if constexpr (kOneElement) {
      if (!(f.det_d > 0.0)) {
        for (Point3<S>& g : result.gradient) g = {0.0, 0.0, 0.0};
        result.quality = kInvalidQuality;
        return result;
      }
    } else {
      valid = Both(valid, f.det_d > 0.0);
    }
    const Point3<S> d2xd0 = Cross(f.d2, f.d0);
    const Point3<S> d0xd1 = Cross(f.d0, f.d1);
    const S root = CubeRoot(f.det_s * f.det_s);
    const S q_k = 3.0 * root / f.frobenius2;
    quality += q_k;
    // ∇u_k = a (∇N − (2/3)(N/δ) v) with a = 1/(3 δ^{2/3}), ∇N = 2 S b_m, v = ∂δ/∂p_{t_m}; the
    // factor −q_k² a turns it into ∇q_k.
    const S scale = -q_k * q_k / (3.0 * root);
    const S n_over_det = f.frobenius2 / f.det_s;
    const S along_v = (2.0 / 3.0) * n_over_det;
    // ∂det D/∂p_{t_m}: det D = d0 · (d1 × d2) is linear in each edge, p_{t_0} enters all three.
    const std::array<Point3<S>, 4> ddet = {-1.0 * (f.d1xd2 + d2xd0 + d0xd1), f.d1xd2, d2xd0, d0xd1};
    for (int m = 0; m < 4; ++m) {
      if constexpr (kOneElement) {
        if (((needed >> t[m]) & 1u) == 0) continue;
      }
      const Point3<S> grad_n = 2.0 * (f.s0 * b[m][0] + f.s1 * b[m][1] + f.s2 * b[m][2]);
      const Point3<S> v = kDetWInverse * ddet[m];
      result.gradient[t[m]] += scale * (grad_n - along_v * v);
    }
  }
  for (Point3<S>& g : result.gradient) g = g * kInverseTets;
  result.quality = quality * kInverseTets;
  if constexpr (!kOneElement) {
    result.quality = Select(valid, result.quality, Splat<S>(kInvalidQuality));
    for (Point3<S>& g : result.gradient) {
      g = {Select(valid, g.x, Splat<S>(0.0)), Select(valid, g.y, Splat<S>(0.0)),
           Select(valid, g.z, Splat<S>(0.0))};
    }
  }
  return result;
}

template <ElementType kType>
struct MeanRatioGradientResult {
  // q(E), unclamped, or kInvalidQuality (and the gradient left zero) for an invalid element.
  double quality = kInvalidQuality;
  std::array<Vec3, ElementTable<kType>::kNodes> gradient{};
};

template <ElementType kType>
inline MeanRatioGradientResult<kType> MeanRatioWithGradient(const ElementNodes<kType>& p,
                                                            unsigned needed = ~0u) {
  const MeanRatioGradientOf<kType, double> lanes =
      MeanRatioWithGradientOf<kType, double>(ToLaneNodes<kType>(p), needed);
  MeanRatioGradientResult<kType> result;
  result.quality = lanes.quality;
  for (int k = 0; k < ElementTable<kType>::kNodes; ++k) {
    result.gradient[k] = Vec3(lanes.gradient[k].x, lanes.gradient[k].y, lanes.gradient[k].z);
  }
  return result;
}

}  // namespace getme
