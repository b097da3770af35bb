#include "getme/meshgen/hybrid_block.h"

#include <algorithm>
#include <array>
#include <vector>

#include "absl/strings/str_cat.h"
#include "getme/meshgen/centred_tet_cube.h"
#include "getme/meshgen/mesh_draft.h"
#include "getme/meshgen/node_jitter.h"
#include "getme/meshgen/structured_grid.h"

namespace getme::meshgen {
namespace {

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

void AddHybridCentredTetCube(MeshDraft& draft, const CubeGrid& grid, int i, int j, int k) {
  const NodeId centre = draft.AddNode(Vec3(i + 0.5, j + 0.5, k + 0.5));
  std::uint8_t quad_faces = 0;
  for (int f = 0; f < static_cast<int>(kCubeFaces.size()); ++f) {
    const CubeFace& face = kCubeFaces[f];
    const int ni = i + face.step[0], nj = j + face.step[1], nk = k + face.step[2];
    const bool inside = grid.ContainsCube(ni, nj, nk);
    const HybridCubeKind neighbour =
        inside ? HybridCubeKindAt(ni, nj, nk, grid.nz()) : HybridCubeKind::kCentredTets;
    if (!FaceIsTriangulated(inside, neighbour, face)) quad_faces |= 1u << f;
  }
  AddCentredTetCube(draft, grid.CubeCorners(i, j, k), centre, quad_faces);
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
            AddHybridCentredTetCube(draft, grid, i, j, k);
            break;
        }
      }
    }
  }
  std::vector<double> moves = grid.InteriorMoves(draft, distortion);
  std::fill(moves.begin() + grid.node_count(), moves.end(), 0.5 * distortion);
  JitterNodes(draft, moves, seed);
  return std::move(draft).Build();
}

}  // namespace getme::meshgen
