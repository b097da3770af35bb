#include "getme/meshgen/vessel_segments.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>

#include "absl/strings/str_cat.h"

namespace getme::meshgen {
namespace {

// gmsh copies the periodic cap's nodes through the translation, so matching nodes differ only by
// rounding: 1e-9 of the segment length is far below any mesh size and far above that.
constexpr double kCapTolerance = 1e-9;

// For every top-cap node, the bottom-cap node below it (-1 for nodes not on the top cap).
absl::StatusOr<std::vector<NodeId>> MatchCaps(const MeshDraft& draft, double segment_length) {
  const double tolerance = kCapTolerance * segment_length;
  std::vector<NodeId> bottom, top;
  for (NodeId node = 0; node < static_cast<NodeId>(draft.node_count()); ++node) {
    const double z = draft.node(node).z();
    if (std::abs(z) <= tolerance) bottom.push_back(node);
    if (std::abs(z - segment_length) <= tolerance) top.push_back(node);
  }
  if (bottom.empty() || bottom.size() != top.size()) {
    return absl::InternalError(absl::StrCat("StackSegments: the end caps have ", bottom.size(),
                                            " and ", top.size(), " nodes"));
  }
  // Caps hold a few hundred to a few thousand nodes: a quadratic search is cheap.
  std::vector<NodeId> below(draft.node_count(), -1);
  for (const NodeId t : top) {
    const Vec3 p = draft.node(t);
    double best = std::numeric_limits<double>::infinity();
    for (const NodeId b : bottom) {
      const Vec3 q = draft.node(b);
      const double distance = std::hypot(p.x() - q.x(), p.y() - q.y());
      if (distance < best) {
        best = distance;
        below[t] = b;
      }
    }
    if (best > tolerance) {
      return absl::InternalError(absl::StrCat("StackSegments: top cap node ", t,
                                              " has no bottom cap node below it (nearest ", best,
                                              " away)"));
    }
  }
  return below;
}

}  // namespace

absl::Status StackSegments(MeshDraft& draft, std::vector<std::array<NodeId, 3>>& wall_triangles,
                           double segment_length, int copies) {
  if (copies <= 1) return absl::OkStatus();
  absl::StatusOr<std::vector<NodeId>> below = MatchCaps(draft, segment_length);
  if (!below.ok()) return below.status();
  const NodeId segment_nodes = static_cast<NodeId>(draft.node_count());
  const ElementId segment_elements = static_cast<ElementId>(draft.element_count());
  const std::size_t segment_triangles = wall_triangles.size();
  std::vector<NodeId> top_of_bottom(segment_nodes, -1);  // inverse of `below`
  for (NodeId t = 0; t < segment_nodes; ++t) {
    if ((*below)[t] >= 0) top_of_bottom[(*below)[t]] = t;
  }
  const std::int64_t cap_nodes =
      std::count_if(top_of_bottom.begin(), top_of_bottom.end(), [](NodeId t) { return t >= 0; });
  const std::int64_t nodes_per_copy = segment_nodes - cap_nodes;
  draft.Reserve(segment_nodes + (copies - 1) * nodes_per_copy,
                std::int64_t{segment_elements} * copies,
                4 * std::int64_t{segment_elements} * copies);
  wall_triangles.reserve(segment_triangles * copies);

  // previous[n]: segment node n's id in the copy below; current[n]: in the copy being added.
  std::vector<NodeId> previous(segment_nodes), current(segment_nodes);
  for (NodeId n = 0; n < segment_nodes; ++n) previous[n] = n;
  for (int copy = 1; copy < copies; ++copy) {
    const double shift = copy * segment_length;
    for (NodeId n = 0; n < segment_nodes; ++n) {
      if (top_of_bottom[n] >= 0) {
        current[n] = previous[top_of_bottom[n]];
      } else {
        current[n] = draft.AddNode(draft.node(n) + Vec3(0.0, 0.0, shift));
      }
    }
    for (ElementId e = 0; e < segment_elements; ++e) {
      std::array<NodeId, 4> tet;
      const std::span<const NodeId> nodes = draft.element_nodes(e);
      for (int k = 0; k < 4; ++k) tet[k] = current[nodes[k]];
      draft.AddElement(ElementType::kTetrahedron, tet);
    }
    for (std::size_t t = 0; t < segment_triangles; ++t) {
      const std::array<NodeId, 3> triangle = wall_triangles[t];
      wall_triangles.push_back({current[triangle[0]], current[triangle[1]], current[triangle[2]]});
    }
    std::swap(previous, current);
  }
  return absl::OkStatus();
}

}  // namespace getme::meshgen
