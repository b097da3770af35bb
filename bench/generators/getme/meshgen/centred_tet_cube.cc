#include "getme/meshgen/centred_tet_cube.h"

#include <algorithm>

namespace getme::meshgen {

void AddCentredTetCube(MeshDraft& draft, const std::array<NodeId, 8>& corners, NodeId centre,
                       std::uint8_t quad_faces) {
  for (int f = 0; f < static_cast<int>(kCubeFaces.size()); ++f) {
    std::array<NodeId, 4> base;
    for (int c = 0; c < 4; ++c) base[c] = corners[kCubeFaces[f].corners[c]];
    if (quad_faces & (1u << f)) {
      draft.AddElement(ElementType::kPyramid, {base[0], base[1], base[2], base[3], centre});
      continue;
    }
    const int m = static_cast<int>(std::min_element(base.begin(), base.end()) - base.begin());
    const NodeId a = base[m], b = base[(m + 1) % 4], c = base[(m + 2) % 4], d = base[(m + 3) % 4];
    draft.AddElement(ElementType::kTetrahedron, {a, b, c, centre});
    draft.AddElement(ElementType::kTetrahedron, {a, c, d, centre});
  }
}

}  // namespace getme::meshgen
