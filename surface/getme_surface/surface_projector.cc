#include "getme_surface/surface_projector.h"

#include <algorithm>
#include <limits>
#include <mutex>
#include <vector>

#include "absl/strings/str_cat.h"
#include "getme_surface/aabb_trees.h"
#include "getme_surface/triangle_grid.h"

namespace getme::surface {
using aabb::Point;
using aabb::Segment;

namespace {

std::vector<std::array<Vec3, 3>> Corners(const std::vector<aabb::Triangle>& triangles) {
  std::vector<std::array<Vec3, 3>> corners;
  corners.reserve(triangles.size());
  for (const aabb::Triangle& triangle : triangles) {
    corners.push_back(
        {aabb::ToVec3(triangle[0]), aabb::ToVec3(triangle[1]), aabb::ToVec3(triangle[2])});
  }
  return corners;
}

}  // namespace

struct SurfaceProjector::Trees {
  // A triangle tree built at its first query, by whichever thread asks first. The grids answer
  // nearly every query of a smoothing run, so most runs never build one (building them was a
  // third of the projector's set-up on the spherical shell).
  struct LazyTriangles {
    mutable aabb::TriangleSet set;
    mutable std::once_flag built;
    const aabb::TriangleSet& Get() const {
      std::call_once(built, [this] { set.Build(); });
      return set;
    }
  };

  explicit Trees(int group_count)
      : groups(std::make_unique<LazyTriangles[]>(static_cast<std::size_t>(group_count))) {}
  // Per group: its triangles as a tree, and as a grid for the queries that come with a point of
  // the group (triangle_grid.h). The grids answer those; the trees, the others.
  std::unique_ptr<LazyTriangles[]> groups;
  std::vector<TriangleGrid> group_grids;
  std::vector<aabb::SegmentSet> curves;

  // The nearest point of group `group` to `point`: the grid's, where some triangle comes within
  // `bound` (exact then), else the tree's (started from `near` if given).
  Vec3 NearestOnGroup(int group, const Vec3& point, double bound, const Vec3* near) const {
    if (const std::optional<Vec3> nearest = group_grids[group].NearestWithin(point, bound)) {
      return *nearest;
    }
    return groups[group].Get().Nearest(point, near);
  }
};

absl::StatusOr<SurfaceProjector> SurfaceProjector::Build(const Mesh& mesh,
                                                         const BoundarySurface& surface) {
  if (surface.kind.size() != static_cast<std::size_t>(mesh.node_count())) {
    return absl::InvalidArgumentError(absl::StrCat("the boundary surface has ", surface.kind.size(),
                                                   " nodes, the mesh ", mesh.node_count(),
                                                   ": build both from the same mesh"));
  }
  auto trees = std::make_unique<Trees>(surface.group_count);
  trees->curves.resize(static_cast<std::size_t>(surface.curve_count));
  const auto point = [&](NodeId node) {
    return Point(mesh.x()[node], mesh.y()[node], mesh.z()[node]);
  };
  for (const BoundaryFace& face : surface.faces) {
    aabb::AppendFaceTriangles(mesh, face.nodes, face.size, trees->groups[face.group].set.items);
  }
  for (std::size_t e = 0; e < surface.feature_edges.size(); ++e) {
    const Segment segment(point(surface.feature_edges[e][0]), point(surface.feature_edges[e][1]));
    if (!segment.is_degenerate()) trees->curves[surface.edge_curve[e]].items.push_back(segment);
  }
  for (int group = 0; group < surface.group_count; ++group) {
    trees->group_grids.emplace_back(Corners(trees->groups[group].set.items));
  }
  for (auto& curve : trees->curves) curve.Build();
  return SurfaceProjector(std::move(trees));
}

SurfaceProjector::SurfaceProjector(std::unique_ptr<Trees> trees) : trees_(std::move(trees)) {}
SurfaceProjector::SurfaceProjector(SurfaceProjector&&) noexcept = default;
SurfaceProjector& SurfaceProjector::operator=(SurfaceProjector&&) noexcept = default;
SurfaceProjector::~SurfaceProjector() = default;

Vec3 SurfaceProjector::OnGroup(int group, const Vec3& point, const Vec3* near) const {
  if (near == nullptr) return trees_->groups[group].Get().Nearest(point);
  return trees_->NearestOnGroup(group, point, (point - *near).norm(), near);
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

double SurfaceProjector::DistanceToGroup(int group, const Vec3& point) const {
  const Trees::LazyTriangles& triangles = trees_->groups[group];
  if (triangles.set.items.empty()) return std::numeric_limits<double>::infinity();
  // The points asked about are sliding nodes, on the surface or within rounding of it: a grid
  // search within a thousandth of a cell answers them exactly, and the tree answers the rest.
  const double bound = 1e-3 * trees_->group_grids[group].cell_size();
  return (trees_->NearestOnGroup(group, point, bound, nullptr) - point).norm();
}

double SurfaceProjector::DistanceToCurve(int curve, const Vec3& point) const {
  if (trees_->curves[curve].items.empty()) return std::numeric_limits<double>::infinity();
  return (trees_->curves[curve].Nearest(point) - point).norm();
}

double SurfaceProjector::DistanceToSurface(const Vec3& point) const {
  // Not on the smoothers' path (they ask DistanceToGroup and DistanceToCurve for their nodes), so
  // the plain way: the nearest of every group's tree.
  double distance = std::numeric_limits<double>::infinity();
  for (int group = 0; group < group_count(); ++group) {
    if (!trees_->groups[group].set.items.empty()) {
      distance = std::min(distance, (trees_->groups[group].Get().Nearest(point) - point).norm());
    }
  }
  return distance;
}

int SurfaceProjector::group_count() const { return static_cast<int>(trees_->group_grids.size()); }
int SurfaceProjector::curve_count() const { return static_cast<int>(trees_->curves.size()); }
const std::vector<TriangleGrid>& SurfaceProjector::group_grids() const {
  return trees_->group_grids;
}

}  // namespace getme::surface
