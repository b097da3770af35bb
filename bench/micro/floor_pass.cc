#include "floor_pass.h"

#include <algorithm>

#include "getme/elements/element_tables.h"

namespace getme::bench {

void GatherScatterPass(const Mesh& mesh, NodeSums& sums) {
  const auto count = static_cast<std::size_t>(mesh.node_count());
  sums.x.assign(count, 0.0);
  sums.y.assign(count, 0.0);
  sums.z.assign(count, 0.0);
  const double* x = mesh.x().data();
  const double* y = mesh.y().data();
  const double* z = mesh.z().data();
  for (ElementType type : kAllElementTypes) {
    DispatchElementType(type, [&]<ElementType kType>() {
      constexpr int kNodes = ElementTable<kType>::kNodes;
      const std::vector<NodeId>& nodes = mesh.block(kType).nodes;
      for (std::size_t i = 0; i < nodes.size(); i += kNodes) {
        double gathered[3][kNodes];
        for (int k = 0; k < kNodes; ++k) {
          gathered[0][k] = x[nodes[i + k]];
          gathered[1][k] = y[nodes[i + k]];
          gathered[2][k] = z[nodes[i + k]];
        }
        for (int k = 0; k < kNodes; ++k) {
          sums.x[nodes[i + k]] += gathered[0][k];
          sums.y[nodes[i + k]] += gathered[1][k];
          sums.z[nodes[i + k]] += gathered[2][k];
        }
      }
    });
  }
}

}  // namespace getme::bench
