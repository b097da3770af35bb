#pragma once

#include <array>
#include <span>

#include "absl/status/status.h"
#include "getme/meshgen/mesh_draft.h"

namespace getme::meshgen {

// Extrudes `layers` layers of prisms from a surface of triangles (each counter-clockwise seen
// from the side to extrude towards), every layer `layer_height` thick, along the area-weighted
// vertex normals. Layer l's nodes are p + l·layer_height·n̂(p); they are added layer by layer in
// order of first appearance in `triangles`, and the prisms layer by layer, in triangle order, each
// with the inner triangle as bottom (0,1,2) and the outer one as top (3,4,5), 3 above 0.
// Fails with Internal if a prism comes out invalid (a surface too curved for the height).
absl::Status ExtrudePrismLayers(MeshDraft& draft, std::span<const std::array<NodeId, 3>> triangles,
                                int layers, double layer_height);

// Mean length of the triangles' distinct edges.
double MeanEdgeLength(const MeshDraft& draft, std::span<const std::array<NodeId, 3>> triangles);

}  // namespace getme::meshgen
