#pragma once

// Brute-force topology of a MeshSpec, computed from the paper's face tables (F, Sec. 2.1, before
// eq. (1)) typed in here, independently of core/getme/mesh/mesh.cc and element_tables.h.

#include <cstdint>
#include <vector>

#include "mesh_spec.h"

namespace getme::mesh_test {

// Faces of one element type as local node lists (3 or 4 entries): the paper's F (Sec. 2.1),
// 0-based.
const std::vector<std::vector<int>>& ReferenceFaces(ElementType type);

struct ReferenceTopology {
  // Rows in the engine's canonical element order (by type: tet, hex, pyramid, prism; then id).
  std::vector<std::vector<std::int64_t>> node_elements;
  std::vector<std::vector<std::int64_t>> element_neighbours;  // without the element itself
  std::vector<bool> boundary;                                 // per node
  std::int64_t boundary_face_count = 0;
};

// Quadratic scans over all elements and faces; a face is identified by its node set, so a
// triangle never matches a quad even when its three nodes belong to the quad.
ReferenceTopology ComputeReferenceTopology(const MeshSpec& spec);

}  // namespace getme::mesh_test
