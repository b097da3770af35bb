#include "getme_surface/surface_projector.h"

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <limits>
#include <vector>

#include "absl/strings/str_cat.h"

namespace getme::surface {
namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Segment = Kernel::Segment_3;
using TriangleTree = CGAL::AABB_tree<CGAL::AABB_traits<
    Kernel, CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>>>;
using SegmentTree = CGAL::AABB_tree<CGAL::AABB_traits<
    Kernel, CGAL::AABB_segment_primitive<Kernel, std::vector<Segment>::const_iterator>>>;

Point ToPoint(const Vec3& v) { return Point(v[0], v[1], v[2]); }
Vec3 ToVec3(const Point& p) { return Vec3(p.x(), p.y(), p.z()); }

// A tree with the primitives it points into: the primitives hold iterators into `items`, which
// therefore never change once the tree is built.
template <typename Item, typename Tree>
struct IndexedItems {
  std::vector<Item> items;
  Tree tree;

  // Builds the hierarchy and its distance-query accelerator now, with one query, rather than
  // lazily at the first query: afterwards every query only reads, so threads may share the tree.
  void Build() {
    tree.rebuild(items.cbegin(), items.cend());
    if (items.empty()) return;
    tree.accelerate_distance_queries();
    tree.closest_point(Point(0.0, 0.0, 0.0));
  }
  Vec3 Nearest(const Vec3& point) const {
    if (items.empty() || !point.allFinite()) return point;
    return ToVec3(tree.closest_point(ToPoint(point)));
  }
};

}  // namespace

struct SurfaceProjector::Trees {
  std::vector<IndexedItems<Triangle, TriangleTree>> groups;
  std::vector<IndexedItems<Segment, SegmentTree>> curves;
  IndexedItems<Triangle, TriangleTree> all;
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
  const auto add = [&](int group, const Triangle& triangle) {
    // A triangle without area has no nearest point of its own (its edges belong to its
    // neighbours), and CGAL's distance queries assume none is degenerate.
    if (triangle.is_degenerate()) return;
    trees->groups[group].items.push_back(triangle);
    trees->all.items.push_back(triangle);
  };
  for (const BoundaryFace& face : surface.faces) {
    const Point a = point(face.nodes[0]);
    const Point b = point(face.nodes[1]);
    const Point c = point(face.nodes[2]);
    add(face.group, Triangle(a, b, c));
    if (face.size == 4) add(face.group, Triangle(a, c, point(face.nodes[3])));
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

Vec3 SurfaceProjector::OnGroup(int group, const Vec3& point) const {
  return trees_->groups[group].Nearest(point);
}

Vec3 SurfaceProjector::OnCurve(int curve, const Vec3& point) const {
  return trees_->curves[curve].Nearest(point);
}

Vec3 SurfaceProjector::Project(BoundaryNodeKind kind, int support, const Vec3& point) const {
  switch (kind) {
    case BoundaryNodeKind::kSurface:
      return OnGroup(support, point);
    case BoundaryNodeKind::kFeature:
      return OnCurve(support, point);
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
