#pragma once

// Nearest-point queries on the input's own boundary (issue 15, item 1): a sliding boundary node
// that moved off its surface goes back to the nearest point of the faces of its group, a feature
// node to the nearest point of its feature curve. The geometry is the input's, copied when the
// projector is built, so the surface a node returns to never drifts with the smoothing.
//
// A query that comes with a point of the surface (`near`: the node's position before its move)
// goes to a grid of the group's triangles (triangle_grid.h), which needs to look only within the
// move's length. Other queries, and moves too long for the grid, go to CGAL's AABB trees (one
// per group, one per curve), built at their first query. Quads are split along their diagonal
// 0–2 into two triangles: a bilinear patch would differ from that by the quad's warp, which
// smoothing keeps small. docs/boundary.md says why CGAL, and why a grid as well. Queries only
// read (the trees are built under std::call_once), so threads may share a projector.

#include <memory>
#include <vector>

#include "absl/status/statusor.h"
#include "getme/elements/vec3.h"
#include "getme/mesh/mesh.h"
#include "getme_surface/boundary_surface.h"
#include "getme_surface/triangle_grid.h"

namespace getme::surface {

class SurfaceProjector {
 public:
  // Trees over the current coordinates of `mesh` for the faces and feature edges of `surface`
  // (which must come from the same mesh).
  static absl::StatusOr<SurfaceProjector> Build(const Mesh& mesh, const BoundarySurface& surface);

  SurfaceProjector(SurfaceProjector&&) noexcept;
  SurfaceProjector& operator=(SurfaceProjector&&) noexcept;
  ~SurfaceProjector();

  // The nearest point to `point` on the faces of `group` (0 ≤ group < group_count()). `near`, if
  // given, must be a point of them (a sliding node's position before its move): the nearest
  // point is then within |point − near|, which lets the grid answer a short move with a few
  // triangles.
  Vec3 OnGroup(int group, const Vec3& point, const Vec3* near = nullptr) const;
  // The nearest point to `point` on feature curve `curve` (0 ≤ curve < curve_count()); `near` as
  // above, a point of the curve.
  Vec3 OnCurve(int curve, const Vec3& point, const Vec3* near = nullptr) const;
  // Where a node of kind `kind` with support `support` (BoundarySurface) at `point` belongs:
  // OnGroup for kSurface, OnCurve for kFeature, `point` itself otherwise (interior nodes are not
  // the projector's business, corners do not move).
  Vec3 Project(BoundaryNodeKind kind, int support, const Vec3& point,
               const Vec3* near = nullptr) const;
  // The distance from `point` to the nearest face of group `group`, or to curve `curve`: how far
  // a sliding node is from where it belongs (the result check asks it for every sliding node).
  double DistanceToGroup(int group, const Vec3& point) const;
  double DistanceToCurve(int curve, const Vec3& point) const;
  // The distance from `point` to the nearest face of any group.
  double DistanceToSurface(const Vec3& point) const;

  int group_count() const;
  int curve_count() const;
  // Per group, the grid of its triangles (for node_triangles.h's lists).
  const std::vector<TriangleGrid>& group_grids() const;

 private:
  struct Trees;
  explicit SurfaceProjector(std::unique_ptr<Trees> trees);
  std::unique_ptr<Trees> trees_;
};

}  // namespace getme::surface
