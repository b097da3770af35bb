#pragma once

#include <cstdint>

#include "getme/mesh/mesh.h"

namespace getme::mesh_test {

// The same mesh with its nodes and its elements numbered in a random order (seeded), as a
// mesher's file may number them: neighbours are no longer near each other in either numbering.
// Fixed flags move with their nodes. Fails the test if the copy does not build.
Mesh Shuffled(const Mesh& mesh, std::uint64_t seed);

}  // namespace getme::mesh_test
