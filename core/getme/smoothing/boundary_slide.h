#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "getme/elements/vec3.h"
#include "getme/mesh/mesh.h"
#include "getme/smoothing/kept_layers.h"

namespace getme {

// Boundary nodes that slide on the input's own surface instead of staying fixed (issue 15,
// docs/boundary.md). The caller builds it from the input mesh (surface/: the boundary's groups,
// feature curves and corners, and nearest points through CGAL) and passes it to Smooth(); the
// engine itself knows no geometry library. Smooth() asks Slides() once per boundary node that the
// caller did not fix; every phase then passes each new position of a sliding node through
// Project() before it judges the step, so a sliding node is always on its surface (or curve)
// when an element's quality is computed. With keep_layers it also describes the boundary-layer
// columns (kept_layers.h). Implementations must be safe to call from several threads at once.
class BoundarySlide {
 public:
  virtual ~BoundarySlide() = default;
  // Whether boundary node `node` slides; false keeps it fixed (a corner, say).
  virtual bool Slides(NodeId node) const = 0;
  // Where sliding node `node` belongs when a smoother has put it at `point`. `near`, if given, is
  // a point where the node already belongs (its position before the move): a nearest-point
  // search that starts from it prunes most of the surface at once.
  virtual Vec3 Project(NodeId node, const Vec3& point, const Vec3* near = nullptr) const = 0;
  // How far sliding node `node`, put at `point`, is from where it belongs on the input's
  // boundary: its own surface group's faces, or its feature curve. The result check's measure for
  // sliding nodes, and the summary's largest distance.
  virtual double DistanceToSurface(NodeId node, const Vec3& point) const = 0;
  // An orthonormal basis of the directions sliding node `node` may move in where `mesh` has it
  // (a point where it belongs): two on a surface, one along a feature curve, none where it
  // cannot move. Returns how many. This default reads them off Project(): small moves along the
  // three axes (a ten-thousandth of the node's nearest-neighbour distance), put back onto the
  // surface, span the tangent space (three queries). An implementation that knows the node's
  // boundary faces can answer from their current corners instead.
  virtual int TangentSpace(const Mesh& mesh, NodeId node, std::array<Vec3, 2>& basis) const;
  // The boundary-layer columns to keep (SmoothingParams::keep_layers); nullptr if not built.
  virtual const KeptLayers* kept_layers() const { return nullptr; }
  // Where column node kept_layers()->nodes[index] goes on the ray from `from` (its wall node)
  // along unit `direction`: at its input distance from the input's wall (a boundary node on its
  // surface too), or nullopt where no point keeps that distance, which refuses the column move.
  // This default takes the distance along the ray as kept_layers() gives it; an implementation
  // that knows the wall corrects it where the ray leans from the wall's nearest face.
  virtual std::optional<Vec3> OnColumn(std::int64_t index, const Vec3& from,
                                       const Vec3& direction) const {
    return from + kept_layers()->distance[index] * direction;
  }
};

}  // namespace getme
