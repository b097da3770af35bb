#include "getme/meshgen/node_jitter.h"

#include <random>

#include "getme/meshgen/deterministic_random.h"

namespace getme::meshgen {
namespace {

// Halving six times leaves 1/64 of the move: beyond that the node is as good as unmoved.
constexpr int kMaxHalvings = 6;

bool AllValid(const MeshDraft& draft, std::span<const ElementId> elements) {
  for (const ElementId element : elements) {
    if (!draft.IsElementValid(element)) return false;
  }
  return true;
}

}  // namespace

JitterStats JitterNodes(MeshDraft& draft, std::span<const double> max_move, std::uint64_t seed) {
  const CompressedRows node_elements = draft.NodeElements();
  std::mt19937_64 engine(seed);
  JitterStats stats;
  for (NodeId node = 0; node < static_cast<NodeId>(draft.node_count()); ++node) {
    const double dx = UniformSymmetric(engine);
    const double dy = UniformSymmetric(engine);
    const double dz = UniformSymmetric(engine);
    if (!(max_move[node] > 0.0)) continue;
    const Vec3 original = draft.node(node);
    const Vec3 displacement = max_move[node] * Vec3(dx, dy, dz);
    const std::span<const ElementId> adjacent = node_elements.Row(node);
    bool accepted = false;
    double scale = 1.0;
    for (int attempt = 0; attempt <= kMaxHalvings; ++attempt, scale *= 0.5) {
      draft.set_node(node, original + scale * displacement);
      if (AllValid(draft, adjacent)) {
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      draft.set_node(node, original);
      ++stats.kept;
    } else if (scale == 1.0) {
      ++stats.moved;
    } else {
      ++stats.shortened;
    }
  }
  return stats;
}

}  // namespace getme::meshgen
