#include "getme/mesh/node_neighbours.h"

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

#include "getme/elements/element_tables.h"
#include "getme/elements/vec3.h"

namespace getme {

CompressedRows BuildEdgeNeighbours(const Mesh& mesh) {
  std::vector<std::pair<NodeId, NodeId>> directed;
  for (ElementType type : kAllElementTypes) {
    DispatchElementType(type, [&]<ElementType kType>() {
      using Table = ElementTable<kType>;
      const ElementBlock& block = mesh.block(kType);
      for (std::size_t i = 0; i < block.elements.size(); ++i) {
        const NodeId* ids = block.nodes.data() + i * Table::kNodes;
        for (const auto& edge : Table::kEdges) {
          directed.emplace_back(ids[edge[0]], ids[edge[1]]);
          directed.emplace_back(ids[edge[1]], ids[edge[0]]);
        }
      }
    });
  }
  std::sort(directed.begin(), directed.end());
  directed.erase(std::unique(directed.begin(), directed.end()), directed.end());
  CompressedRows rows;
  rows.offsets.assign(mesh.node_count() + 1, 0);
  rows.items.reserve(directed.size());
  for (const auto& [from, to] : directed) {
    ++rows.offsets[from + 1];
    rows.items.push_back(to);
  }
  for (std::int64_t i = 0; i < mesh.node_count(); ++i) rows.offsets[i + 1] += rows.offsets[i];
  return rows;
}

double NearestNodeDistance2(const Mesh& mesh, NodeId node) {
  const Vec3 at(mesh.x()[node], mesh.y()[node], mesh.z()[node]);
  double nearest2 = std::numeric_limits<double>::infinity();
  for (ElementId e : mesh.node_elements(node)) {
    for (NodeId other : mesh.element_nodes(e)) {
      if (other == node) continue;
      nearest2 = std::min(
          nearest2, (Vec3(mesh.x()[other], mesh.y()[other], mesh.z()[other]) - at).squaredNorm());
    }
  }
  return nearest2;
}

}  // namespace getme
