#pragma once

// Each sliding surface node's own short list of the triangles it can be projected onto: those of
// its group within a reach of its input position, nearest first. The smoothers move a node by a
// fraction of an edge at a time and ask for its nearest surface point after every move (issue 15:
// on a shell, where every node slides, that was a quarter of the run through the grid's hash
// lookups, which miss the cache). A scan of the node's list answers most of those queries from
// a few triangles next to each other in memory.
//
// Why the answer is the nearest point of the whole group, not just of the list: the query comes
// with a point of the surface (the node's position before the move, `near`), so the nearest
// point p* is within m = |point − near| of `point`, and so within s + m of the node's input
// position x0, where s = |point − x0|. The list holds every triangle within the reach R of x0,
// so when s + m ≤ R it holds p*'s triangle. Otherwise (the node has wandered off, or the move is
// long) the caller asks the grid. The scan stops at the first triangle whose distance from x0,
// less s, exceeds the best distance found: that bounds its distance from `point` from below,
// and the list is sorted by it.
//
// Immutable once built, so threads may share it.

#include <cstdint>
#include <optional>
#include <vector>

#include "getme/elements/vec3.h"
#include "getme/mesh/mesh.h"
#include "getme_surface/boundary_surface.h"
#include "getme_surface/triangle_grid.h"

namespace getme::surface {

class NodeTriangles {
 public:
  // The reach of a node's list, in units of its umbrella's radius (the farthest corner of its
  // own boundary faces from it). Half an umbrella answered 97.7-99.7 % of the sliding runs'
  // queries on the shell, the slice and knowles-mixed-beam, with lists of about six triangles; a
  // whole one answered all of them, but its longer lists cost more to gather than the grid
  // searches they spared (docs/boundary.md, "Nearest points").
  static constexpr double kReachInUmbrellas = 0.5;

  NodeTriangles() = default;
  // Lists for the nodes with `listed[node]` set, which must be kSurface nodes of `surface`;
  // `grids[g]` is group g's triangle grid, `faces_of` a node's boundary faces (CSR over the nodes,
  // indices into surface.faces).
  NodeTriangles(const Mesh& mesh, const BoundarySurface& surface,
                const std::vector<TriangleGrid>& grids, const std::vector<bool>& listed,
                const std::vector<std::int64_t>& faces_of_offsets,
                const std::vector<std::int64_t>& faces_of);

  // The nearest point of `grid` (the node's group's) to `point`, where `near` is a point of that
  // group; nullopt if the node has no list or its list cannot be sure of the answer.
  std::optional<Vec3> Nearest(const TriangleGrid& grid, NodeId node, const Vec3& point,
                              const Vec3& near) const;

  std::int64_t listed_nodes() const { return static_cast<std::int64_t>(nodes_.size()); }
  std::int64_t entries() const { return static_cast<std::int64_t>(entries_.size()); }

 private:
  struct Node {
    Vec3 origin;
    double reach;
    std::uint32_t begin, end;
  };
  struct Entry {
    float distance;  // from the node's origin, rounded down
    std::uint32_t triangle;
  };
  static constexpr std::uint32_t kUnlisted = ~std::uint32_t{0};
  // Per mesh node, its index in nodes_ (kUnlisted for most: only sliding surface nodes have a
  // list, so a large mesh pays 4 bytes a node and the rest only for its boundary).
  std::vector<std::uint32_t> slot_;
  std::vector<Node> nodes_;
  std::vector<Entry> entries_;
};

}  // namespace getme::surface
