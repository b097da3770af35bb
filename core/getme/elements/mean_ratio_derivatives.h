#pragma once

// The local objective of a derivative-based polish after GETMe (issue 14) and its exact gradient
// and Hessian with respect to one node, templated on the element type. Scalar double only: a
// polish step works on one node and the few elements around it.
//
// Which cost. Def. 3 / eq. (10) averages the tetrahedral mean ratio q_k = 3 det(S_k)^{2/3} /
// |S_k|_F² over the element's node tetrahedra T_k (eq. 9), S_k = D(T_k) W⁻¹. The cost here is the
// mean of the reciprocals,
//
//   c(E) = (1/K) Σ_k 1/q_k = (1/K) Σ_k |S_k|_F² / (3 det(S_k)^{2/3}),
//
// not 1/q(E), for three reasons:
//   - Barrier (Def. 2). One flattening node tetrahedron (det S_k → 0⁺) sends its 1/q_k to +∞, so
//     c(E) → +∞ as well; q(E) would only lose one of its K terms and stay positive, so 1/q(E)
//     stays finite and would let a minimiser flatten a corner of a hexahedron, prism or pyramid.
//   - Convexity in one node. Moving node i by x changes S_k by x b_kᵗ (rank one), so |S_k|_F² is
//     a convex quadratic and det S_k is affine in x; (u, t) ↦ |u|² / t^{2/3} is jointly convex for
//     t > 0 (its Hessian has a non-negative Schur complement), hence each 1/q_k, and so c(E) and
//     any sum of such costs over a node's elements, is convex on the region where every element
//     is valid (an intersection of half-spaces, so convex itself): node-local Newton steps are
//     well posed.
//   - It is the objective of the global optimiser the polish is measured against: Mesquite's
//     feasible Newton minimises the average over corner tetrahedra of this same per-tetrahedron
//     inverse mean ratio.
// c(E) ≥ 1 (every q_k ≤ 1, Def. 3), with equality when every S_k is a multiple of a rotation, as in
// a regular element; by the arithmetic–harmonic mean inequality c(E) ≥ 1/q(E), with equality for
// a tetrahedron (K = 1).
// Like q it is invariant under translation, rotation and uniform scaling (Lemma 1).
//
// Derivatives. For node tetrahedron T_k = (t_0, t_1, t_2, t_3) the edge matrix is D = P E with
// P = [p_{t_0} … p_{t_3}] and E's rows (−1, −1, −1), e_1ᵗ, e_2ᵗ, e_3ᵗ, so S = Σ_m p_{t_m} b_mᵗ
// with b_mᵗ row m of E W⁻¹. With N = |S|_F², δ = det S and node t_m moved by x:
//   ∇N = 2 S b_m,  ∇²N = 2 |b_m|² I,
//   ∇δ = v = det(W⁻¹) ∂det D/∂p_{t_m} (a cross product of two edges),  ∇²δ = 0 (δ is affine),
// and for 1/q = N δ^{-2/3} / 3:
//   ∇(1/q)  = a (∇N − (2/3)(N/δ) v),
//   ∇²(1/q) = a (2|b_m|² I − (2/(3δ)) (∇N vᵗ + v ∇Nᵗ) + (10/9)(N/δ²) v vᵗ),  a = 1/(3 δ^{2/3}).
// A node belongs to several node tetrahedra (to all four of a pyramid's, as the apex): their terms
// are summed, then divided by K like the cost.

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "getme/elements/cube_root.h"
#include "getme/elements/element_quality.h"
#include "getme/elements/element_tables.h"
#include "getme/elements/vec3.h"

