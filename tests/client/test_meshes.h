#pragma once

#include <cstdint>

#include "getme/mesh/mesh.h"

namespace getme::remote::testing {

// An n × n × n block of unit hexahedra whose interior nodes are moved deterministically by up to
// `distortion` edge lengths per axis (small enough to keep every element valid for distortion
// below 0.25). (n+1)^3 nodes.
Mesh DistortedHexBlock(int n, double distortion, std::uint64_t seed = 1);

}  // namespace getme::remote::testing
