#include "reference_quality.h"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

#include "reference_topology.h"

namespace getme::mesh_test {
namespace {

struct Reference {
  std::vector<std::array<int, 4>> node_tets;  // N (paper Sec. 2.2, before eq. (9)), 0-based
  Eigen::Matrix3d target;                     // W, by columns
};

Eigen::Matrix3d Columns(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                        const Eigen::Vector3d& c) {
  Eigen::Matrix3d m;
  m.col(0) = a;
  m.col(1) = b;
  m.col(2) = c;
  return m;
}

const Reference& ReferenceFor(ElementType type) {
  static const Reference kTet = {{{0, 1, 2, 3}},
                                 Columns({1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0},
                                         {0.5, std::sqrt(3.0) / 6, std::sqrt(2.0 / 3)})};
  static const Reference kHex = {{{0, 3, 4, 1},
                                  {1, 0, 5, 2},
                                  {2, 1, 6, 3},
                                  {3, 2, 7, 0},
                                  {4, 7, 5, 0},
                                  {5, 4, 6, 1},
                                  {6, 5, 7, 2},
                                  {7, 6, 4, 3}},
                                 Eigen::Matrix3d::Identity()};
  static const Reference kPyramid = {{{0, 1, 3, 4}, {1, 2, 0, 4}, {2, 3, 1, 4}, {3, 0, 2, 4}},
                                     Columns({1, 0, 0}, {0, 1, 0}, {0.5, 0.5, std::sqrt(2.0) / 2})};
  static const Reference kPrism = {
      {{0, 1, 2, 3}, {1, 2, 0, 4}, {2, 0, 1, 5}, {3, 5, 4, 0}, {4, 3, 5, 1}, {5, 4, 3, 2}},
      Columns({1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0}, {0, 0, 1})};
  switch (type) {
    case ElementType::kTetrahedron:
      return kTet;
    case ElementType::kHexahedron:
      return kHex;
    case ElementType::kPyramid:
      return kPyramid;
    case ElementType::kPrism:
      break;
  }
  return kPrism;
}

Eigen::Matrix3d NodeTetEdges(const std::array<int, 4>& t, const Points& p) {
  return Columns(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]], p[t[3]] - p[t[0]]);
}

double QuadWarpage(const Points& q) {
  std::array<Eigen::Vector3d, 4> n;
  for (int k = 0; k < 4; ++k) {
    n[k] = (q[k] - q[(k + 3) % 4]).cross(q[(k + 1) % 4] - q[k]).normalized();
  }
  return 1.0 - std::min(std::pow(n[0].dot(n[2]), 3), std::pow(n[1].dot(n[3]), 3));
}

}  // namespace

bool ReferenceIsValid(ElementType type, const Points& p) {
  for (const auto& t : ReferenceFor(type).node_tets) {
    if (!(NodeTetEdges(t, p).determinant() > 0.0)) return false;
  }
  return true;
}

double ReferenceMeanRatio(ElementType type, const Points& p) {
  if (!ReferenceIsValid(type, p)) return 0.0;
  const Reference& reference = ReferenceFor(type);
  const Eigen::Matrix3d target_inverse = reference.target.inverse();
  double sum = 0.0;
  for (const auto& t : reference.node_tets) {
    const Eigen::Matrix3d s = NodeTetEdges(t, p) * target_inverse;
    sum += 3.0 * std::pow(s.determinant(), 2.0 / 3.0) / s.squaredNorm();
  }
  return sum / static_cast<double>(reference.node_tets.size());
}

double ReferenceWarpage(ElementType type, const Points& p) {
  double warpage = 0.0;
  for (const std::vector<int>& face : ReferenceFaces(type)) {
    if (face.size() != 4) continue;
    warpage = std::max(warpage, QuadWarpage({p[face[0]], p[face[1]], p[face[2]], p[face[3]]}));
  }
  return warpage;
}

}  // namespace getme::mesh_test
