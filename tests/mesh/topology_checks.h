#pragma once

#include "getme/mesh/mesh.h"
#include "mesh_spec.h"

namespace getme::mesh_test {

// Compares every topology query of `mesh` (built from `spec`) with the brute-force reference:
// node→elements, element neighbours, boundary flags and face count, blocks.
void ExpectTopologyMatchesReference(const Mesh& mesh, const MeshSpec& spec);

}  // namespace getme::mesh_test
