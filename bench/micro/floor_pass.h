#pragma once

#include <vector>

#include "getme/mesh/mesh.h"

namespace getme::bench {

// Per-node sums the floor pass scatters into, allocated once.
struct NodeSums {
  std::vector<double> x, y, z;
};

// The memory-traffic floor of a simultaneous iteration (issue 5): every element gathers its
// nodes' coordinates through its connectivity and adds them back into per-node sums, single
// thread, with no arithmetic beyond the additions. Whatever a simultaneous iteration does, it at
// least reads every element's nodes and writes every node.
void GatherScatterPass(const Mesh& mesh, NodeSums& sums);

}  // namespace getme::bench