namespace getme {

// The cost c(E) and its gradient with respect to one node.
struct InverseMeanRatioGradientResult {
  double cost;
  Vec3 gradient;
};

// The cost c(E), its gradient and its 3×3 Hessian block with respect to one node.
struct InverseMeanRatioHessianResult {
  double cost;
  Vec3 gradient;
  Eigen::Matrix3d hessian;
};

namespace internal {

// One node tetrahedron T_k = (t_0, t_1, t_2, t_3) of an element: its edges from t_0, d1 × d2, the
// columns of S = D W⁻¹, det S and |S|_F², formed in the order MeanRatioOrInvalid forms them
// (element_quality.h), so every kernel built on it has the same bits.
struct NodeTetFrame {
  Vec3 d0, d1, d2, d1xd2;
  Vec3 s0, s1, s2;
  double det_s = 0.0;
  double frobenius2 = 0.0;
};

// False, with `f` only partly set, where the node tetrahedron is not positively oriented (or a
// coordinate is NaN): the element is invalid (Def. 2).
template <ElementType kType>
[[gnu::always_inline]] inline bool MakeNodeTetFrame(const ElementNodes<kType>& p,
                                                    const NodeTetIndices& t, NodeTetFrame& f) {
  constexpr auto& w = ElementTable<kType>::kTargetInverse;
  // The columns of S below and det S = det D · w00 w11 w22 rely on W⁻¹ being upper triangular.
  static_assert(w[1][0] == 0.0 && w[2][0] == 0.0 && w[2][1] == 0.0);
  f.d0 = p[t[1]] - p[t[0]];
  f.d1 = p[t[2]] - p[t[0]];
  f.d2 = p[t[3]] - p[t[0]];
  f.d1xd2 = f.d1.cross(f.d2);
  const double det_d = f.d0.dot(f.d1xd2);
  if (!(det_d > 0.0)) return false;
  f.s0 = f.d0 * w[0][0];
  f.s1 = f.d0 * w[0][1] + f.d1 * w[1][1];
  f.s2 = f.d0 * w[0][2] + f.d1 * w[1][2] + f.d2 * w[2][2];
  f.det_s = det_d * (w[0][0] * w[1][1] * w[2][2]);
  f.frobenius2 = f.s0.squaredNorm() + f.s1.squaredNorm() + f.s2.squaredNorm();
  return true;
}

// kOrder 0: cost only; 1: and the gradient (the Hessian: InverseMeanRatioHessianOf below). For an
// invalid element (Def. 2: some node tetrahedron has det ≤ 0, or a coordinate is NaN) the cost is
// +∞ — the barrier — and the gradient is left zero: it carries no information past the barrier,
// and a caller must test std::isfinite(cost) before using it. A node index outside
// 0..NodeCount(type)−1 belongs to no node tetrahedron and gets zero derivatives.
template <ElementType kType, int kOrder>
inline double InverseMeanRatioTerms(const ElementNodes<kType>& p, int node, Vec3* gradient) {
  using Table = ElementTable<kType>;
  constexpr auto& w = Table::kTargetInverse;
  constexpr double kDetWInverse = w[0][0] * w[1][1] * w[2][2];
  constexpr int kTets = static_cast<int>(Table::kNodeTets.size());
  constexpr double kInfinity = std::numeric_limits<double>::infinity();

  double sum = 0.0;
  Vec3 g = Vec3::Zero();
  for (const auto& t : Table::kNodeTets) {
    NodeTetFrame frame;
    if (!MakeNodeTetFrame<kType>(p, t, frame)) {
      if constexpr (kOrder >= 1) gradient->setZero();
      return kInfinity;
    }
    const auto& [d0, d1, d2, d1xd2, s0, s1, s2, det_s, frobenius2] = frame;
    const CubeRootRatio<double> root = CubeRootAsRatio(det_s * det_s);
    const double a = root.denominator / (3.0 * root.numerator);
    sum += frobenius2 * a;
    if constexpr (kOrder >= 1) {
      int m = -1;
      for (int j = 0; j < 4; ++j) {
        if (t[j] == node) m = j;
      }
      if (m < 0) continue;
      // b = row m of E W⁻¹, and ∂det D/∂p_{t_m}: det D = d0 · (d1 × d2) is linear in each edge,
      // and p_{t_0} enters all three edges with sign −1.
      Vec3 b;
      Vec3 ddet;
      if (m == 0) {
        b = -Vec3(w[0][0] + w[1][0] + w[2][0], w[0][1] + w[1][1] + w[2][1],
                  w[0][2] + w[1][2] + w[2][2]);
        ddet = -(d1xd2 + d2.cross(d0) + d0.cross(d1));
      } else {
        b = Vec3(w[m - 1][0], w[m - 1][1], w[m - 1][2]);
        ddet = m == 1 ? d1xd2 : (m == 2 ? d2.cross(d0) : d0.cross(d1));
      }
      const Vec3 grad_n = 2.0 * (s0 * b[0] + s1 * b[1] + s2 * b[2]);
      const Vec3 v = kDetWInverse * ddet;
      const double n_over_det = frobenius2 * (1.0 / det_s);  // as NodeTetDerivatives forms it
      g += a * (grad_n - (2.0 / 3.0) * n_over_det * v);
    }
  }
  constexpr double kInverseTets = 1.0 / kTets;
  if constexpr (kOrder >= 1) *gradient = g * kInverseTets;
  return sum * kInverseTets;
}

}  // namespace internal

// c(E): the mean over node tetrahedra of 1/q_k (see the top of this file), +∞ for an element that
// is not valid (Def. 2).
template <ElementType kType>
inline double InverseMeanRatioCost(const ElementNodes<kType>& p) {
  return internal::InverseMeanRatioTerms<kType, 0>(p, -1, nullptr);
}

// c(E) and the mean ratio q(E) of Def. 3 from one pass over the node tetrahedra: a polish trial
// needs both (the cost to accept a step, q to keep q_min), and they share every cube root.
// `quality` has the bits of MeanRatioOrInvalid (the same operations in the same order), so the
// polish's per-element qualities match a fresh evaluation exactly; it is kInvalidQuality (and
// `cost` +∞) for an element that is not valid.
struct InverseMeanRatioCostAndQuality {
  double cost;
  double quality;
};

// The same over lanes (lanes.h): kLaneCount<S> elements side by side, each lane with the bits
// the one-element function gives, so a polish trial can evaluate a node's elements several at a
// time (element_passes.h, CostAndQualityListPass).
template <typename S>
struct InverseMeanRatioCostAndQualityOf {
  S cost;
  S quality;
};

template <ElementType kType, typename S>
GETME_LANE_INLINE InverseMeanRatioCostAndQualityOf<S> CostAndQuality(const LaneNodes<kType, S>& p) {
  using Table = ElementTable<kType>;
  constexpr double kTets = static_cast<double>(Table::kNodeTets.size());
  S cost = Splat<S>(0.0);
  S quality = Splat<S>(0.0);
  auto valid = AllLanes<S>();
  for (const auto& t : Table::kNodeTets) {
    const NodeTetFrameOf<S> f = NodeTetFrameAt<kType, S>(p, t);
    valid = Both(valid, f.det_d > 0.0);
    // 1/q_k as AddNodeTetCost forms it and q_k as MeanRatioOrInvalid does: the polish compares a
    // trial's cost with the Hessian pass's, and stores the trial's qualities.
    const CubeRootRatio<S> root = CubeRootAsRatio(f.det_s * f.det_s);
    cost += f.frobenius2 * (root.denominator / (3.0 * root.numerator));
    quality += 3.0 * root.numerator / (root.denominator * f.frobenius2);
  }
  quality /= kTets;
  const S clamped =
      Select(quality < 0.0, Splat<S>(0.0), Select(1.0 < quality, Splat<S>(1.0), quality));
  return {Select(valid, cost * (1.0 / kTets), Splat<S>(std::numeric_limits<double>::infinity())),
          Select(valid, clamped, Splat<S>(kInvalidQuality))};
}

template <ElementType kType>
inline InverseMeanRatioCostAndQuality CostAndQuality(const ElementNodes<kType>& p) {
  const InverseMeanRatioCostAndQualityOf<double> r =
      CostAndQuality<kType, double>(ToLaneNodes<kType>(p));
  return {r.cost, r.quality};
}

// c(E) and ∂c/∂p_node. Past the barrier (cost +∞) the gradient is zero.
template <ElementType kType>
inline InverseMeanRatioGradientResult InverseMeanRatioGradient(const ElementNodes<kType>& p,
                                                               int node) {
  InverseMeanRatioGradientResult result;
  result.cost = internal::InverseMeanRatioTerms<kType, 1>(p, node, &result.gradient);
  return result;
}

// c(E), ∂c/∂p_node and ∂²c/∂p_node² (symmetric, positive semi-definite where c is finite). Past
// the barrier (cost +∞) gradient and Hessian are zero.
// c(E), ∂c/∂p_node and ∂²c/∂p_node² over lanes (lanes.h): kLaneCount<S> elements side by side,
// each with its own node (`node`: an int, or a lane vector of int64), so a polish step can take
// the derivatives of a node's elements several at a time (element_passes.h,
// HessianListPass). Written out coefficient by coefficient rather than with Eigen so that every
// lane has the bits the one-element instantiation (S = double) gives. The Hessian's upper
// triangle, row by row: (0,0) (0,1) (0,2) (1,1) (1,2) (2,2).
template <typename S>
struct InverseMeanRatioHessianOf {
  S cost;
  Point3<S> gradient;
  std::array<S, 6> hessian;
};

namespace internal {

// Row m of E W⁻¹ (see the top of this file) in every lane.
template <ElementType kType, typename S>
GETME_LANE_INLINE Point3<S> TargetRow(int m) {
  constexpr auto& w = ElementTable<kType>::kTargetInverse;
  if (m == 0) {
    return {Splat<S>(-(w[0][0] + w[1][0] + w[2][0])), Splat<S>(-(w[0][1] + w[1][1] + w[2][1])),
            Splat<S>(-(w[0][2] + w[1][2] + w[2][2]))};
  }
  return {Splat<S>(w[m - 1][0]), Splat<S>(w[m - 1][1]), Splat<S>(w[m - 1][2])};
}

// Lane by lane: if0 where at0, else if1 where at1, else if2 where at2, else if3. (Free functions
// rather than lambdas: everything that passes lanes must be forced inline, lanes.h.)
template <typename Mask, typename S>
GETME_LANE_INLINE Point3<S> ByPosition(Mask at0, Mask at1, Mask at2, const Point3<S>& if0,
                                       const Point3<S>& if1, const Point3<S>& if2,
                                       const Point3<S>& if3) {
  return {Select(at0, if0.x, Select(at1, if1.x, Select(at2, if2.x, if3.x))),
          Select(at0, if0.y, Select(at1, if1.y, Select(at2, if2.y, if3.y))),
          Select(at0, if0.z, Select(at1, if1.z, Select(at2, if2.z, if3.z)))};
}

}  // namespace internal

namespace internal {

// What the node tetrahedra of one element add up to, lane by lane: Σ 1/q_k, and the node's
// Σ ∇(1/q_k) and Σ ∇²(1/q_k) over the node tetrahedra that hold it.
template <typename S>
struct HessianSums {
  S sum;
  Point3<S> gradient;
  std::array<S, 6> hessian;
  decltype(AllLanes<S>()) valid;
};

template <typename S>
GETME_LANE_INLINE HessianSums<S> EmptyHessianSums() {
  const S zero = Splat<S>(0.0);
  HessianSums<S> sums{zero, {zero, zero, zero}, {}, AllLanes<S>()};
  sums.hessian.fill(zero);
  return sums;
}

// Node tetrahedron f's term of the cost: adds 1/q_k to the sum and its det's sign to the
// validity, and returns a = 1/(3 δ^{2/3}) for the derivatives.
template <typename S>
GETME_LANE_INLINE S AddNodeTetCost(const NodeTetFrameOf<S>& f, HessianSums<S>& sums) {
  sums.valid = Both(sums.valid, f.det_d > 0.0);
  const CubeRootRatio<S> root = CubeRootAsRatio(f.det_s * f.det_s);
  const S a = root.denominator / (3.0 * root.numerator);
  sums.sum += f.frobenius2 * a;
  return a;
}

// ∇(1/q_k) and ∇²(1/q_k) of node tetrahedron f with respect to its node at the position whose
// row of E W⁻¹ is b and whose ∂det D/∂p is ddet (see the top of this file).
template <typename S>
struct NodeTetDerivativesOf {
  Point3<S> gradient;
  std::array<S, 6> hessian;
};

template <ElementType kType, typename S>
GETME_LANE_INLINE NodeTetDerivativesOf<S> NodeTetDerivatives(const NodeTetFrameOf<S>& f, const S& a,
                                                             const Point3<S>& b,
                                                             const Point3<S>& ddet) {
  constexpr auto& w = ElementTable<kType>::kTargetInverse;
  constexpr double kDetWInverse = w[0][0] * w[1][1] * w[2][2];
  const Point3<S> grad_n = 2.0 * (f.s0 * b.x + f.s1 * b.y + f.s2 * b.z);
  const Point3<S> v = kDetWInverse * ddet;
  // One division by δ for the three factors below: divisions are what these kernels wait for.
  const S inverse_det = 1.0 / f.det_s;
  const S n_over_det = f.frobenius2 * inverse_det;
  NodeTetDerivativesOf<S> d;
  d.gradient = a * (grad_n - ((2.0 / 3.0) * n_over_det) * v);
  // ∇²(1/q) = a (2|b|² I − (2/(3δ)) (∇N vᵗ + v ∇Nᵗ) + (10/9)(N/δ²) v vᵗ).
  const S diagonal = 2.0 * SquaredNorm(b);
  const S cross_factor = (2.0 / 3.0) * inverse_det;
  const S outer_factor = (10.0 / 9.0) * (n_over_det * inverse_det);
  const std::array<S, 3> gn = {grad_n.x, grad_n.y, grad_n.z};
  const std::array<S, 3> vv = {v.x, v.y, v.z};
  int entry = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = i; j < 3; ++j, ++entry) {
      S term = outer_factor * (vv[i] * vv[j]) - cross_factor * (gn[i] * vv[j] + vv[i] * gn[j]);
      if (i == j) term = diagonal + term;
      d.hessian[entry] = a * term;
    }
  }
  return d;
}

