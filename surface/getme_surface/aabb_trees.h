#pragma once

// CGAL's AABB trees as the surface library uses them (an internal header: only surface/'s .cc
// files include it, so nothing outside sees CGAL). docs/boundary.md says why CGAL.

#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <array>
#include <vector>

#include "getme/elements/vec3.h"
#include "getme/mesh/mesh.h"

namespace getme::surface::aabb {

using Kernel = CGAL::Simple_cartesian<double>;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Segment = Kernel::Segment_3;
using TriangleTree = CGAL::AABB_tree<CGAL::AABB_traits<
    Kernel, CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>>>;
using SegmentTree = CGAL::AABB_tree<CGAL::AABB_traits<
    Kernel, CGAL::AABB_segment_primitive<Kernel, std::vector<Segment>::const_iterator>>>;

inline Point ToPoint(const Vec3& v) { return Point(v[0], v[1], v[2]); }
inline Vec3 ToVec3(const Point& p) { return Vec3(p.x(), p.y(), p.z()); }

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
  // The nearest point of the items to `point`; `point` itself when there are none. `near`, if
  // given, must be a point of the items: the search starts with it as the best so far instead
  // of asking the tree's k-d tree of corners for one.
  Vec3 Nearest(const Vec3& point, const Vec3* near = nullptr) const {
    if (items.empty() || !point.allFinite()) return point;
    if (near != nullptr && near->allFinite()) {
      return ToVec3(tree.closest_point(ToPoint(point), ToPoint(*near)));
    }
    return ToVec3(tree.closest_point(ToPoint(point)));
  }
};

// Appends a boundary face (3 or 4 nodes, as its element lists them) to `triangles` at the mesh's
// current coordinates: a quad split along its diagonal 0–2, since a bilinear patch would differ
// from that only by the quad's warp, which smoothing keeps small. A triangle without area is left
// out: it has no nearest point of its own (its edges belong to its neighbours), and CGAL's
// distance queries assume none is degenerate.
inline void AppendFaceTriangles(const Mesh& mesh, const std::array<NodeId, 4>& nodes, int size,
                                std::vector<Triangle>& triangles) {
  const auto point = [&](NodeId node) {
    return Point(mesh.x()[node], mesh.y()[node], mesh.z()[node]);
  };
  const auto append = [&](const Triangle& triangle) {
    if (!triangle.is_degenerate()) triangles.push_back(triangle);
  };
  append(Triangle(point(nodes[0]), point(nodes[1]), point(nodes[2])));
  if (size == 4) append(Triangle(point(nodes[0]), point(nodes[2]), point(nodes[3])));
}

using TriangleSet = IndexedItems<Triangle, TriangleTree>;
using SegmentSet = IndexedItems<Segment, SegmentTree>;

}  // namespace getme::surface::aabb
