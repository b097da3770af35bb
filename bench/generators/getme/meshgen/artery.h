#pragma once

#include <cstdint>
#include <vector>

#include "absl/status/statusor.h"
#include "getme/elements/vec3.h"
#include "getme/mesh/mesh.h"
#include "getme/meshgen/boundary_layers.h"

namespace getme::meshgen {

// A vascular CFD-like mesh (docs/thin-layers.md, "The artery"): a vessel whose centre line is a
// helix (curved in 3D, not planar), whose radius tapers from inlet to outlet and narrows in a
// stenosis half way, with side branches fused on (gmsh's OpenCASCADE kernel). gmsh fills the lumen
// with tetrahedra; then prism boundary layers are grown from the wall inward (into the lumen, the
// tetrahedra pushed back to make room) and outward, both with geometric growth away from the wall.
struct ArteryOptions {
  double radius = 1.0;  // at the inlet
  // Centre line c(t) = (a·cos(φt) − a, a·sin(φt), length·t), t ∈ [0, 1]: a helix of radius
  // a = helix_radius turning through φ = turn_angle (radians) about the z axis while it rises by
  // `length`. helix_radius 0 gives a straight centre line.
  double length = 8.0;
  double helix_radius = 2.0;
  double turn_angle = 3.8;
  // Radius r(t) = radius·(1 − taper·t)·(1 − stenosis·exp(−((t − ½)/0.08)²)).
  double taper = 0.3;
  double stenosis = 0.3;
  // Side branches (0–3), straight cones leaving the main vessel 60° from its downstream direction
  // at t = 0.3 and 0.72 (0.3 alone for one; 0.18, 0.38 and 0.72 for three), turned 0.5, −1.0
  // and 2.0 radians about the centre line from the direction away from the helix axis. Start radius
  // branch_radius_ratio·r(t), 15 % less at the branch's cap, branch_length from the main centre
  // line to the cap.
  int branches = 2;
  double branch_radius_ratio = 0.55;
  double branch_length = 3.0;
  // Radius of the fillet OpenCASCADE rounds the junction curves with, as a fraction of `radius`;
  // 0 leaves the junctions a sharp crease (the harder case for the layers and the smoother).
  double junction_fillet = 0.25;
  // Target tetrahedron edge length handed to gmsh (Mesh.MeshSizeMin/Max).
  double mesh_size = 0.3;
  int inward_layers = 6;
  int outward_layers = 2;
  // First layer height (the layers on either side of the wall) as a fraction of the mean wall
  // triangle edge length; each further layer is growth_ratio times thicker.
  double first_layer_ratio = 0.005;
  double growth_ratio = 1.2;
  std::uint64_t seed = 1;  // gmsh's Mesh.RandomSeed
};

// The generated mesh with what the tests and benchmarks measure against.
struct ArteryMesh {
  Mesh mesh;
  // The inlet (c(0)), the outlet (c(1)), then one per branch; normals point out of the vessel.
  std::vector<CapPlane> caps;
  double mean_wall_edge = 0.0;  // of gmsh's wall triangles, before the layers
  double first_layer_height = 0.0;
  BoundaryLayerReport layers;
};

// The cap planes of the vessel `options` describes (inlet, outlet, branches), from the geometry.
std::vector<CapPlane> ArteryCaps(const ArteryOptions& options);

// Deterministic for given options (gmsh one-threaded with a fixed seed). Layout: gmsh's tetrahedra
// and their nodes first, then the layers as in GrowBoundaryLayers. No node is marked fixed: with
// the default fix_boundary the engine fixes the outer wall (top of the outward layers) and the
// caps; without outward layers the wall itself. gmsh is global state (see RunGmsh).
absl::StatusOr<ArteryMesh> GenerateArtery(const ArteryOptions& options = {});
absl::StatusOr<Mesh> Artery(const ArteryOptions& options = {});

}  // namespace getme::meshgen
