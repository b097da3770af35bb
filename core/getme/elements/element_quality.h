#pragma once

// Per-element quality kernels: validity (Def. 2), mean ratio (Def. 3, eq. 10), quad-face and
// element warpage and the combined criterion q_γ (Sec. 4.4). Templated on the element type.

#include <algorithm>
#include <cmath>

#include "getme/elements/cube_root.h"
#include "getme/elements/element_tables.h"
#include "getme/elements/lanes.h"
#include "getme/elements/vec3.h"

namespace getme {

// det D(T_k) of node tetrahedron k (eq. 9).
template <ElementType kType>
inline double NodeTetDeterminant(const ElementNodes<kType>& p, int k) {
  const auto& t = ElementTable<kType>::kNodeTets[k];
  const Vec3 a = p[t[1]] - p[t[0]];
  const Vec3 b = p[t[2]] - p[t[0]];
  const Vec3 c = p[t[3]] - p[t[0]];
  return a.dot(b.cross(c));
}

// Def. 2: every node tetrahedron has a positive determinant.
template <ElementType kType>
inline bool IsValid(const ElementNodes<kType>& p) {
  for (int k = 0; k < static_cast<int>(ElementTable<kType>::kNodeTets.size()); ++k) {
    if (!(NodeTetDeterminant<kType>(p, k) > 0.0)) return false;
  }
  return true;
}

// Returned by MeanRatioOrInvalid for an element that is not valid (Def. 2).
inline constexpr double kInvalidQuality = -1.0;

// Node tetrahedron T_k = (t_0, t_1, t_2, t_3) of an element (eq. 9), over lanes: its edges from
// t_0, d1 × d2, det D, the columns of S = D W⁻¹, det S and |S|_F². Every kernel on node
// tetrahedra (the mean ratio here; the polish's cost, gradient and Hessian,
// mean_ratio_derivatives.h) forms them here, in this order, so they all share these bits.
template <typename S>
struct NodeTetFrameOf {
  Point3<S> d0, d1, d2, d1xd2;
  S det_d;
  Point3<S> s0, s1, s2;
  S det_s;
  S frobenius2;
};

template <ElementType kType, typename S>
GETME_LANE_INLINE NodeTetFrameOf<S> NodeTetFrameAt(const LaneNodes<kType, S>& p,
                                                   const NodeTetIndices& t) {
  constexpr auto& w = ElementTable<kType>::kTargetInverse;
  // The columns of S below and det S = det D · w00 w11 w22 rely on W⁻¹ being upper triangular.
  static_assert(w[1][0] == 0.0 && w[2][0] == 0.0 && w[2][1] == 0.0);
  NodeTetFrameOf<S> f;
  f.d0 = p[t[1]] - p[t[0]];
  f.d1 = p[t[2]] - p[t[0]];
  f.d2 = p[t[3]] - p[t[0]];
  f.d1xd2 = Cross(f.d1, f.d2);
  f.det_d = Dot(f.d0, f.d1xd2);
  // S = D W⁻¹ with W⁻¹ upper triangular: column j of S is Σ_i D_i · W⁻¹(i, j).
  f.s0 = f.d0 * w[0][0];
  f.s1 = f.d0 * w[0][1] + f.d1 * w[1][1];
  f.s2 = f.d0 * w[0][2] + f.d1 * w[1][2] + f.d2 * w[2][2];
  f.det_s = f.det_d * (w[0][0] * w[1][1] * w[2][2]);
  f.frobenius2 = SquaredNorm(f.s0) + SquaredNorm(f.s1) + SquaredNorm(f.s2);
  return f;
}

// Mean ratio quality number (Def. 3, eq. 10) clamped to [0, 1], or kInvalidQuality when a node
// tetrahedron has det ≤ 0: one pass gives both validity and quality. The clamp matters because
// rounding can give a regular element 1 + 2e-16, which would make the simultaneous weight
// (1 − q)^η NaN (docs/paper-notes.md#rounding-of-the-mean-ratio). Generic over the lane type S
// (lanes.h).
template <ElementType kType, typename S>
GETME_LANE_INLINE S MeanRatioOrInvalid(const LaneNodes<kType, S>& p) {
  using Table = ElementTable<kType>;
  S sum = Splat<S>(0.0);
  auto valid = AllLanes<S>();
  for (const auto& t : Table::kNodeTets) {
    const NodeTetFrameOf<S> f = NodeTetFrameAt<kType, S>(p, t);
    valid = Both(valid, f.det_d > 0.0);
    // q_k = 3 ∛(det S²) / |S|_F², with one division (CubeRootAsRatio).
    const CubeRootRatio<S> root = CubeRootAsRatio(f.det_s * f.det_s);
    sum += 3.0 * root.numerator / (root.denominator * f.frobenius2);
  }
  const S q = sum / static_cast<double>(Table::kNodeTets.size());
  // std::clamp(q, 0, 1), lane by lane.
  const S clamped = Select(q < 0.0, Splat<S>(0.0), Select(1.0 < q, Splat<S>(1.0), q));
  return Select(valid, clamped, Splat<S>(kInvalidQuality));
}

template <ElementType kType>
inline double MeanRatioOrInvalid(const ElementNodes<kType>& p) {
  return MeanRatioOrInvalid<kType, double>(ToLaneNodes<kType>(p));
}

// Mean ratio (Def. 3), with an invalid element counted as q = 0
// (docs/paper-notes.md#invalid-elements).
template <ElementType kType>
inline double MeanRatio(const ElementNodes<kType>& p) {
  return std::max(0.0, MeanRatioOrInvalid<kType>(p));
}

// Warpage of the quad face (a, b, c, d) (Sec. 4.4): 1 − min((n̂0·n̂2)³, (n̂1·n̂3)³) ∈ [0, 2], with
// n_k = (p_k − p_{k−1}) × (p_{k+1} − p_k). A degenerate corner (zero normal) counts as fully
// warped.
inline double QuadWarpage(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 q[4] = {a, b, c, d};
  Vec3 n[4];
  for (int k = 0; k < 4; ++k) {
    const Vec3& prev = q[(k + 3) % 4];
    const Vec3& next = q[(k + 1) % 4];
    n[k] = (q[k] - prev).cross(next - q[k]);
    const double length = n[k].norm();
    if (!(length > 0.0)) return 2.0;
    n[k] /= length;
  }
  const double c02 = n[0].dot(n[2]);
  const double c13 = n[1].dot(n[3]);
  return 1.0 - std::min(c02 * c02 * c02, c13 * c13 * c13);
}

// Element warpage: the maximum over its quad faces; 0 for a tetrahedron.
template <ElementType kType>
inline double Warpage(const ElementNodes<kType>& p) {
  double warpage = 0.0;
  for (const auto& face : ElementTable<kType>::kFaces) {
    if (face.size != 4) continue;
    const auto& f = face.nodes;
    warpage = std::max(warpage, QuadWarpage(p[f[0]], p[f[1]], p[f[2]], p[f[3]]));
  }
  return warpage;
}

// QuadWarpage over lanes (lanes.h), for the whole-mesh warpage pass (element_passes.h,
// WarpagePass): the same operations in the same order, with Point3's Eigen-ordered sums, so every
// lane has QuadWarpage's bits for its face (element_passes_test.cc). A lane with a degenerate
// corner computes on with a zero division and is replaced by 2 at the end.
template <typename S>
GETME_LANE_INLINE S QuadWarpageOf(const std::array<Point3<S>, 4>& q) {
  auto valid = AllLanes<S>();
  std::array<Point3<S>, 4> n;
  for (int k = 0; k < 4; ++k) {
    const Point3<S>& prev = q[(k + 3) % 4];
    const Point3<S>& next = q[(k + 1) % 4];
    n[k] = Cross(q[k] - prev, next - q[k]);
    const S length = Norm(n[k]);
    valid = Both(valid, length > 0.0);
    n[k] = n[k] / length;
  }
  const S c02 = Dot(n[0], n[2]);
  const S c13 = Dot(n[1], n[3]);
  const S cube02 = c02 * c02 * c02;
  const S cube13 = c13 * c13 * c13;
  // 1 − std::min(cube02, cube13), lane by lane.
  const S warpage = 1.0 - Select(cube13 < cube02, cube13, cube02);
  return Select(valid, warpage, Splat<S>(2.0));
}

// Warpage over lanes: the maximum over the quad faces as Warpage takes it; 0 for a tetrahedron.
template <ElementType kType, typename S>
GETME_LANE_INLINE S WarpageOf(const LaneNodes<kType, S>& p) {
  S warpage = Splat<S>(0.0);
  for (const auto& face : ElementTable<kType>::kFaces) {
    if (face.size != 4) continue;
    const auto& f = face.nodes;
    const S face_warpage = QuadWarpageOf<S>({p[f[0]], p[f[1]], p[f[2]], p[f[3]]});
    warpage = Select(warpage < face_warpage, face_warpage, warpage);  // std::max, lane by lane
  }
  return warpage;
}

// Combined criterion of Sec. 4.4: q_γ(E) = min(q(E), γ·(1 − w(E)/2)), from an element's mean
// ratio and warpage (the sequential substep has the mean ratio already when it needs q_γ).
inline double QualityGammaFrom(double quality, double warpage, double gamma) {
  return std::min(quality, gamma * (1.0 - warpage / 2.0));
}

template <ElementType kType>
inline double QualityGamma(const ElementNodes<kType>& p, double gamma) {
  return QualityGammaFrom(MeanRatio<kType>(p), Warpage<kType>(p), gamma);
}

}  // namespace getme
