#pragma once

#include "getme/elements/vec3.h"
#include "getme/mesh/mesh.h"

namespace getme {

// Boundary nodes that slide on the input's own surface instead of staying fixed (issue 15,
// docs/boundary.md). The caller builds it from the input mesh (surface/: the boundary's groups,
// feature curves and corners, and nearest points through CGAL) and passes it to Smooth(); the
// engine itself knows no geometry library. Smooth() asks Slides() once per boundary node that the
// caller did not fix; every phase then passes each new position of a sliding node through
// Project() before it judges the step, so a sliding node is always on its surface (or curve)
// when an element's quality is computed. Implementations must be safe to call from several
// threads at once.
class BoundarySlide {
 public:
  virtual ~BoundarySlide() = default;
  // Whether boundary node `node` slides; false keeps it fixed (a corner, say).
  virtual bool Slides(NodeId node) const = 0;
  // Where sliding node `node` belongs when a smoother has put it at `point`.
  virtual Vec3 Project(NodeId node, const Vec3& point) const = 0;
  // How far `point` is from the input's boundary surface: the result check's measure.
  virtual double DistanceToSurface(const Vec3& point) const = 0;
};

}  // namespace getme
