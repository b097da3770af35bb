#pragma once

// Nearest points on a set of triangles for a query that comes with a bound: a sliding node's move
// starts from a point of its surface (its position before the move), so the nearest point lies
// within the move's length of the moved point, and only the triangles that reach into that ball
// can hold it. The smoothers move a node by a fraction of an edge, so that ball touches one to
// eight cells of a grid whose cells are about one triangle wide, and holds a handful of
// triangles.
//
// A graded surface (a boundary layer's small wall faces beside a far field's large ones) would
// put a large triangle in thousands of cells of a grid sized for the small ones, so the grid has
// levels: level l has cells 2^l times the size of level 0's, and a triangle goes to the finest
// level where its bounding box touches at most eight cells. A query looks in every level that
// has triangles; on an evenly meshed surface that is level 0 alone.
//
// Why not only CGAL's AABB tree (which SurfaceProjector still asks when this grid cannot answer):
// its query, even started from the node's last position, walks the hierarchy from the root and
// costs about 0.7 µs (docs/benchmarks.md, BM_Projection); on meshes where most nodes slide that
// was 20–40 % of a sliding run. A hash of the grid's cells goes straight to the few triangles
// near the point. docs/boundary.md has the measurements.
//
// Immutable once built, so threads may share it.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "absl/container/flat_hash_map.h"
#include "getme/elements/vec3.h"

namespace getme::surface {

class TriangleGrid {
 public:
  // Over `triangles` (their corners), which must not be degenerate (SurfaceProjector leaves those
  // out, as for its trees).
  explicit TriangleGrid(std::span<const std::array<Vec3, 3>> triangles);

  // The nearest point of the triangles to `point`, if some triangle comes within `bound` of it
  // (the caller's bound: the distance to a point of the triangles it knows); nullopt if none
  // does, or if the bound spans more cells than a short move would (kMaxCells), where a tree
  // search is the cheaper way. The answer is the nearest point of every triangle, not only of
  // those near the bound: any nearer one would be within the bound too.
  std::optional<Vec3> NearestWithin(const Vec3& point, double bound) const;

  // Above this many cells in one level a query is left to the caller's tree (it means a move of
  // two cells or more in every direction, which the smoothers rarely make).
  static constexpr std::int64_t kMaxCells = 64;

  // A triangle and its distance from a point.
  struct Reach {
    double distance;
    std::uint32_t triangle;
  };
  // Every triangle within `radius` of `point` with its distance, nearest first (equal distances
  // by index), into `within`; false if the ball spans more than kMaxGatherCells cells in a level.
  // For lists built once (node_triangles.h), so it may look at more cells than a query does.
  // `scratch` is working space, kept by the caller to spare an allocation per call.
  bool TrianglesWithin(const Vec3& point, double radius, std::vector<Reach>& within,
                       std::vector<std::uint32_t>& scratch) const;
  static constexpr std::int64_t kMaxGatherCells = 512;

  // The nearest point of triangle `triangle` (an index TrianglesWithin gave) to `point`.
  Vec3 ClosestPointOf(std::uint32_t triangle, const Vec3& point) const {
    return ClosestPoint(triangles_[triangle], point);
  }

  // Level 0's cell size, and how many levels hold triangles.
  double cell_size() const { return cell_size_; }
  int level_count() const { return static_cast<int>(levels_.size()); }

 private:
  // What the closest-point test needs of a triangle, computed once: its corner a, its edges from
  // a and their dot products.
  struct Prepared {
    Vec3 a, ab, ac;
    double ab_ab, ab_ac, ac_ac;
  };
  // A triangle as a cell lists it: its bounding box in floats rounded outwards (conservative
  // for the rejection, and a cell's list is then one contiguous scan), and its index.
  struct Member {
    std::array<float, 3> low, high;
    std::uint32_t triangle;
  };
  using CellKey = std::uint64_t;
  using CellRange = std::array<std::array<std::int64_t, 3>, 2>;

  std::array<std::int64_t, 3> CellOf(int level, const Vec3& point) const;
  CellRange CellsOf(int level, const Vec3& low, const Vec3& high) const;
  static CellKey Key(int level, const std::array<std::int64_t, 3>& cell);
  static Vec3 ClosestPoint(const Prepared& triangle, const Vec3& point);

  std::vector<Prepared> triangles_;
  Vec3 origin_ = Vec3::Zero();
  double cell_size_ = 1.0;
  std::vector<int> levels_;  // the levels that hold triangles, finest first
  // Per occupied cell (level and position), the range of its triangles in members_.
  absl::flat_hash_map<CellKey, std::pair<std::uint32_t, std::uint32_t>> cells_;
  std::vector<Member> members_;
};

}  // namespace getme::surface
