#include "getme_surface/node_triangles.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace getme::surface {
namespace {

// A query's points lie on the surface only to within rounding, and the list's distances were
// rounded too: the reach a query may use is the gathering radius less this relative margin.
constexpr double kReachMargin = 1e-9;

}  // namespace

NodeTriangles::NodeTriangles(const Mesh& mesh, const BoundarySurface& surface,
                             const std::vector<TriangleGrid>& grids,
                             const std::vector<bool>& listed,
                             const std::vector<std::int64_t>& faces_of_offsets,
                             const std::vector<std::int64_t>& faces_of)
    : slot_(static_cast<std::size_t>(mesh.node_count()), kUnlisted) {
  std::vector<TriangleGrid::Reach> within;
  std::vector<std::uint32_t> scratch;
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    if (!listed[static_cast<std::size_t>(node)]) continue;
    const Vec3 origin = NodePosition(mesh, node);
    double umbrella = 0.0;
    for (std::int64_t k = faces_of_offsets[node]; k < faces_of_offsets[node + 1]; ++k) {
      const BoundaryFace& face = surface.faces[static_cast<std::size_t>(faces_of[k])];
      for (int corner = 0; corner < face.size; ++corner) {
        umbrella = std::max(umbrella, (NodePosition(mesh, face.nodes[corner]) - origin).norm());
      }
    }
    if (!(umbrella > 0.0) || !std::isfinite(umbrella)) continue;
    const double radius = kReachInUmbrellas * umbrella;
    const TriangleGrid& grid = grids[static_cast<std::size_t>(surface.support[node])];
    if (!grid.TrianglesWithin(origin, radius, within, scratch) || within.empty()) continue;
    slot_[static_cast<std::size_t>(node)] = static_cast<std::uint32_t>(nodes_.size());
    const auto begin = static_cast<std::uint32_t>(entries_.size());
    for (const TriangleGrid::Reach& reach : within) {
      // Rounded down, so that the distance less s stays a lower bound.
      const float distance = std::nextafter(static_cast<float>(reach.distance), 0.0f);
      entries_.push_back({distance, reach.triangle});
    }
    nodes_.push_back({origin, radius * (1.0 - kReachMargin), begin,
                      static_cast<std::uint32_t>(entries_.size())});
  }
}

std::optional<Vec3> NodeTriangles::Nearest(const TriangleGrid& grid, NodeId node, const Vec3& point,
                                           const Vec3& near) const {
  if (static_cast<std::size_t>(node) >= slot_.size()) return std::nullopt;  // built for no mesh
  const std::uint32_t slot = slot_[static_cast<std::size_t>(node)];
  if (slot == kUnlisted) return std::nullopt;
  const Node& entry = nodes_[slot];
  const double from_origin = (point - entry.origin).norm();
  const double move = (point - near).norm();
  if (!(from_origin + move <= entry.reach)) return std::nullopt;
  double best_squared = std::numeric_limits<double>::infinity();
  double best_distance = std::numeric_limits<double>::infinity();
  Vec3 best = point;
  for (std::uint32_t e = entry.begin; e < entry.end; ++e) {
    if (static_cast<double>(entries_[e].distance) - from_origin > best_distance) break;
    const Vec3 candidate = grid.ClosestPointOf(entries_[e].triangle, point);
    const double squared = (candidate - point).squaredNorm();
    // The first of equally near points wins: the list's order is fixed, so the answer does not
    // depend on the thread asking.
    if (squared < best_squared) {
      best_squared = squared;
      best_distance = std::sqrt(squared) * (1.0 + 1e-12);
      best = candidate;
    }
  }
  return best;
}

}  // namespace getme::surface
