#include "getme/mesh/node_positions.h"

#include <algorithm>

namespace getme {

void NodePositions::CopyFrom(const Mesh& mesh) {
  x.assign(mesh.x().begin(), mesh.x().end());
  y.assign(mesh.y().begin(), mesh.y().end());
  z.assign(mesh.z().begin(), mesh.z().end());
}

void NodePositions::CopyTo(Mesh& mesh) const {
  std::copy(x.begin(), x.end(), mesh.x().begin());
  std::copy(y.begin(), y.end(), mesh.y().begin());
  std::copy(z.begin(), z.end(), mesh.z().begin());
}

}  // namespace getme
