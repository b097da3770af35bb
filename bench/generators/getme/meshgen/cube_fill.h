#pragma once

#include <cstdint>
#include <vector>

#include "absl/status/statusor.h"
#include "getme/mesh/mesh.h"

namespace getme::meshgen {

// How one unit cube of a CubeFillGrid is meshed.
enum class CubeFill : std::uint8_t {
  kEmpty,       // no elements: a hole, its faces towards filled cubes are boundary
  kHexahedron,  // one hexahedron
  kCentredTets  // a centre node and one pyramid per face (centred_tet_cube.h), split into two
                // tetrahedra except towards a hexahedron cube, where the pyramid stays
};

// The fill of every cube of an nx × ny × nz box of unit cubes, cube (i, j, k) spanning
// [i, i+1] × [j, j+1] × [k, k+1]. Cubes outside the box read as empty.
class CubeFillGrid {
 public:
  CubeFillGrid(int nx, int ny, int nz, CubeFill fill);

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int nz() const { return nz_; }
  bool Contains(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < nx_ && j < ny_ && k < nz_;
  }
  CubeFill at(int i, int j, int k) const {
    return Contains(i, j, k) ? fill_[Index(i, j, k)] : CubeFill::kEmpty;
  }
  void set(int i, int j, int k, CubeFill fill) { fill_[Index(i, j, k)] = fill; }

 private:
  std::int64_t Index(int i, int j, int k) const {
    return i + std::int64_t{nx_} * (j + std::int64_t{ny_} * k);
  }
  int nx_, ny_, nz_;
  std::vector<CubeFill> fill_;
};

struct CubeFillCounts {
  std::int64_t hexahedra = 0;
  std::int64_t pyramids = 0;
  std::int64_t tetrahedra = 0;
  std::int64_t nodes = 0;
  std::int64_t elements() const { return hexahedra + pyramids + tetrahedra; }
};

// What MeshCubeFill builds from the grid, counted without building it (cheap enough to search
// for a grid size that gives a wanted element count).
CubeFillCounts CountCubeFill(const CubeFillGrid& grid);

// Meshes every non-empty cube per its CubeFill; faces conform everywhere (a pyramid's quad base
// is a hexahedron's face, split faces share the smallest-id diagonal). Nodes at grid point
// (i, j, k) and cube centres at (i+½, j+½, k+½), in cube units; only grid points of non-empty
// cubes become nodes. Node ids grow layer by layer: the grid points of layer k (i fastest, then
// j), then the centres of the cube layer above it, so an element's nodes lie close together in
// memory whatever the size. Elements follow cube order (i fastest, then j, then k).
// Then every node not on the boundary (a grid point all of whose eight cubes are filled, or a
// centre) moves by up to `distortion` per axis, centres by half that (they are half a cube from
// the faces), keeping every element valid (node_jitter.h); boundary nodes, on the box and on
// holes' walls, stay put. Deterministic for a given seed.
absl::StatusOr<Mesh> MeshCubeFill(const CubeFillGrid& grid, double distortion, std::uint64_t seed);

}  // namespace getme::meshgen
