#pragma once

// Regular elements with unit edge length, built from their geometric description in the paper's
// node order (Fig. 1, docs/node-orders.md; not from the W columns: the tests compare against W
// afterwards), plus mirror images and similarity maps.

#include <Eigen/Geometry>
#include <cmath>

#include "reference_kernels.h"

namespace getme::test {

// An equilateral unit triangle counter-clockwise seen from +z, then the element's remaining nodes.
inline Points RegularElementPoints(ElementType type) {
  const Eigen::Vector3d a(0, 0, 0);
  const Eigen::Vector3d b(1, 0, 0);
  const Eigen::Vector3d c(0.5, std::sqrt(0.75), 0);
  switch (type) {
    case ElementType::kTetrahedron: {
      // Apex above the triangle's centroid at the height that makes its edges unit long: the
      // centroid lies 1/√3 from each corner.
      const Eigen::Vector3d centroid = (a + b + c) / 3.0;
      const double height = std::sqrt(1.0 - (centroid - a).squaredNorm());
      return {a, b, c, centroid + Eigen::Vector3d(0, 0, height)};
    }
    case ElementType::kHexahedron:
      return {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
              {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    case ElementType::kPyramid: {
      // Unit square base, apex above its centre; the centre lies √2/2 from each corner.
      const Eigen::Vector3d centre(0.5, 0.5, 0);
      const double height = std::sqrt(1.0 - (centre - a).squaredNorm());
      return {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, centre + Eigen::Vector3d(0, 0, height)};
    }
    case ElementType::kPrism:
      break;
  }
  const Eigen::Vector3d up(0, 0, 1);
  return {a, b, c, a + up, b + up, c + up};
}

template <ElementType kType>
ElementNodes<kType> RegularElement() {
  return ToNodes<kType>(RegularElementPoints(kType));
}

// The mirror image through the plane z = 0: same shape, opposite orientation.
inline Points Mirrored(Points p) {
  for (Eigen::Vector3d& node : p) node.z() = -node.z();
  return p;
}

// x ↦ ζ R x + t (Lemma 1).
struct Similarity {
  double scale = 1.0;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();

  Eigen::Vector3d operator()(const Eigen::Vector3d& x) const {
    return scale * rotation * x + translation;
  }
  Points operator()(const Points& points) const {
    Points out;
    for (const Eigen::Vector3d& x : points) out.push_back((*this)(x));
    return out;
  }
};

}  // namespace getme::test
