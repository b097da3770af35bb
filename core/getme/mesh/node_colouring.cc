#include "getme/mesh/node_colouring.h"

#include <algorithm>

namespace getme {

NodeColouring ColourNodes(const Mesh& mesh, std::span<const std::uint8_t> selected) {
  const std::int64_t node_count = mesh.node_count();
  constexpr std::int32_t kNone = -1;
  std::vector<std::int32_t> colour(node_count, kNone);
  // taken_by[c] == node: colour c is used by a neighbour of `node` (a stamp, so the array is never
  // cleared between nodes).
  std::vector<NodeId> taken_by;
  std::int32_t colours = 0;
  for (std::int64_t i = 0; i < node_count; ++i) {
    const auto node = static_cast<NodeId>(i);
    if (!selected[i]) continue;
    for (ElementId e : mesh.node_elements(node)) {
      for (NodeId other : mesh.element_nodes(e)) {
        const std::int32_t c = colour[other];
        if (c != kNone) taken_by[c] = node;
      }
    }
    std::int32_t c = 0;
    while (c < colours && taken_by[c] == node) ++c;
    if (c == colours) {
      ++colours;
      taken_by.push_back(kNone);
    }
    colour[i] = c;
  }

  NodeColouring result;
  result.offsets.assign(colours + 1, 0);
  for (std::int64_t i = 0; i < node_count; ++i) {
    if (colour[i] != kNone) ++result.offsets[colour[i] + 1];
  }
  for (std::int32_t c = 0; c < colours; ++c) result.offsets[c + 1] += result.offsets[c];
  result.nodes.resize(result.offsets.back());
  std::vector<std::int64_t> next(result.offsets.begin(), result.offsets.end() - 1);
  for (std::int64_t i = 0; i < node_count; ++i) {  // ascending ids within each colour
    if (colour[i] != kNone) result.nodes[next[colour[i]]++] = static_cast<NodeId>(i);
  }
  return result;
}

CompressedRows ElementsByLastColour(const Mesh& mesh, const NodeColouring& colouring) {
  constexpr std::int32_t kNone = -1;
  std::vector<std::int32_t> colour(static_cast<std::size_t>(mesh.node_count()), kNone);
  for (int c = 0; c < colouring.colour_count(); ++c) {
    for (NodeId node : colouring.Colour(c)) colour[node] = c;
  }
  std::vector<std::int32_t> last(static_cast<std::size_t>(mesh.element_count()), kNone);
  for (ElementId e = 0; e < mesh.element_count(); ++e) {
    for (NodeId node : mesh.element_nodes(e)) last[e] = std::max(last[e], colour[node]);
  }
  return BuildRows(colouring.colour_count(), [&](auto&& emit) {
    for (ElementId e = 0; e < mesh.element_count(); ++e) {
      if (last[e] != kNone) emit(last[e], e);
    }
  });
}

}  // namespace getme