// The mean over the K node tetrahedra; +∞ cost and zero derivatives past the barrier.
template <ElementType kType, typename S>
GETME_LANE_INLINE InverseMeanRatioHessianOf<S> FinishHessian(const HessianSums<S>& sums) {
  constexpr double kInverseTets = 1.0 / static_cast<double>(ElementTable<kType>::kNodeTets.size());
  const S zero = Splat<S>(0.0);
  const S infinity = Splat<S>(std::numeric_limits<double>::infinity());
  InverseMeanRatioHessianOf<S> result;
  result.cost = Select(sums.valid, sums.sum * kInverseTets, infinity);
  result.gradient = {Select(sums.valid, sums.gradient.x * kInverseTets, zero),
                     Select(sums.valid, sums.gradient.y * kInverseTets, zero),
                     Select(sums.valid, sums.gradient.z * kInverseTets, zero)};
  for (int k = 0; k < 6; ++k) {
    result.hessian[k] = Select(sums.valid, sums.hessian[k] * kInverseTets, zero);
  }
  return result;
}

// Node tetrahedron kTet's terms when the node is the element's node 0, in every lane: whether
// the tetrahedron holds it, and at which position, are constants, so the tetrahedra without it
// cost only their term of the cost. The same operations, in the same order, as the lanes of
// InverseMeanRatioHessianLanes whose node is 0, so the same bits.
template <ElementType kType, std::size_t kTet, typename S>
GETME_LANE_INLINE void AddNodeTetAtFirstNode(const LaneNodes<kType, S>& p, HessianSums<S>& sums) {
  constexpr NodeTetIndices t = ElementTable<kType>::kNodeTets[kTet];
  constexpr int m = t[0] == 0 ? 0 : t[1] == 0 ? 1 : t[2] == 0 ? 2 : t[3] == 0 ? 3 : -1;
  const NodeTetFrameOf<S> f = NodeTetFrameAt<kType, S>(p, t);
  const S a = AddNodeTetCost(f, sums);
  if constexpr (m >= 0) {
    Point3<S> ddet;
    if constexpr (m == 0) {
      ddet = -1.0 * (f.d1xd2 + Cross(f.d2, f.d0) + Cross(f.d0, f.d1));
    } else if constexpr (m == 1) {
      ddet = f.d1xd2;
    } else if constexpr (m == 2) {
      ddet = Cross(f.d2, f.d0);
    } else {
      ddet = Cross(f.d0, f.d1);
    }
    const NodeTetDerivativesOf<S> d =
        NodeTetDerivatives<kType, S>(f, a, TargetRow<kType, S>(m), ddet);
    sums.gradient = sums.gradient + d.gradient;
    for (int k = 0; k < 6; ++k) sums.hessian[k] = sums.hessian[k] + d.hessian[k];
  }
}

