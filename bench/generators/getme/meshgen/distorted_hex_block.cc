#include "getme/meshgen/distorted_hex_block.h"

#include "getme/meshgen/mesh_draft.h"
#include "getme/meshgen/node_jitter.h"
#include "getme/meshgen/structured_grid.h"

namespace getme::meshgen {

absl::StatusOr<Mesh> DistortedHexBlock(int nx, int ny, int nz, double distortion,
                                       std::uint64_t seed) {
  if (absl::Status status = ValidateBlockArguments("DistortedHexBlock", nx, ny, nz, distortion);
      !status.ok()) {
    return status;
  }
  MeshDraft draft;
  const CubeGrid grid(draft, nx, ny, nz);
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        draft.AddElement(ElementType::kHexahedron, grid.CubeCorners(i, j, k));
      }
    }
  }
  JitterNodes(draft, grid.InteriorMoves(draft, distortion), seed);
  return std::move(draft).Build();
}

}  // namespace getme::meshgen
