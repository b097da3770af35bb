#include "getme/smoothing/boundary_slide.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

namespace getme {

int BoundarySlide::TangentSpace(const Mesh& mesh, NodeId node, std::array<Vec3, 2>& basis) const {
  const Vec3 at(mesh.x()[node], mesh.y()[node], mesh.z()[node]);
  double nearest2 = std::numeric_limits<double>::infinity();
  for (ElementId e : mesh.node_elements(node)) {
    for (NodeId other : mesh.element_nodes(e)) {
      if (other == node) continue;
      nearest2 = std::min(
          nearest2, (Vec3(mesh.x()[other], mesh.y()[other], mesh.z()[other]) - at).squaredNorm());
    }
  }
  const double epsilon = 1e-4 * std::sqrt(nearest2);
  Eigen::Matrix3d moves;
  for (int k = 0; k < 3; ++k) {
    Vec3 trial = at;
    trial[k] += epsilon;
    moves.col(k) = (Project(node, trial, &at) - at) / epsilon;
  }
  // The moves are the axes through the projection's Jacobian: its range is the tangent space,
  // the eigenvectors of M Mᵀ whose eigenvalues are near 1 (near 0 across the surface).
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> spans(moves * moves.transpose());
  int count = 0;
  for (int k = 2; k >= 0 && count < 2; --k) {
    if (spans.eigenvalues()[k] > 0.25) basis[count++] = spans.eigenvectors().col(k);
  }
  return count;
}

}  // namespace getme
