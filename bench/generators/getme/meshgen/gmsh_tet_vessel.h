#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <string>
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

// What a gmsh run hands back: all nodes, the tetrahedra, and the triangles of some groups of
// surfaces (gmsh node tags throughout).
struct RawGmshMesh {
  std::vector<std::size_t> node_tags;
  std::vector<double> node_coords;
  std::vector<std::size_t> tet_nodes;                   // 4 tags per tetrahedron
  std::vector<std::vector<std::size_t>> surface_nodes;  // per group, 3 tags per triangle
};

// Runs `generate` in its own gmsh session (initialised without config files, always finalised),
// one caller at a time: gmsh keeps one global model. A gmsh exception becomes Internal, prefixed
// with `who`. Every gmsh call must happen inside `generate`.
absl::Status RunGmsh(const std::function<void(RawGmshMesh&)>& generate, RawGmshMesh& raw,
                     const std::string& who);

// Inside `generate`, after meshing: reads the nodes, the tetrahedra and, for each group of surface
// tags, the triangles of those surfaces into `raw`.
void ReadGmshMesh(const std::vector<std::vector<int>>& surface_groups, RawGmshMesh& raw);

// Adds the tetrahedra of `raw` to `draft` (nodes compacted to those the tetrahedra use, in
// ascending tag order; every tetrahedron oriented valid) and returns each surface group's
// triangles, each counter-clockwise seen from outside (its normal points away from its
// tetrahedron). Internal, prefixed with `who`, when a group is empty, a triangle is no
// tetrahedron's face, or a tetrahedron is degenerate.
absl::StatusOr<std::vector<std::vector<std::array<NodeId, 3>>>> ImportGmshTets(
    const RawGmshMesh& raw, MeshDraft& draft, const std::string& who);

}  // namespace getme::meshgen
