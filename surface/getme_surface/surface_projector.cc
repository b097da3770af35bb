#include "getme_surface/surface_projector.h"

#include <limits>
#include <vector>

#include "absl/strings/str_cat.h"
#include "getme_surface/aabb_trees.h"

namespace getme::surface {
using aabb::Point;
using aabb::Segment;

struct SurfaceProjector::Trees {
  std::vector<aabb::TriangleSet> groups;
  std::vector<aabb::SegmentSet> curves;
  aabb::TriangleSet all;
};

absl::StatusOr<SurfaceProjector> SurfaceProjector::Build(const Mesh& mesh,
                                                         const BoundarySurface& surface) {
  if (surface.kind.size() != static_cast<std::size_t>(mesh.node_count())) {
    return absl::InvalidArgumentError(absl::StrCat("the boundary surface has ", surface.kind.size(),
                                                   " nodes, the mesh ", mesh.node_count(),
                                                   ": build both from the same mesh"));
  }
  auto trees = std::make_unique<Trees>();
  trees->groups.resize(static_cast<std::size_t>(surface.group_count));
  trees->curves.resize(static_cast<std::size_t>(surface.curve_count));
  const auto point = [&](NodeId node) {
    return Point(mesh.x()[node], mesh.y()[node], mesh.z()[node]);
  };
  for (const BoundaryFace& face : surface.faces) {
    aabb::AppendFaceTriangles(mesh, face.nodes, face.size, trees->groups[face.group].items);
    aabb::AppendFaceTriangles(mesh, face.nodes, face.size, trees->all.items);
  }
  for (std::size_t e = 0; e < surface.feature_edges.size(); ++e) {
    const Segment segment(point(surface.feature_edges[e][0]), point(surface.feature_edges[e][1]));
    if (!segment.is_degenerate()) trees->curves[surface.edge_curve[e]].items.push_back(segment);
  }
  for (auto& group : trees->groups) group.Build();
  for (auto& curve : trees->curves) curve.Build();
  trees->all.Build();
  return SurfaceProjector(std::move(trees));
}

SurfaceProjector::SurfaceProjector(std::unique_ptr<Trees> trees) : trees_(std::move(trees)) {}
SurfaceProjector::SurfaceProjector(SurfaceProjector&&) noexcept = default;
SurfaceProjector& SurfaceProjector::operator=(SurfaceProjector&&) noexcept = default;
SurfaceProjector::~SurfaceProjector() = default;

Vec3 SurfaceProjector::OnGroup(int group, const Vec3& point, const Vec3* near) const {
  return trees_->groups[group].Nearest(point, near);
}

Vec3 SurfaceProjector::OnCurve(int curve, const Vec3& point, const Vec3* near) const {
  return trees_->curves[curve].Nearest(point, near);
}

Vec3 SurfaceProjector::Project(BoundaryNodeKind kind, int support, const Vec3& point,
                               const Vec3* near) const {
  switch (kind) {
    case BoundaryNodeKind::kSurface:
      return OnGroup(support, point, near);
    case BoundaryNodeKind::kFeature:
      return OnCurve(support, point, near);
    case BoundaryNodeKind::kInterior:
    case BoundaryNodeKind::kCorner:
      break;
  }
  return point;
}

double SurfaceProjector::DistanceToSurface(const Vec3& point) const {
  if (trees_->all.items.empty()) return std::numeric_limits<double>::infinity();
  return (trees_->all.Nearest(point) - point).norm();
}

int SurfaceProjector::group_count() const { return static_cast<int>(trees_->groups.size()); }
int SurfaceProjector::curve_count() const { return static_cast<int>(trees_->curves.size()); }

}  // namespace getme::surface
