#pragma once

#include "getme/elements/element_tables.h"
#include "getme/elements/element_type.h"
#include "getme/mesh/mesh.h"

namespace getme {

// The position of `node` among an element's node ids (−1 if absent). Without a branch per id:
// the node-local steps (polish, untangling) look their node up in every element around it, and
// where it sits is as good as random, so an early-exit loop mispredicted its exit about once per
// element; on cub_wedge_like.vtk that was an eighth of a default run.
template <ElementType kType>
[[gnu::always_inline]] inline int LocalIndex(const NodeId* ids, NodeId node) {
  int local = -1;
  for (int k = 0; k < ElementTable<kType>::kNodes; ++k) local = ids[k] == node ? k : local;
  return local;
}

}  // namespace getme
