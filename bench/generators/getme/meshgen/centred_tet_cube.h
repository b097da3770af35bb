#pragma once

#include <array>
#include <cstdint>

#include "getme/meshgen/mesh_draft.h"

namespace getme::meshgen {

// A cube face as indices into the cube's corners (CubeGrid::CubeCorners order: bottom k
// counter-clockwise seen from above, then the top k + 1), counter-clockwise seen from the cube's
// centre so it is a valid pyramid base for an apex there, and the step to the cube across it.
struct CubeFace {
  std::array<int, 4> corners;
  std::array<int, 3> step;
};
inline constexpr std::array<CubeFace, 6> kCubeFaces = {{
    {{0, 1, 2, 3}, {0, 0, -1}},  // bottom
    {{4, 7, 6, 5}, {0, 0, 1}},   // top
    {{0, 4, 5, 1}, {0, -1, 0}},  // front (y = j)
    {{1, 5, 6, 2}, {1, 0, 0}},   // right (x = i + 1)
    {{2, 6, 7, 3}, {0, 1, 0}},   // back  (y = j + 1)
    {{3, 7, 4, 0}, {-1, 0, 0}},  // left  (x = i)
}};

// Fills a cube with one pyramid per face, apex at `centre` (a node inside the cube). Faces whose
// bit (1 << index into kCubeFaces) is set in `quad_faces` keep their pyramid, so they match a
// hexahedron or another quad face across; every other pyramid is split into two tetrahedra along
// the face diagonal through the face's smallest node id. That global rule makes split faces
// conform: the cube across a face sees the same four ids and picks the same diagonal, and when
// node ids grow with (k, j, i) it is the Kuhn diagonal. Elements come in kCubeFaces order.
void AddCentredTetCube(MeshDraft& draft, const std::array<NodeId, 8>& corners, NodeId centre,
                       std::uint8_t quad_faces);

}  // namespace getme::meshgen
