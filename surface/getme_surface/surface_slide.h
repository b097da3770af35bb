#pragma once

// The engine's BoundarySlide (core/getme/smoothing/boundary_slide.h) on the input's own surface:
// surface and feature nodes slide, corners stay, and a moved node goes back to the nearest point
// of its group's faces or its feature curve in the input (boundary_surface.h,
// surface_projector.h). Built once from the input mesh, before smoothing.

#include <memory>
#include <span>

#include "absl/status/statusor.h"
#include "getme/smoothing/boundary_slide.h"
#include "getme_surface/boundary_surface.h"
#include "getme_surface/surface_projector.h"

namespace getme::surface {

class SurfaceSlide final : public BoundarySlide {
 public:
  static absl::StatusOr<std::unique_ptr<SurfaceSlide>> Build(
      const Mesh& mesh, std::span<const GroupedFace> groups = {},
      double feature_angle_degrees = kDefaultFeatureAngleDegrees);

  bool Slides(NodeId node) const override;
  Vec3 Project(NodeId node, const Vec3& point) const override;
  double DistanceToSurface(const Vec3& point) const override;

  const BoundarySurface& surface() const { return surface_; }

 private:
  SurfaceSlide(BoundarySurface surface, SurfaceProjector projector)
      : surface_(std::move(surface)), projector_(std::move(projector)) {}

  BoundarySurface surface_;
  SurfaceProjector projector_;
};

}  // namespace getme::surface
