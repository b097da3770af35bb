#pragma once

#include <cstdint>

#include "absl/status/statusor.h"
#include "getme/mesh/mesh.h"

namespace getme::meshgen {

// How HybridBlock fills one unit cube of its grid.
enum class HybridCubeKind : std::uint8_t {
  kHexahedron,  // one hexahedron
  kPrismPair,   // two prisms split by the vertical plane through the (i,j)–(i+1,j+1) diagonal
  kCentredTets  // a centre node and one pyramid per cube face, apex at the centre; the pyramid
                // is split into two tetrahedra unless its base must stay a quad (see below)
};

// The z-layered layout of HybridBlock (needs nz >= 3):
//   k <  max(1, nz/4)                 hexahedron layers,
//   k >= nz − max(1, nz/4)            prism layers,
//   otherwise                         centred-tet layers, except hexahedron "islands" at
//                                     i % 3 == 1 and j % 3 == 1 in the centred-tet layers whose
//                                     offset from the first centred-tet layer is odd, leaving out
//                                     the topmost centred-tet layer (it touches the prisms).
// Prism cubes thus meet only prism cubes sideways and centred-tet cubes or the boundary through
// their triangulated top and bottom; hexahedra never touch a prism's triangulated face.
HybridCubeKind HybridCubeKindAt(int i, int j, int k, int nz);

// A structured nx × ny × nz grid of unit cubes filled per HybridCubeKindAt, so all four element
// types appear and all faces conform:
// - Quad faces that get split use one global rule: the diagonal through the face's smallest node
//   id. Grid ids grow with i, j, k, so this is the Kuhn diagonal, and a prism cube's top and bottom
//   diagonals both run through its (i, j) corner, which is its vertical splitting plane.
// - A centred-tet cube's face gives two tetrahedra when the cube across it is a centred-tet cube,
//   a prism cube meeting it with a triangulated face, or nothing (box boundary); it stays a
//   pyramid when it meets a quad face (a hexahedron or a prism cube's side).
// Interior grid nodes then move by up to `distortion` per axis and cube centres by up to
// `distortion`/2 (they are half a cube from the faces), keeping every element valid. Boundary
// nodes stay on the box. Deterministic for a given seed. Nodes: the (nx+1)(ny+1)(nz+1) grid nodes,
// then one centre node per centred-tet cube in cube order (i fastest, then j, then k).
absl::StatusOr<Mesh> HybridBlock(int nx, int ny, int nz, double distortion, std::uint64_t seed);

}  // namespace getme::meshgen
