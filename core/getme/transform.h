#pragma once

// The regularizing element transformation (Def. 1, eqs. 1–5), the centroid-preserving
// mean-edge-length scaling (eq. 8) and relaxation (eq. 11), templated on the element type.

#include <cmath>

#include "getme/element_tables.h"
#include "getme/vec3.h"

namespace getme {

// τ of the base points a_k(τ) (eq. 5) for the triangular dual faces of pyramids and prisms.
constexpr double kPrismTauScale = 0.8;                 // 4/5
constexpr double kPrismTauSigma = 0.5659119256652702;  // √2 / 39^(1/4)

// Def. 1: p'_k = b_k + σ n_k / sqrt(|n_k|) on the dual element (eq. 1) of E.
template <ElementType kType>
inline ElementNodes<kType> TransformElement(const ElementNodes<kType>& p, double sigma) {
  using Table = ElementTable<kType>;
  constexpr int kDualNodes = static_cast<int>(Table::kFaces.size());
  // eq. (1): dual nodes are the face centroids.
  std::array<Vec3, kDualNodes> d;
  for (int k = 0; k < kDualNodes; ++k) {
    const auto& face = Table::kFaces[k];
    Vec3 sum = p[face.nodes[0]] + p[face.nodes[1]] + p[face.nodes[2]];
    if (face.size == 4) sum += p[face.nodes[3]];
    d[k] = sum / face.size;
  }
  ElementNodes<kType> out;
  for (int k = 0; k < Table::kNodes; ++k) {
    const auto& dual = Table::kDualFaces[k];
    const Vec3& e0 = d[dual.nodes[0]];
    const Vec3& e1 = d[dual.nodes[1]];
    const Vec3& e2 = d[dual.nodes[2]];
    Vec3 normal;  // eq. (2)
    Vec3 base;    // eq. (5)
    if (dual.size == 4) {
      const Vec3& e3 = d[dual.nodes[3]];
      normal = 0.5 * (e2 - e0).cross(e3 - e1);
      base = 0.25 * (e0 + e1 + e2 + e3);
    } else {
      normal = (e1 - e0).cross(e2 - e0);
      if constexpr (kType == ElementType::kPyramid) {
        const double tau = 0.5 + sigma;
        base = (1.0 - tau) * e0 + 0.5 * tau * (e1 + e2);
      } else if constexpr (kType == ElementType::kPrism) {
        const double tau = kPrismTauScale * (1.0 - kPrismTauSigma * sigma);
        base = (1.0 - tau) * e0 + 0.5 * tau * (e1 + e2);
      } else {
        base = (e0 + e1 + e2) / 3.0;  // eq. (3)
      }
    }
    const double length = normal.norm();
    out[k] = length > 0.0 ? Vec3(base + (sigma / std::sqrt(length)) * normal) : base;
  }
  return out;
}

template <ElementType kType>
inline double MeanEdgeLength(const ElementNodes<kType>& p) {
  double sum = 0.0;
  for (const auto& edge : ElementTable<kType>::kEdges) sum += (p[edge[1]] - p[edge[0]]).norm();
  return sum / static_cast<double>(ElementTable<kType>::kEdges.size());
}

template <ElementType kType>
inline Vec3 Centroid(const ElementNodes<kType>& p) {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& node : p) sum += node;
  return sum / static_cast<double>(p.size());
}

// eq. (8) with mean-edge-length-preserving ζ, then eq. (11): E'_r = (1−ρ)E + ρ(q + ζ(E' − q')).
template <ElementType kType>
inline ElementNodes<kType> ScaleAndRelax(const ElementNodes<kType>& original,
                                         const ElementNodes<kType>& transformed, double rho) {
  const Vec3 q = Centroid<kType>(original);
  const Vec3 q_prime = Centroid<kType>(transformed);
  const double transformed_length = MeanEdgeLength<kType>(transformed);
  const double zeta =
      transformed_length > 0.0 ? MeanEdgeLength<kType>(original) / transformed_length : 0.0;
  ElementNodes<kType> out;
  for (std::size_t k = 0; k < original.size(); ++k) {
    const Vec3 scaled = q + zeta * (transformed[k] - q_prime);
    out[k] = (1.0 - rho) * original[k] + rho * scaled;
  }
  return out;
}

// One full step as the smoothers use it: transform (Def. 1), scale (eq. 8), relax (eq. 11).
template <ElementType kType>
inline ElementNodes<kType> RegularizingStep(const ElementNodes<kType>& p, double sigma,
                                            double rho) {
  return ScaleAndRelax<kType>(p, TransformElement<kType>(p, sigma), rho);
}

}  // namespace getme
