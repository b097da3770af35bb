#pragma once

#include <array>
#include <vector>

#include "absl/status/status.h"
#include "getme/meshgen/mesh_draft.h"

namespace getme::meshgen {

// Turns a draft holding one straight vessel segment (tetrahedra only, axis along z from z = 0 to
// z = segment_length, both end caps triangulated alike) into `copies` segments stacked end to end.
// Copy c is the segment moved up by c · segment_length; its bottom cap nodes are the previous
// copy's top cap nodes, so faces conform across the joins. Nodes and tetrahedra are appended copy
// by copy, and the copies' wall triangles are appended to `wall_triangles`.
// Why copies: gmsh's 3D Delaunay over a long vessel grows faster than linearly (measured: 4 s for
// 100k elements, 58 s for 1M, 2.3x per doubling), while copying one meshed segment is linear in
// time and memory. Fails with Internal if the caps do not match node for node.
absl::Status StackSegments(MeshDraft& draft, std::vector<std::array<NodeId, 3>>& wall_triangles,
                           double segment_length, int copies);

}  // namespace getme::meshgen
