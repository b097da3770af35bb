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
  slide->IndexNeighbourhoods(mesh.node_count());
  slide->ListNodeTriangles(mesh);
  if (!options.keep_layers) return slide;
  slide->kept_ = DescribeKeptLayers(mesh, slide->layers_, *slide->walls_);
  for (const NodeId node : slide->kept_.nodes) {
    slide->wall_distance_.push_back(
        slide->walls_->Distance(Vec3(mesh.x()[node], mesh.y()[node], mesh.z()[node])));
  }
  return slide;
}

void SurfaceSlide::IndexNeighbourhoods(std::int64_t node_count) {
  std::vector<std::vector<std::int64_t>> lists(static_cast<std::size_t>(node_count));
  for (std::size_t f = 0; f < surface_.faces.size(); ++f) {
    const BoundaryFace& face = surface_.faces[f];
    for (int k = 0; k < face.size; ++k) {
      if (surface_.kind[face.nodes[k]] == BoundaryNodeKind::kSurface) {
        lists[face.nodes[k]].push_back(static_cast<std::int64_t>(f));
      }
    }
  }
  for (std::size_t e = 0; e < surface_.feature_edges.size(); ++e) {
    const auto [a, b] = surface_.feature_edges[e];
    if (surface_.kind[a] == BoundaryNodeKind::kFeature) lists[a].push_back(b);
    if (surface_.kind[b] == BoundaryNodeKind::kFeature) lists[b].push_back(a);
  }
  neighbourhood_offsets_.assign(1, 0);
  for (const auto& list : lists) {
    neighbourhood_.insert(neighbourhood_.end(), list.begin(), list.end());
    neighbourhood_offsets_.push_back(static_cast<std::int64_t>(neighbourhood_.size()));
  }
}

void SurfaceSlide::ListNodeTriangles(const Mesh& mesh) {
  std::vector<bool> listed(static_cast<std::size_t>(mesh.node_count()), false);
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    listed[static_cast<std::size_t>(node)] =
        surface_.kind[node] == BoundaryNodeKind::kSurface && Slides(node);
  }
  node_triangles_ = NodeTriangles(mesh, surface_, projector_.group_grids(), listed,
                                  neighbourhood_offsets_, neighbourhood_);
}

bool SurfaceSlide::Slides(NodeId node) const {
  const BoundaryNodeKind kind = surface_.kind[node];
  if (kind != BoundaryNodeKind::kSurface && kind != BoundaryNodeKind::kFeature) return false;
  // A column's boundary node moves with its column or not at all (the class comment).
  return options_.keep_layers || layers_.level[node] < 0;
}

int SurfaceSlide::TangentSpace(const Mesh& mesh, NodeId node, std::array<Vec3, 2>& basis) const {
  const auto at = [&](std::int64_t n) { return Vec3(mesh.x()[n], mesh.y()[n], mesh.z()[n]); };
  const std::int64_t begin = neighbourhood_offsets_[node];
  const std::int64_t end = neighbourhood_offsets_[node + 1];
  if (surface_.kind[node] == BoundaryNodeKind::kFeature && end - begin == 2) {
    const Vec3 chord = at(neighbourhood_[begin + 1]) - at(neighbourhood_[begin]);
    if (chord.norm() > 0.0) {
      basis[0] = chord.normalized();
      return 1;
    }
  } else if (surface_.kind[node] == BoundaryNodeKind::kSurface && end > begin) {
    Vec3 normal = Vec3::Zero();
    for (std::int64_t k = begin; k < end; ++k) {
      const BoundaryFace& face = surface_.faces[neighbourhood_[k]];
      const Vec3 a = at(face.nodes[0]), b = at(face.nodes[1]), c = at(face.nodes[2]);
      // A quad's area vector is half the cross product of its diagonals.
      normal += face.size == 4 ? (c - a).cross(at(face.nodes[3]) - b) : (b - a).cross(c - a);
    }
    if (normal.norm() > 0.0) {
      normal.normalize();
      // Any unit vector in the plane, then the one across it.
      int axis = 0;
      for (int k = 1; k < 3; ++k) {
        if (std::abs(normal[k]) < std::abs(normal[axis])) axis = k;
      }
      basis[0] = normal.cross(Vec3::Unit(axis)).normalized();
      basis[1] = normal.cross(basis[0]);
      return 2;
    }
  }
  return BoundarySlide::TangentSpace(mesh, node, basis);
}

Vec3 SurfaceSlide::Project(NodeId node, const Vec3& point, const Vec3* near) const {
  if (near != nullptr && surface_.kind[node] == BoundaryNodeKind::kSurface) {
    const std::optional<Vec3> nearest = node_triangles_.Nearest(
        projector_.group_grids()[static_cast<std::size_t>(surface_.support[node])], node, point,
        *near);
    if (nearest) return *nearest;
  }
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

double SurfaceSlide::DistanceToSurface(NodeId node, const Vec3& point) const {
  switch (surface_.kind[node]) {
    case BoundaryNodeKind::kSurface:
      return projector_.DistanceToGroup(surface_.support[node], point);
    case BoundaryNodeKind::kFeature:
      return projector_.DistanceToCurve(surface_.support[node], point);
    case BoundaryNodeKind::kInterior:
    case BoundaryNodeKind::kCorner:
      break;
  }
  return projector_.DistanceToSurface(point);
}

}  // namespace getme::surface
