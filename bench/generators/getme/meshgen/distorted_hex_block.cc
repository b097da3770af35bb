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
  grid.AddHexahedra(draft);
  JitterNodes(draft, grid.InteriorMoves(draft, distortion), seed);
  return std::move(draft).Build();
}

}  // namespace getme::meshgen
