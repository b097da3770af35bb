#pragma once

#include <cstdint>

#include "absl/status/statusor.h"
#include "getme/mesh/mesh.h"

namespace getme::meshgen {

// An nx × ny × nz block of unit cubes, each split into the 6 Kuhn (Freudenthal) tetrahedra around
// its (i,j,k)–(i+1,j+1,k+1) diagonal, so neighbouring cubes split their shared face along the same
// diagonal. Interior nodes are jittered by up to `jitter` per axis, keeping every tetrahedron valid
// (node_jitter.h). Deterministic for a given seed. Elements: 6·nx·ny·nz tetrahedra.
absl::StatusOr<Mesh> JitteredTetBlock(int nx, int ny, int nz, double jitter, std::uint64_t seed);

}  // namespace getme::meshgen
