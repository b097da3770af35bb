#include "getme/meshgen/cube_fill.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <utility>

#include "absl/strings/str_cat.h"
#include "getme/meshgen/centred_tet_cube.h"
#include "getme/meshgen/mesh_draft.h"
#include "getme/meshgen/node_jitter.h"

namespace getme::meshgen {
namespace {

// The eight cubes around grid point (i, j, k): which of them are filled.
struct PointSurroundings {
  bool any_filled = false;
  bool any_empty = false;
};

PointSurroundings Surroundings(const CubeFillGrid& grid, int i, int j, int k) {
  PointSurroundings around;
  for (int dk = -1; dk <= 0; ++dk) {
    for (int dj = -1; dj <= 0; ++dj) {
      for (int di = -1; di <= 0; ++di) {
        const bool filled = grid.at(i + di, j + dj, k + dk) != CubeFill::kEmpty;
        around.any_filled |= filled;
        around.any_empty |= !filled;
      }
    }
  }
  return around;
}

// Faces of a centred-tet cube that meet a hexahedron, as bits over kCubeFaces.
std::uint8_t QuadFaces(const CubeFillGrid& grid, int i, int j, int k) {
  std::uint8_t quad_faces = 0;
  for (int f = 0; f < static_cast<int>(kCubeFaces.size()); ++f) {
    const std::array<int, 3>& step = kCubeFaces[f].step;
    if (grid.at(i + step[0], j + step[1], k + step[2]) == CubeFill::kHexahedron) {
      quad_faces |= 1u << f;
    }
  }
  return quad_faces;
}

// Builds the mesh one cube layer at a time, keeping the node ids of only two grid layers and one
// cube layer of centres.
class LayerMesher {
 public:
  LayerMesher(const CubeFillGrid& grid, double distortion, MeshDraft& draft,
              std::vector<double>& max_move)
      : grid_(grid),
        distortion_(distortion),
        draft_(draft),
        max_move_(max_move),
        below_(LayerSize()),
        above_(LayerSize()),
        centres_(static_cast<std::size_t>(grid.nx()) * static_cast<std::size_t>(grid.ny())) {}

  void Run() {
    AddGridLayer(0, below_);
    for (int k = 0; k < grid_.nz(); ++k) {
      AddCentres(k);
      AddGridLayer(k + 1, above_);
      AddCubeLayer(k);
      std::swap(below_, above_);
    }
  }

 private:
  std::size_t LayerSize() const {
    return static_cast<std::size_t>(grid_.nx() + 1) * static_cast<std::size_t>(grid_.ny() + 1);
  }
  std::size_t PointIndex(int i, int j) const {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(grid_.nx() + 1) * j;
  }
  std::size_t CubeIndex(int i, int j) const {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(grid_.nx()) * j;
  }

  void AddGridLayer(int k, std::vector<NodeId>& ids) {
    for (int j = 0; j <= grid_.ny(); ++j) {
      for (int i = 0; i <= grid_.nx(); ++i) {
        const PointSurroundings around = Surroundings(grid_, i, j, k);
        if (!around.any_filled) continue;
        ids[PointIndex(i, j)] = draft_.AddNode(Vec3(i, j, k));
        max_move_.push_back(around.any_empty ? 0.0 : distortion_);
      }
    }
  }

  void AddCentres(int k) {
    for (int j = 0; j < grid_.ny(); ++j) {
      for (int i = 0; i < grid_.nx(); ++i) {
        if (grid_.at(i, j, k) != CubeFill::kCentredTets) continue;
        centres_[CubeIndex(i, j)] = draft_.AddNode(Vec3(i + 0.5, j + 0.5, k + 0.5));
        max_move_.push_back(0.5 * distortion_);
      }
    }
  }

