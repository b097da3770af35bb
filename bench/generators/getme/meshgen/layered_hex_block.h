#pragma once

#include <cstdint>

#include "absl/status/statusor.h"
#include "getme/mesh/mesh.h"

namespace getme::meshgen {

// A hexahedral boundary-layer block (issue 15's layer tests): nx × ny × nz hexahedra on the wall
// z = 0 whose layer k (k = 0 at the wall) is first_height · growth^k thick, as a CFD mesher
// clusters cells toward a wall; x and y edges are 1. Interior nodes are first moved randomly by up
// to `distortion` edge lengths per axis on the unit grid (as DistortedHexBlock does), then z is
// mapped onto the layers piecewise linearly, so a node's move in z stays within the layers
// around it and the columns lean. Deterministic for a given seed.
absl::StatusOr<Mesh> LayeredHexBlock(int nx, int ny, int nz, double first_height, double growth,
                                     double distortion, std::uint64_t seed);

}  // namespace getme::meshgen
