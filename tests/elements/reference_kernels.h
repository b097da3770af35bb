#pragma once

// Straightforward re-computations of the paper's formulas from the tables in paper_tables.h, used
// as the independent side of the element-level tests. They favour plain Eigen and loops over speed
// and share no code with core/getme/elements/element_quality.h or transform.h.

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "getme/elements/vec3.h"
#include "paper_tables.h"

namespace getme::test {

using Points = std::vector<Eigen::Vector3d>;

template <ElementType kType>
Points ToPoints(const ElementNodes<kType>& nodes) {
  return Points(nodes.begin(), nodes.end());
}

template <ElementType kType>
ElementNodes<kType> ToNodes(const Points& points) {
  ElementNodes<kType> nodes;
  for (std::size_t k = 0; k < nodes.size(); ++k) nodes[k] = points[k];
  return nodes;
}

inline Eigen::Vector3d Mean(const Points& points) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points) sum += p;
  return sum / static_cast<double>(points.size());
}

// D(T_k) of Def. 2: the spanning edge vectors of node tetrahedron k as columns.
inline Eigen::Matrix3d NodeTetEdges(ElementType type, const Points& p, int k) {
  const IndexTuple& t = Paper(type).node_tets[k];
  Eigen::Matrix3d d;
  d << p[t[1]] - p[t[0]], p[t[2]] - p[t[0]], p[t[3]] - p[t[0]];
  return d;
}

// Def. 3 without clamping, using Eigen's inverse and determinant of W; NaN for an invalid element
// so that a caller cannot mistake the reference for a quality number of an invalid element.
inline double ReferenceMeanRatio(ElementType type, const Points& p) {
  const PaperTables& paper = Paper(type);
  const Eigen::Matrix3d w_inverse = paper.target.inverse();
  double sum = 0.0;
  for (int k = 0; k < static_cast<int>(paper.node_tets.size()); ++k) {
    const Eigen::Matrix3d d = NodeTetEdges(type, p, k);
    if (!(d.determinant() > 0.0)) return std::nan("");
    const Eigen::Matrix3d s = d * w_inverse;
    sum += 3.0 * std::pow(s.determinant(), 2.0 / 3.0) / s.squaredNorm();
  }
  return sum / static_cast<double>(paper.node_tets.size());
}

// eq. (1): the dual element's nodes are the face centroids.
inline Points DualNodes(ElementType type, const Points& p) {
  Points d;
  for (const IndexTuple& face : Paper(type).faces) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int node : face) sum += p[node];
    d.push_back(sum / static_cast<double>(face.size()));
  }
  return d;
}

// τ of eq. (5) for the triangular dual faces of pyramids (k = 0..3) and prisms.
inline double PyramidTau(double sigma) { return 0.5 + sigma; }
inline double PrismTau(double sigma) {
  return 0.8 * (1.0 - std::sqrt(2.0) * sigma / std::pow(39.0, 0.25));
}

// eq. (5): b_k is the dual face centroid c_k (eq. 3) for tetrahedra, hexahedra and the pyramid's
// quadrilateral dual face, and a_k(τ) on the line from the face's first node to the midpoint of
// the opposite side otherwise.
inline Points ReferenceBasePoints(ElementType type, const Points& p, double sigma) {
  const Points d = DualNodes(type, p);
  Points b;
  for (const IndexTuple& face : Paper(type).dual_faces) {
    const bool triangle_with_tau =
        face.size() == 3 && (type == ElementType::kPyramid || type == ElementType::kPrism);
    if (triangle_with_tau) {
      const double tau = type == ElementType::kPyramid ? PyramidTau(sigma) : PrismTau(sigma);
      b.push_back((1.0 - tau) * d[face[0]] + tau * 0.5 * (d[face[1]] + d[face[2]]));
    } else {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (int node : face) sum += d[node];
      b.push_back(sum / static_cast<double>(face.size()));
    }
  }
  return b;
}

// eq. (2): outward normals of the dual faces.
inline Points ReferenceDualNormals(ElementType type, const Points& p) {
  const Points d = DualNodes(type, p);
  Points n;
  for (const IndexTuple& face : Paper(type).dual_faces) {
    if (face.size() == 3) {
      n.push_back((d[face[1]] - d[face[0]]).cross(d[face[2]] - d[face[0]]));
    } else {
      n.push_back(0.5 * (d[face[2]] - d[face[0]]).cross(d[face[3]] - d[face[1]]));
    }
  }
  return n;
}

// Def. 1, eq. (4): p'_k = b_k + σ n_k / sqrt(|n_k|).
inline Points ReferenceTransform(ElementType type, const Points& p, double sigma) {
  const Points b = ReferenceBasePoints(type, p, sigma);
  const Points n = ReferenceDualNormals(type, p);
  Points out;
  for (std::size_t k = 0; k < b.size(); ++k)
    out.push_back(b[k] + sigma * n[k] / std::sqrt(n[k].norm()));
  return out;
}

inline std::vector<double> EdgeLengths(ElementType type, const Points& p) {
  std::vector<double> lengths;
  for (const auto& [a, b] : PaperEdges(type)) lengths.push_back((p[b] - p[a]).norm());
  return lengths;
}

inline double ReferenceMeanEdgeLength(ElementType type, const Points& p) {
  double sum = 0.0;
  for (double length : EdgeLengths(type, p)) sum += length;
  return sum / static_cast<double>(PaperEdges(type).size());
}

// eq. (8) with mean-edge-length-preserving ζ followed by eq. (11).
inline Points ReferenceScaleAndRelax(ElementType type, const Points& original,
                                     const Points& transformed, double rho) {
  const Eigen::Vector3d q = Mean(original);
  const Eigen::Vector3d q_prime = Mean(transformed);
  const double zeta =
      ReferenceMeanEdgeLength(type, original) / ReferenceMeanEdgeLength(type, transformed);
  Points out;
  for (std::size_t k = 0; k < original.size(); ++k) {
    out.push_back((1.0 - rho) * original[k] + rho * (q + zeta * (transformed[k] - q_prime)));
  }
  return out;
}

// All pairwise node distances; two elements with proportional distance matrices are similar.
inline Eigen::MatrixXd DistanceMatrix(const Points& p) {
  const int n = static_cast<int>(p.size());
  Eigen::MatrixXd distances(n, n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) distances(i, j) = (p[i] - p[j]).norm();
  }
  return distances;
}

inline double MaxDistance(const Points& a, const Points& b) {
  double max = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) max = std::max(max, (a[k] - b[k]).norm());
  return max;
}

}  // namespace getme::test
