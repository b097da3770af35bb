#include "getme/meshgen/structured_grid.h"

#include <cmath>
#include <limits>

#include "absl/strings/str_cat.h"

namespace getme::meshgen {

CubeGrid::CubeGrid(MeshDraft& draft, int nx, int ny, int nz) : nx_(nx), ny_(ny), nz_(nz) {
  for (int k = 0; k <= nz; ++k) {
    for (int j = 0; j <= ny; ++j) {
      for (int i = 0; i <= nx; ++i) draft.AddNode(Vec3(i, j, k));
    }
  }
}

std::array<NodeId, 8> CubeGrid::CubeCorners(int i, int j, int k) const {
  return {
      Node(i, j, k),     Node(i + 1, j, k),     Node(i + 1, j + 1, k),     Node(i, j + 1, k),
      Node(i, j, k + 1), Node(i + 1, j, k + 1), Node(i + 1, j + 1, k + 1), Node(i, j + 1, k + 1)};
}

void CubeGrid::AddHexahedra(MeshDraft& draft) const {
  for (int k = 0; k < nz_; ++k) {
    for (int j = 0; j < ny_; ++j) {
      for (int i = 0; i < nx_; ++i)
        draft.AddElement(ElementType::kHexahedron, CubeCorners(i, j, k));
    }
  }
}

std::vector<double> CubeGrid::InteriorMoves(const MeshDraft& draft, double move) const {
  std::vector<double> moves(draft.node_count(), 0.0);
  for (int k = 1; k < nz_; ++k) {
    for (int j = 1; j < ny_; ++j) {
      for (int i = 1; i < nx_; ++i) moves[Node(i, j, k)] = move;
    }
  }
  return moves;
}

absl::Status ValidateBlockArguments(absl::string_view generator, int nx, int ny, int nz,
                                    double distortion) {
  if (nx < 1 || ny < 1 || nz < 1) {
    return absl::InvalidArgumentError(absl::StrCat(
        generator, ": cube counts must be at least 1, got nx=", nx, " ny=", ny, " nz=", nz));
  }
  const std::int64_t cubes = std::int64_t{nx} * ny * nz;
  const std::int64_t grid_nodes = (std::int64_t{nx} + 1) * (std::int64_t{ny} + 1) * (nz + 1);
  // Hybrid blocks add one centre node per cube and split a cube into up to 12 tetrahedra.
  constexpr std::int64_t kMaxElementsPerCube = 12;
  constexpr std::int64_t kLimit = std::numeric_limits<NodeId>::max();
  if (grid_nodes + cubes > kLimit || cubes * kMaxElementsPerCube > kLimit) {
    return absl::InvalidArgumentError(absl::StrCat(generator, ": ", nx, "x", ny, "x", nz,
                                                   " cubes exceed 2^31-1 nodes or elements"));
  }
  if (!std::isfinite(distortion) || distortion < 0.0) {
    return absl::InvalidArgumentError(
        absl::StrCat(generator, ": distortion must be finite and >= 0, got ", distortion));
  }
  return absl::OkStatus();
}

}  // namespace getme::meshgen
