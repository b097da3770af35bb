#pragma once

#include <span>

#include "absl/status/status.h"
#include "getme/mesh/mesh.h"

namespace getme {

// Checks of how elements meet that MeshBuilder::Build makes once the node → element rows exist.
// Both situations are input errors a smoother cannot interpret: boundary detection counts the
// elements on each face, so a repeated element hides its outer faces from the boundary (and lets
// boundary nodes move), and a face of three or more elements means overlapping elements.

// INVALID_ARGUMENT naming the first element (insertion order) whose nodes, as a set, are those of
// an earlier element of the same type.
absl::Status CheckNoRepeatedElements(const Mesh& mesh);

// INVALID_ARGUMENT naming a face (its nodes, sorted, 3 or 4) that `element_uses` elements share,
// and the elements containing it.
absl::Status NonManifoldFaceError(const Mesh& mesh, std::span<const NodeId> face_nodes,
                                  std::int64_t element_uses);

}  // namespace getme