template <ElementType kType, typename S, std::size_t... kTet>
GETME_LANE_INLINE HessianSums<S> HessianSumsAtFirstNode(const LaneNodes<kType, S>& p,
                                                        std::index_sequence<kTet...>) {
  HessianSums<S> sums = EmptyHessianSums<S>();
  (AddNodeTetAtFirstNode<kType, kTet, S>(p, sums), ...);
  return sums;
}

}  // namespace internal

template <ElementType kType, typename S, typename Node>
GETME_LANE_INLINE InverseMeanRatioHessianOf<S> InverseMeanRatioHessianLanes(
    const LaneNodes<kType, S>& p, Node node) {
  using Table = ElementTable<kType>;
  internal::HessianSums<S> sums = internal::EmptyHessianSums<S>();
  for (const auto& t : Table::kNodeTets) {
    const NodeTetFrameOf<S> f = NodeTetFrameAt<kType, S>(p, t);
    const S a = internal::AddNodeTetCost(f, sums);
    // Which position m of T_k the node has, lane by lane; b = row m of E W⁻¹ and ∂det D/∂p_{t_m}
    // (see the top of this file). A lane whose node is not in T_k adds nothing.
    const auto at0 = node == t[0];
    const auto at1 = node == t[1];
    const auto at2 = node == t[2];
    const auto at3 = node == t[3];
    const auto in_tet = Either(Either(at0, at1), Either(at2, at3));
    if (NoLane(in_tet)) continue;
    const Point3<S> d2xd0 = Cross(f.d2, f.d0);
    const Point3<S> d0xd1 = Cross(f.d0, f.d1);
    const Point3<S> minus_all = -1.0 * (f.d1xd2 + d2xd0 + d0xd1);
    const Point3<S> b = internal::ByPosition(
        at0, at1, at2, internal::TargetRow<kType, S>(0), internal::TargetRow<kType, S>(1),
        internal::TargetRow<kType, S>(2), internal::TargetRow<kType, S>(3));
    const Point3<S> ddet = internal::ByPosition(at0, at1, at2, minus_all, f.d1xd2, d2xd0, d0xd1);
    const internal::NodeTetDerivativesOf<S> d =
        internal::NodeTetDerivatives<kType, S>(f, a, b, ddet);
    const Point3<S>& g = sums.gradient;
    sums.gradient = {Select(in_tet, g.x + d.gradient.x, g.x),
                     Select(in_tet, g.y + d.gradient.y, g.y),
                     Select(in_tet, g.z + d.gradient.z, g.z)};
    for (int k = 0; k < 6; ++k) {
      sums.hessian[k] = Select(in_tet, sums.hessian[k] + d.hessian[k], sums.hessian[k]);
    }
  }
  return internal::FinishHessian<kType>(sums);
}

