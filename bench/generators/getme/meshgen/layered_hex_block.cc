#include "getme/meshgen/layered_hex_block.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "absl/strings/str_cat.h"
#include "getme/meshgen/mesh_draft.h"
#include "getme/meshgen/node_jitter.h"
#include "getme/meshgen/structured_grid.h"

namespace getme::meshgen {

absl::StatusOr<Mesh> LayeredHexBlock(int nx, int ny, int nz, double first_height, double growth,
                                     double distortion, std::uint64_t seed) {
  if (absl::Status status = ValidateBlockArguments("LayeredHexBlock", nx, ny, nz, distortion);
      !status.ok()) {
    return status;
  }
  if (!(first_height > 0.0 && std::isfinite(first_height))) {
    return absl::InvalidArgumentError(
        absl::StrCat("LayeredHexBlock: first layer height must be positive, got ", first_height));
  }
  if (!(growth >= 1.0 && std::isfinite(growth))) {
    return absl::InvalidArgumentError(
        absl::StrCat("LayeredHexBlock: growth ratio must be at least 1, got ", growth));
  }
  MeshDraft draft;
  const CubeGrid grid(draft, nx, ny, nz);
  grid.AddHexahedra(draft);
  // The layers' tops: level[k] is the height of grid level k.
  std::vector<double> level(static_cast<std::size_t>(nz) + 1, 0.0);
  double height = first_height;
  for (int k = 1; k <= nz; ++k, height *= growth) level[k] = level[k - 1] + height;
  const std::int64_t per_level = (std::int64_t{nx} + 1) * (ny + 1);
  std::vector<double> moves = grid.InteriorMoves(draft, distortion);
  for (NodeId node = 0; node < draft.node_count(); ++node) {
    const auto k = static_cast<int>(node / per_level);
    Vec3 p = draft.node(node);
    p[2] = level[k];
    draft.set_node(node, p);
    // Moves in the layers' own size: the thinner of the two layers the node sits between.
    if (k > 0 && k < nz) moves[node] *= std::min(level[k] - level[k - 1], level[k + 1] - level[k]);
  }
  JitterNodes(draft, moves, seed);
  return std::move(draft).Build();
}

}  // namespace getme::meshgen
