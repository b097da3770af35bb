#pragma once

// Nearest-point queries on the input's own boundary (issue 15, item 1): a sliding boundary node
// that moved off its surface goes back to the nearest point of the faces of its group, a feature
// node to the nearest point of its feature curve. The geometry is the input's, copied when the
// projector is built, so the surface a node returns to never drifts with the smoothing.
//
// Queries run through CGAL's AABB trees (bounding-volume hierarchies of the triangles and of the
// feature segments), one per group and one per curve: O(log n) per query on a well-shaped
// surface. Quads are split along their diagonal 0–2 into two triangles: a bilinear patch would
// differ from that by the quad's warp, which smoothing keeps small. docs/boundary.md says why
// CGAL. Every structure is built by Build(); queries only read, so threads may share a projector.

#include <memory>

#include "absl/status/statusor.h"
#include "getme/elements/vec3.h"
#include "getme/mesh/mesh.h"
#include "getme_surface/boundary_surface.h"

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
  // given, must be a point of them (a sliding node's position before its move): the search
  // starts from it instead of from a search for the nearest triangle corner, which halves a
  // query's cost when the move is short.
  Vec3 OnGroup(int group, const Vec3& point, const Vec3* near = nullptr) const;
  // The nearest point to `point` on feature curve `curve` (0 ≤ curve < curve_count()); `near` as
  // above, a point of the curve.
  Vec3 OnCurve(int curve, const Vec3& point, const Vec3* near = nullptr) const;
  // Where a node of kind `kind` with support `support` (BoundarySurface) at `point` belongs:
  // OnGroup for kSurface, OnCurve for kFeature, `point` itself otherwise (interior nodes are not
  // the projector's business, corners do not move).
  Vec3 Project(BoundaryNodeKind kind, int support, const Vec3& point,
               const Vec3* near = nullptr) const;
  // The distance from `point` to the nearest face of any group.
  double DistanceToSurface(const Vec3& point) const;

  int group_count() const;
  int curve_count() const;

 private:
  struct Trees;
  explicit SurfaceProjector(std::unique_ptr<Trees> trees);
  std::unique_ptr<Trees> trees_;
};

}  // namespace getme::surface
