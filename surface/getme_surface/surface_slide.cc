#include "getme_surface/surface_slide.h"

namespace getme::surface {

absl::StatusOr<std::unique_ptr<SurfaceSlide>> SurfaceSlide::Build(
    const Mesh& mesh, std::span<const GroupedFace> groups, double feature_angle_degrees) {
  absl::StatusOr<BoundarySurface> surface =
      ExtractBoundarySurface(mesh, groups, feature_angle_degrees);
  if (!surface.ok()) return surface.status();
  absl::StatusOr<SurfaceProjector> projector = SurfaceProjector::Build(mesh, *surface);
  if (!projector.ok()) return projector.status();
  return std::unique_ptr<SurfaceSlide>(
      new SurfaceSlide(*std::move(surface), *std::move(projector)));
}

bool SurfaceSlide::Slides(NodeId node) const {
  const BoundaryNodeKind kind = surface_.kind[node];
  return kind == BoundaryNodeKind::kSurface || kind == BoundaryNodeKind::kFeature;
}

Vec3 SurfaceSlide::Project(NodeId node, const Vec3& point) const {
  return projector_.Project(surface_.kind[node], surface_.support[node], point);
}

double SurfaceSlide::DistanceToSurface(const Vec3& point) const {
  return projector_.DistanceToSurface(point);
}

}  // namespace getme::surface