  void AddCubeLayer(int k) {
    for (int j = 0; j < grid_.ny(); ++j) {
      for (int i = 0; i < grid_.nx(); ++i) {
        const CubeFill fill = grid_.at(i, j, k);
        if (fill == CubeFill::kEmpty) continue;
        // CubeGrid::CubeCorners order: bottom counter-clockwise seen from above, then the top.
        const std::array<NodeId, 8> corners = {
            below_[PointIndex(i, j)],         below_[PointIndex(i + 1, j)],
            below_[PointIndex(i + 1, j + 1)], below_[PointIndex(i, j + 1)],
            above_[PointIndex(i, j)],         above_[PointIndex(i + 1, j)],
            above_[PointIndex(i + 1, j + 1)], above_[PointIndex(i, j + 1)]};
        if (fill == CubeFill::kHexahedron) {
          draft_.AddElement(ElementType::kHexahedron, corners);
        } else {
          AddCentredTetCube(draft_, corners, centres_[CubeIndex(i, j)], QuadFaces(grid_, i, j, k));
        }
      }
    }
  }

  const CubeFillGrid& grid_;
  const double distortion_;
  MeshDraft& draft_;
  std::vector<double>& max_move_;
  std::vector<NodeId> below_, above_;  // node ids of the grid points of layers k and k + 1
  std::vector<NodeId> centres_;        // node ids of the centres of cube layer k
};

}  // namespace

CubeFillGrid::CubeFillGrid(int nx, int ny, int nz, CubeFill fill)
    : nx_(nx),
      ny_(ny),
      nz_(nz),
      fill_(static_cast<std::size_t>(std::max(nx, 0)) * std::max(ny, 0) * std::max(nz, 0), fill) {}

CubeFillCounts CountCubeFill(const CubeFillGrid& grid) {
  CubeFillCounts counts;
  for (int k = 0; k <= grid.nz(); ++k) {
    for (int j = 0; j <= grid.ny(); ++j) {
      for (int i = 0; i <= grid.nx(); ++i) {
        if (Surroundings(grid, i, j, k).any_filled) ++counts.nodes;
        const CubeFill fill = grid.at(i, j, k);
        if (fill == CubeFill::kHexahedron) ++counts.hexahedra;
        if (fill != CubeFill::kCentredTets) continue;
        ++counts.nodes;
        const int pyramids = std::popcount(QuadFaces(grid, i, j, k));
        counts.pyramids += pyramids;
        counts.tetrahedra += 2 * (static_cast<int>(kCubeFaces.size()) - pyramids);
      }
    }
  }
  return counts;
}

absl::StatusOr<Mesh> MeshCubeFill(const CubeFillGrid& grid, double distortion, std::uint64_t seed) {
  if (grid.nx() < 1 || grid.ny() < 1 || grid.nz() < 1) {
    return absl::InvalidArgumentError(absl::StrCat("MeshCubeFill: the grid must have at least one ",
                                                   "cube per axis, got ", grid.nx(), "x", grid.ny(),
                                                   "x", grid.nz()));
  }
  if (!std::isfinite(distortion) || distortion < 0.0) {
    return absl::InvalidArgumentError(
        absl::StrCat("MeshCubeFill: distortion must be finite and >= 0, got ", distortion));
  }
  const CubeFillCounts counts = CountCubeFill(grid);
  if (counts.elements() == 0) {
    return absl::InvalidArgumentError("MeshCubeFill: every cube is empty");
  }
  constexpr std::int64_t kLimit = std::numeric_limits<NodeId>::max();
  if (counts.nodes > kLimit || counts.elements() > kLimit) {
    return absl::InvalidArgumentError(absl::StrCat("MeshCubeFill: ", counts.nodes, " nodes and ",
                                                   counts.elements(), " elements exceed 2^31-1"));
  }
  MeshDraft draft;
  draft.Reserve(counts.nodes, counts.elements(),
                8 * counts.hexahedra + 5 * counts.pyramids + 4 * counts.tetrahedra);
  std::vector<double> max_move;
  max_move.reserve(counts.nodes);
  LayerMesher(grid, distortion, draft, max_move).Run();
  JitterNodes(draft, max_move, seed);
  return std::move(draft).Build();
}

}  // namespace getme::meshgen
