#pragma once

#include <array>
#include <vector>

#include "absl/status/statusor.h"
#include "getme/meshgen/mesh_draft.h"
#include "getme/meshgen/thin_prism_vessel.h"

namespace getme::meshgen {

// The tetrahedral core of ThinPrismVessel: gmsh's tetrahedra already added to `draft` (nodes
// compacted to those the tetrahedra use, in ascending gmsh tag order; every tetrahedron oriented
// valid), and the triangles of the lateral wall, each counter-clockwise seen from outside.
struct TetVessel {
  std::vector<std::array<NodeId, 3>> wall_triangles;
};

// Meshes the vessel described by `options` (radius, length, bend_angle, mesh_size, seed) with
// gmsh and appends it to `draft`. With segments > 1 (straight vessels only) it meshes just the
// first segment, length / segments long, with identical triangulations of its two end caps, for
// StackSegments to copy. Fails with Internal when gmsh reports an error.
// The length of one segment: options.length / options.segments.
double SegmentLength(const ThinPrismVesselOptions& options);

absl::StatusOr<TetVessel> MeshTetVessel(const ThinPrismVesselOptions& options, MeshDraft& draft);

}  // namespace getme::meshgen
