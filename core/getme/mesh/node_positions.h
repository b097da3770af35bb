#pragma once

#include <vector>

#include "getme/mesh/mesh.h"

namespace getme {

// Node coordinates of a whole mesh, structure of arrays like Mesh's own: a phase keeps the best
// state it has seen in one, to hand it on instead of merely the last state.
struct NodePositions {
  std::vector<double> x, y, z;

  void CopyFrom(const Mesh& mesh);
  void CopyTo(Mesh& mesh) const;
};

}  // namespace getme