// InverseMeanRatioHessianLanes with respect to node 0 in every lane, with the node tetrahedra
// unrolled: a polish step turns each element so that its node comes first
// (ElementTable::kSymmetryToFirst, element_passes.h). Bit for bit the same as
// InverseMeanRatioHessianLanes(p, 0); on a hexahedron half the node tetrahedra skip their
// derivatives, on a prism a third.
template <ElementType kType, typename S>
GETME_LANE_INLINE InverseMeanRatioHessianOf<S> InverseMeanRatioHessianAtFirstNode(
    const LaneNodes<kType, S>& p) {
  constexpr std::size_t kTets = ElementTable<kType>::kNodeTets.size();
  return internal::FinishHessian<kType>(
      internal::HessianSumsAtFirstNode<kType, S>(p, std::make_index_sequence<kTets>()));
}

// The one-element result in Eigen's types.
inline InverseMeanRatioHessianResult ToHessianResult(const InverseMeanRatioHessianOf<double>& r) {
  InverseMeanRatioHessianResult result;
  result.cost = r.cost;
  result.gradient = Vec3(r.gradient.x, r.gradient.y, r.gradient.z);
  const auto& h = r.hessian;
  result.hessian << h[0], h[1], h[2], h[1], h[3], h[4], h[2], h[4], h[5];
  return result;
}

template <ElementType kType>
inline InverseMeanRatioHessianResult InverseMeanRatioHessian(const ElementNodes<kType>& p,
                                                             int node) {
  const InverseMeanRatioHessianOf<double> r =
      InverseMeanRatioHessianLanes<kType, double>(ToLaneNodes<kType>(p), node);
  return ToHessianResult(r);
}

}  // namespace getme
