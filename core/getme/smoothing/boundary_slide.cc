#include "getme/smoothing/boundary_slide.h"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "getme/mesh/node_neighbours.h"

namespace getme {

int BoundarySlide::TangentSpace(const Mesh& mesh, NodeId node, std::array<Vec3, 2>& basis) const {
  const Vec3 at(mesh.x()[node], mesh.y()[node], mesh.z()[node]);
  const double epsilon = 1e-4 * std::sqrt(NearestNodeDistance2(mesh, node));
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
