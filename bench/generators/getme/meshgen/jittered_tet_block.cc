#include "getme/meshgen/jittered_tet_block.h"

#include <array>

#include "getme/meshgen/mesh_draft.h"
#include "getme/meshgen/node_jitter.h"
#include "getme/meshgen/structured_grid.h"

namespace getme::meshgen {
namespace {

// A Kuhn tetrahedron walks from corner (0,0,0) to (1,1,1) along the three axes in one of the six
// orders. The walk's corners, as CubeCorners indices, with the odd permutations' middle corners
// swapped so that det[p1−p0, p2−p0, p3−p0] > 0 for every tetrahedron.
constexpr std::array<std::array<int, 4>, 6> kKuhnTetrahedra = {{
    {0, 1, 2, 6},  // x, y, z
    {0, 5, 1, 6},  // x, z, y (odd)
    {0, 3, 7, 6},  // y, z, x
    {0, 2, 3, 6},  // y, x, z (odd)
    {0, 4, 5, 6},  // z, x, y
    {0, 7, 4, 6},  // z, y, x (odd)
}};

}  // namespace

absl::StatusOr<Mesh> JitteredTetBlock(int nx, int ny, int nz, double jitter, std::uint64_t seed) {
  if (absl::Status status = ValidateBlockArguments("JitteredTetBlock", nx, ny, nz, jitter);
      !status.ok()) {
    return status;
  }
  MeshDraft draft;
  const CubeGrid grid(draft, nx, ny, nz);
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const std::array<NodeId, 8> corner = grid.CubeCorners(i, j, k);
        for (const auto& tet : kKuhnTetrahedra) {
          draft.AddElement(ElementType::kTetrahedron,
                           {corner[tet[0]], corner[tet[1]], corner[tet[2]], corner[tet[3]]});
        }
      }
    }
  }
  JitterNodes(draft, grid.InteriorMoves(draft, jitter), seed);
  return std::move(draft).Build();
}

}  // namespace getme::meshgen
