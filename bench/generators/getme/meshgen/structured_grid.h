#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/string_view.h"
#include "getme/meshgen/mesh_draft.h"

namespace getme::meshgen {

// The nodes of an nx × ny × nz grid of unit cubes, node (i, j, k) at (i, j, k). Node ids grow with
// i fastest, then j, then k, so among the corners of any cube face the smallest id is the corner
// with the smallest (i, j, k): the global "diagonal through the smallest id" rule that makes
// split quad faces conform is the Kuhn/Freudenthal diagonal.
class CubeGrid {
 public:
  // Adds the grid's nodes to the draft; they must be its first nodes (ids start at 0).
  CubeGrid(MeshDraft& draft, int nx, int ny, int nz);

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  int nz() const { return nz_; }
  std::int64_t node_count() const { return (std::int64_t{nx_} + 1) * (ny_ + 1) * (nz_ + 1); }
  NodeId Node(int i, int j, int k) const { return i + (nx_ + 1) * (j + (ny_ + 1) * k); }
  // The cube's corners in the hexahedron's paper order: bottom (k) counter-clockwise seen from
  // above, then the top (k + 1) in the same order.
  std::array<NodeId, 8> CubeCorners(int i, int j, int k) const;
  // One hexahedron per cube, in the cubes' (i fastest, then j, then k) order.
  void AddHexahedra(MeshDraft& draft) const;
  bool ContainsCube(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < nx_ && j < ny_ && k < nz_;
  }
  bool IsBoxBoundaryNode(int i, int j, int k) const {
    return i == 0 || j == 0 || k == 0 || i == nx_ || j == ny_ || k == nz_;
  }
  // Per node of the draft (size draft.node_count() at the time of the call): `move` for grid nodes
  // inside the box, 0 for grid nodes on its surface and for nodes added after the grid.
  std::vector<double> InteriorMoves(const MeshDraft& draft, double move) const;

 private:
  int nx_, ny_, nz_;
};

// Rejects non-positive cube counts, grids beyond 2^31−1 nodes and negative or non-finite
// distortions, naming the generator and the offending argument.
absl::Status ValidateBlockArguments(absl::string_view generator, int nx, int ny, int nz,
                                    double distortion);

}  // namespace getme::meshgen
