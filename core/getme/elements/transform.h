#pragma once

// The regularizing element transformation (Def. 1, eqs. 1–5), the centroid-preserving
// mean-edge-length scaling (eq. 8) and relaxation (eq. 11), templated on the element type and on
// the lane type S (lanes.h: one element, or kLanes elements at once with identical bits).

#include <cmath>

#include "getme/elements/element_tables.h"
#include "getme/elements/lanes.h"
#include "getme/elements/vec3.h"

namespace getme {

// Means are sums times the reciprocal of their count, not sums divided by it: a division by 3, 5,
// 6, 9 or 12 is one to two orders of magnitude slower than a multiplication in a vector unit (the
// tetrahedron's 24 divisions by 3 were the largest single cost of the simultaneous substep's
// transform pass, issue 16), and the product is within one ulp of the quotient. Counts that are
// powers of two give the same bits either way.
constexpr double kOneThird = 1.0 / 3.0;

// τ of the base points a_k(τ) (eq. 5) for the triangular dual faces of pyramids and prisms.
constexpr double kPrismTauScale = 0.8;                 // 4/5
constexpr double kPrismTauSigma = 0.5659119256652702;  // √2 / 39^(1/4)

// Def. 1: p'_k = b_k + σ n_k / sqrt(|n_k|) on the dual element (eq. 1) of E.
template <ElementType kType, typename S>
GETME_LANE_INLINE LaneNodes<kType, S> TransformElement(const LaneNodes<kType, S>& p, S sigma) {
  using Table = ElementTable<kType>;
  constexpr int kDualNodes = static_cast<int>(Table::kFaces.size());
  // eq. (1): dual nodes are the face centroids.
  std::array<Point3<S>, kDualNodes> d;
  for (int k = 0; k < kDualNodes; ++k) {
    const auto& face = Table::kFaces[k];
    Point3<S> sum = p[face.nodes[0]] + p[face.nodes[1]] + p[face.nodes[2]];
    if (face.size == 4) sum += p[face.nodes[3]];
    d[k] = sum * (face.size == 4 ? 0.25 : kOneThird);
  }
  LaneNodes<kType, S> out;
  for (int k = 0; k < Table::kNodes; ++k) {
    const auto& dual = Table::kDualFaces[k];
    const Point3<S>& e0 = d[dual.nodes[0]];
    const Point3<S>& e1 = d[dual.nodes[1]];
    const Point3<S>& e2 = d[dual.nodes[2]];
    Point3<S> normal;  // eq. (2)
    Point3<S> base;    // eq. (5)
    if (dual.size == 4) {
      const Point3<S>& e3 = d[dual.nodes[3]];
      normal = 0.5 * Cross(e2 - e0, e3 - e1);
      base = 0.25 * (e0 + e1 + e2 + e3);
    } else {
      normal = Cross(e1 - e0, e2 - e0);
      if constexpr (kType == ElementType::kPyramid) {
        const S tau = 0.5 + sigma;
        base = (1.0 - tau) * e0 + 0.5 * tau * (e1 + e2);
      } else if constexpr (kType == ElementType::kPrism) {
        const S tau = kPrismTauScale * (1.0 - kPrismTauSigma * sigma);
        base = (1.0 - tau) * e0 + 0.5 * tau * (e1 + e2);
      } else {
        base = (e0 + e1 + e2) * kOneThird;  // eq. (3)
      }
    }
    const S length = Norm(normal);
    const auto positive = length > 0.0;
    const Point3<S> moved = base + (sigma / Sqrt(length)) * normal;
    out[k] = {Select(positive, moved.x, base.x), Select(positive, moved.y, base.y),
              Select(positive, moved.z, base.z)};
  }
  return out;
}

template <ElementType kType, typename S>
GETME_LANE_INLINE S MeanEdgeLength(const LaneNodes<kType, S>& p) {
  S sum = Splat<S>(0.0);
  for (const auto& edge : ElementTable<kType>::kEdges) sum += Norm(p[edge[1]] - p[edge[0]]);
  return sum * (1.0 / static_cast<double>(ElementTable<kType>::kEdges.size()));
}

template <ElementType kType, typename S>
GETME_LANE_INLINE Point3<S> Centroid(const LaneNodes<kType, S>& p) {
  Point3<S> sum{Splat<S>(0.0), Splat<S>(0.0), Splat<S>(0.0)};
  for (const Point3<S>& node : p) sum += node;
  return sum * (1.0 / static_cast<double>(p.size()));
}

// eq. (8) with mean-edge-length-preserving ζ, then eq. (11): E'_r = (1−ρ)E + ρ(q + ζ(E' − q')).
template <ElementType kType, typename S>
GETME_LANE_INLINE LaneNodes<kType, S> ScaleAndRelax(const LaneNodes<kType, S>& original,
                                                    const LaneNodes<kType, S>& transformed,
                                                    double rho) {
  const Point3<S> q = Centroid<kType, S>(original);
  const Point3<S> q_prime = Centroid<kType, S>(transformed);
  const S transformed_length = MeanEdgeLength<kType, S>(transformed);
  const S zeta = Select(transformed_length > 0.0,
                        MeanEdgeLength<kType, S>(original) / transformed_length, Splat<S>(0.0));
  LaneNodes<kType, S> out;
  for (std::size_t k = 0; k < original.size(); ++k) {
    const Point3<S> scaled = q + zeta * (transformed[k] - q_prime);
    out[k] = (1.0 - rho) * original[k] + rho * scaled;
  }
  return out;
}

// One full step as the smoothers use it: transform (Def. 1), scale (eq. 8), relax (eq. 11).
template <ElementType kType, typename S>
GETME_LANE_INLINE LaneNodes<kType, S> RegularizingStep(const LaneNodes<kType, S>& p, S sigma,
                                                       double rho) {
  return ScaleAndRelax<kType, S>(p, TransformElement<kType, S>(p, sigma), rho);
}

// --- The same on one element's nodes as Eigen vectors (ElementNodes) ---

template <ElementType kType>
inline ElementNodes<kType> TransformElement(const ElementNodes<kType>& p, double sigma) {
  return ToElementNodes<kType>(TransformElement<kType, double>(ToLaneNodes<kType>(p), sigma));
}

template <ElementType kType>
inline double MeanEdgeLength(const ElementNodes<kType>& p) {
  return MeanEdgeLength<kType, double>(ToLaneNodes<kType>(p));
}

template <ElementType kType>
inline Vec3 Centroid(const ElementNodes<kType>& p) {
  const Point3<double> centroid = Centroid<kType, double>(ToLaneNodes<kType>(p));
  return Vec3(centroid.x, centroid.y, centroid.z);
}

template <ElementType kType>
inline ElementNodes<kType> ScaleAndRelax(const ElementNodes<kType>& original,
                                         const ElementNodes<kType>& transformed, double rho) {
  return ToElementNodes<kType>(ScaleAndRelax<kType, double>(ToLaneNodes<kType>(original),
                                                            ToLaneNodes<kType>(transformed), rho));
}

template <ElementType kType>
inline ElementNodes<kType> RegularizingStep(const ElementNodes<kType>& p, double sigma,
                                            double rho) {
  return ToElementNodes<kType>(RegularizingStep<kType, double>(ToLaneNodes<kType>(p), sigma, rho));
}

}  // namespace getme
