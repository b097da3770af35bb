#pragma once

#include <cstdint>

#include "absl/status/statusor.h"
#include "getme/mesh/mesh.h"

namespace getme::meshgen {

// An nx × ny × nz block of unit hexahedra whose interior nodes are moved randomly by up to
// `distortion` (in units of the edge length) per axis; a move that would invalidate an adjacent
// hexahedron (Def. 2) is retried shorter (node_jitter.h). Boundary nodes stay on the box.
// Deterministic for a given seed. Nodes: (nx+1)(ny+1)(nz+1); elements: nx·ny·nz hexahedra.
absl::StatusOr<Mesh> DistortedHexBlock(int nx, int ny, int nz, double distortion,
                                       std::uint64_t seed);

}  // namespace getme::meshgen
