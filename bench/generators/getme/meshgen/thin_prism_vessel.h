#pragma once

#include <cstdint>

#include "absl/status/statusor.h"
#include "getme/mesh/mesh.h"

namespace getme::meshgen {

// The hard case of the paper's Table 3 (the aorta): a tetrahedral vessel wrapped in a boundary
// layer of very thin prisms, whose initial q_min / q_mean the paper reports as 0.0413 / 0.3077.
struct ThinPrismVesselOptions {
  double radius = 1.0;
  // Along the centreline. Scale the mesh with the length: the defaults give about 6k tetrahedra
  // and 9k prisms (q_min 0.058, q_mean 0.37); length 42 (bend_angle 1.5) gives about 100k
  // elements with the same 60 % prism share. A finer mesh_size instead shifts the share towards
  // tetrahedra (volume grows as 1/h³, the wall only as 1/h²): 0.12 gives 51k tets + 37k prisms.
  double length = 6.0;
  // Target tetrahedron edge length handed to gmsh (Mesh.MeshSizeMin/Max).
  double mesh_size = 0.25;
  // Angle (radians, 0 ≤ angle < 2π) the centreline turns through: 0 is a straight cylinder,
  // otherwise a torus section with centreline radius length / bend_angle.
  double bend_angle = 0.0;
  int layers = 6;  // prism layers outside the wall
  // Every layer is this fraction of the mean wall triangle edge length thick.
  double layer_height_ratio = 0.01;
  // Straight vessels (bend_angle 0) only: gmsh meshes one segment of length / segments whose end
  // caps are triangulated alike, and the vessel is that segment copied end to end
  // (vessel_segments.h), so large vessels take linear time and memory. 1: one gmsh run.
  int segments = 1;
  std::uint64_t seed = 1;  // gmsh's Mesh.RandomSeed
  // Mark the outer wall (the outermost layer's nodes, or the tetrahedra's wall without layers)
  // fixed. With pinned end caps the cap prisms keep their 1% height whatever the smoother does,
  // so the thin-layer tests fix only the wall and smooth with fix_boundary off.
  bool fix_outer_wall = false;
};

// Options for a straight vessel of about `target_elements` elements with the given cross-section
// and layers (radius, mesh_size, layers, layer_height_ratio, seed and fix_outer_wall are taken from
// `base`): the length follows from the elements per unit length, about 15·r²/h³ tetrahedra plus
// 15·layers·r/h² prisms (fitted to gmsh's meshes; measured 8 % over at 10k, within 1 % from 100k
// up), and the vessel is cut into segments of at most kMaxSegmentElements. More elements make a
// longer vessel, not a finer one, so the prism share stays the same at every size: 60 % with the
// default mesh_size 0.25, 68 % with kPaperVesselMeshSize, whose initial q_mean 0.30 is also the
// paper's (its aorta: 69 % prisms, q_mean 0.3077).
inline constexpr double kPaperVesselMeshSize = 0.38;
inline constexpr std::int64_t kMaxSegmentElements = 100'000;
ThinPrismVesselOptions VesselOptionsForElements(std::int64_t target_elements,
                                                const ThinPrismVesselOptions& base = {});

// Meshes the vessel with tetrahedra through gmsh's C++ API (3D Delaunay, one thread, fixed random
// seed, so the same options give the same mesh), then extrudes `layers` layers of prisms outward
// from the lateral wall triangles (not the end caps) along area-weighted vertex normals.
// Layout: the tetrahedra's nodes come first (segment by segment), then one node per wall vertex per
// layer, layer by layer; tetrahedra come first, then prisms layer by layer (innermost first), in
// wall triangle order. Each prism's bottom (0,1,2) lies on the inner side, counter-clockwise seen
// from outside, its top (3,4,5) directly outward (3 above 0). No node is marked fixed: the engine's
// boundary detection fixes the outer prism surface and the end caps, the tet/prism interface stays
// free (unless fix_outer_wall). gmsh is global state: calls are serialised by a mutex, and gmsh
// must not be in use elsewhere.
absl::StatusOr<Mesh> ThinPrismVessel(const ThinPrismVesselOptions& options = {});

}  // namespace getme::meshgen
