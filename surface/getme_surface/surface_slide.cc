#include "getme_surface/surface_slide.h"

#include <cmath>

namespace getme::surface {

absl::StatusOr<std::unique_ptr<SurfaceSlide>> SurfaceSlide::Build(const Mesh& mesh,
                                                                  const SlideOptions& options) {
  absl::StatusOr<BoundarySurface> surface = ExtractBoundarySurface(
      mesh, options.groups, options.feature_angle_degrees, options.skip_interior_groups);
  if (!surface.ok()) return surface.status();
  absl::StatusOr<SurfaceProjector> projector = SurfaceProjector::Build(mesh, *surface);
  if (!projector.ok()) return projector.status();
  // The columns are needed in any case (Slides() holds their boundary nodes); their walls and the
  // engine's description of them only when they are kept.
  LayerColumns layers = FindLayerColumns(mesh);
  std::unique_ptr<WallDistance> walls;
  if (options.keep_layers) walls = std::make_unique<WallDistance>(mesh, layers);
  std::unique_ptr<SurfaceSlide> slide(new SurfaceSlide(
      options, *std::move(surface), *std::move(projector), std::move(layers), std::move(walls)));
  if (!options.keep_layers) return slide;
  slide->kept_ = DescribeKeptLayers(mesh, slide->layers_, *slide->walls_);
  for (const NodeId node : slide->kept_.nodes) {
    slide->wall_distance_.push_back(
        slide->walls_->Distance(Vec3(mesh.x()[node], mesh.y()[node], mesh.z()[node])));
  }
  return slide;
}

bool SurfaceSlide::Slides(NodeId node) const {
  const BoundaryNodeKind kind = surface_.kind[node];
  if (kind != BoundaryNodeKind::kSurface && kind != BoundaryNodeKind::kFeature) return false;
  // A column's boundary node moves with its column or not at all (the class comment).
  return options_.keep_layers || layers_.level[node] < 0;
}

Vec3 SurfaceSlide::Project(NodeId node, const Vec3& point, const Vec3* near) const {
  return projector_.Project(surface_.kind[node], surface_.support[node], point, near);
}

std::optional<Vec3> SurfaceSlide::OnColumn(std::int64_t index, const Vec3& from,
                                           const Vec3& direction) const {
  const NodeId node = kept_.nodes[index];
  const double wanted = wall_distance_[index];
  Vec3 point = AlongToWallDistance(*walls_, from, direction, kept_.distance[index], wanted);
  if (surface_.kind[node] != BoundaryNodeKind::kInterior) {
    // On an end cap, say: turn the ray into the node's surface, so that projecting onto it keeps
    // the wall distance.
    const Vec3 along = Project(node, point) - from;
    if (along.norm() > 0.0) {
      point = Project(node, AlongToWallDistance(*walls_, from, along.normalized(),
                                                kept_.distance[index], wanted));
    }
  }
  if (!(std::abs(walls_->Distance(point) - wanted) <= kWallDistanceTolerance * wanted)) {
    return std::nullopt;
  }
  return point;
}

double SurfaceSlide::DistanceToSurface(const Vec3& point) const {
  return projector_.DistanceToSurface(point);
}

}  // namespace getme::surface
