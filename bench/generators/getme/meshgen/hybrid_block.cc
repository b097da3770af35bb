#include "getme/meshgen/hybrid_block.h"

#include <algorithm>
#include <array>
#include <vector>

#include "absl/strings/str_cat.h"
#include "getme/meshgen/mesh_draft.h"
#include "getme/meshgen/node_jitter.h"
#include "getme/meshgen/structured_grid.h"

namespace getme::meshgen {
namespace {

// A cube face as CubeCorners indices, counter-clockwise seen from the cube's centre (so it is a
// valid pyramid base for an apex at the centre), and the step to the cube across it.
struct CubeFace {
  std::array<int, 4> corners;
  std::array<int, 3> step;
};
constexpr std::array<CubeFace, 6> kCubeFaces = {{
    {{0, 1, 2, 3}, {0, 0, -1}},  // bottom
    {{4, 7, 6, 5}, {0, 0, 1}},   // top
    {{0, 4, 5, 1}, {0, -1, 0}},  // front (y = j)
    {{1, 5, 6, 2}, {1, 0, 0}},   // right (x = i + 1)
    {{2, 6, 7, 3}, {0, 1, 0}},   // back  (y = j + 1)
    {{3, 7, 4, 0}, {-1, 0, 0}},  // left  (x = i)
}};

// The two prisms of a prism cube: bottom triangles counter-clockwise seen from above on either side
// of the (i,j)–(i+1,j+1) diagonal (corners 0–2 below, 4–6 above), tops directly above.
constexpr std::array<std::array<int, 6>, 2> kPrismPair = {{{0, 1, 2, 4, 5, 6}, {0, 2, 3, 4, 6, 7}}};

int HexLayers(int nz) { return std::max(1, nz / 4); }
int PrismLayers(int nz) { return std::max(1, nz / 4); }

// Whether a centred-tet cube's face must be split into two triangles rather than kept as a
// pyramid's quad base, given the cube across it (if the face is not on the box boundary).
bool FaceIsTriangulated(bool neighbour_inside, HybridCubeKind neighbour, const CubeFace& face) {
  if (!neighbour_inside) return true;
  switch (neighbour) {
    case HybridCubeKind::kCentredTets:
      return true;
    case HybridCubeKind::kPrismPair:
      return face.step[2] != 0;  // a prism cube's top and bottom are triangulated, its sides not
    case HybridCubeKind::kHexahedron:
      return false;
  }
  return false;
}

void AddCentredTetCube(MeshDraft& draft, const CubeGrid& grid, int i, int j, int k) {
  const std::array<NodeId, 8> corner = grid.CubeCorners(i, j, k);
  const NodeId centre = draft.AddNode(Vec3(i + 0.5, j + 0.5, k + 0.5));
  for (const CubeFace& face : kCubeFaces) {
    const int ni = i + face.step[0], nj = j + face.step[1], nk = k + face.step[2];
    const bool inside = grid.ContainsCube(ni, nj, nk);
    const HybridCubeKind neighbour =
        inside ? HybridCubeKindAt(ni, nj, nk, grid.nz()) : HybridCubeKind::kCentredTets;
    std::array<NodeId, 4> base;
    for (int c = 0; c < 4; ++c) base[c] = corner[face.corners[c]];
    if (!FaceIsTriangulated(inside, neighbour, face)) {
      draft.AddElement(ElementType::kPyramid, {base[0], base[1], base[2], base[3], centre});
      continue;
    }
    // The global diagonal rule: split through the face's smallest node id, so the cube across
    // the face (or the prism cube's triangles) use the same diagonal.
    const int m = static_cast<int>(std::min_element(base.begin(), base.end()) - base.begin());
    const NodeId a = base[m], b = base[(m + 1) % 4], c = base[(m + 2) % 4], d = base[(m + 3) % 4];
    draft.AddElement(ElementType::kTetrahedron, {a, b, c, centre});
    draft.AddElement(ElementType::kTetrahedron, {a, c, d, centre});
  }
}

}  // namespace

HybridCubeKind HybridCubeKindAt(int i, int j, int k, int nz) {
  const int first_tet_layer = HexLayers(nz);
  const int first_prism_layer = nz - PrismLayers(nz);
  if (k < first_tet_layer) return HybridCubeKind::kHexahedron;
  if (k >= first_prism_layer) return HybridCubeKind::kPrismPair;
  const bool island_layer = (k - first_tet_layer) % 2 == 1 && k < first_prism_layer - 1;
  if (island_layer && i % 3 == 1 && j % 3 == 1) return HybridCubeKind::kHexahedron;
  return HybridCubeKind::kCentredTets;
}

absl::StatusOr<Mesh> HybridBlock(int nx, int ny, int nz, double distortion, std::uint64_t seed) {
  if (absl::Status status = ValidateBlockArguments("HybridBlock", nx, ny, nz, distortion);
      !status.ok()) {
    return status;
  }
  if (nz < 3) {
    return absl::InvalidArgumentError(absl::StrCat(
        "HybridBlock: nz must be at least 3 (hexahedron, tetrahedron and prism layers), got ", nz));
  }
  MeshDraft draft;
  const CubeGrid grid(draft, nx, ny, nz);
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const std::array<NodeId, 8> corner = grid.CubeCorners(i, j, k);
        switch (HybridCubeKindAt(i, j, k, nz)) {
          case HybridCubeKind::kHexahedron:
            draft.AddElement(ElementType::kHexahedron, corner);
            break;
          case HybridCubeKind::kPrismPair:
            for (const auto& prism : kPrismPair) {
              draft.AddElement(ElementType::kPrism,
                               {corner[prism[0]], corner[prism[1]], corner[prism[2]],
                                corner[prism[3]], corner[prism[4]], corner[prism[5]]});
            }
            break;
          case HybridCubeKind::kCentredTets:
            AddCentredTetCube(draft, grid, i, j, k);
            break;
        }
      }
    }
  }
  std::vector<double> moves = grid.InteriorMoves(draft, distortion);
  std::fill(moves.begin() + grid.node_count(), moves.end(), 0.5 * distortion);
  JitterNodes(draft, moves, seed);
  return draft.Build();
}

}  // namespace getme::meshgen
