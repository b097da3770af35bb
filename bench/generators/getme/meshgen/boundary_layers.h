#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "absl/status/statusor.h"
#include "getme/elements/vec3.h"
#include "getme/meshgen/mesh_draft.h"

namespace getme::meshgen {

// A planar end cap (inflow or outflow opening) of a vessel: a point on it and its unit normal,
// pointing out of the vessel.
struct CapPlane {
  Vec3 centre;
  Vec3 normal;
  double radius = 0.0;  // of the opening, for checks only
};

// Prism layers grown from a vessel wall in both directions, as in a CFD boundary-layer mesh.
// Layer thicknesses grow geometrically away from the wall: the two layers touching the wall are
// `first_layer_height` thick, the k-th layer from the wall (k = 1, 2, ...) first·growth^(k−1),
// on both sides.
struct BoundaryLayerOptions {
  int inward_layers = 6;   // prisms inside the lumen, between the wall and the tetrahedral core
  int outward_layers = 2;  // prisms outside the wall
  double first_layer_height = 0.0;
  double growth_ratio = 1.2;
  // Jacobi sweeps that average each wall vertex normal with its neighbours' (after the
  // area-weighted start), so that layers at creases (branch junctions) and where the radius
  // changes fan out smoothly instead of crossing.
  int normal_smoothing_iterations = 5;
  // Jacobi sweeps spreading the inward push of the wall into the tetrahedra: each interior node
  // moves by the mean move of its neighbours, cap nodes stay in their cap plane.
  int displacement_iterations = 10;
  // Rounds of local thinning: a wall vertex whose prisms or tetrahedra come out invalid has its
  // stack (inward or outward, whichever is invalid) halved, and everything is checked again.
  int max_shrink_rounds = 30;
};

struct BoundaryLayerReport {
  std::int64_t wall_vertices = 0;
  // Wall vertices whose inward / outward stack had to be thinned, and the thinnest scale used
  // (1: every stack as requested).
  std::int64_t thinned_inward = 0;
  std::int64_t thinned_outward = 0;
  double min_inward_scale = 1.0;
  double min_outward_scale = 1.0;
  int shrink_rounds = 0;
};

// `draft` holds tetrahedra only (the vessel's lumen); `wall` is their wall surface, each triangle
// counter-clockwise seen from outside; `caps[c]` are the tetrahedra's triangles on the plane
// `planes[c]`. Pushes the wall inward by the inward stack's thickness (the tetrahedra's wall nodes
// move along the smoothed vertex normals, the push fades into the interior, cap nodes slide in
// their plane), then fills the gap with `inward_layers` prisms and adds `outward_layers` prisms
// outside the original wall. Wall vertices on a cap's rim move in the cap plane, so the layers'
// side faces there lie on the cap. Layout: the tetrahedra's nodes (moved) first, then per layer
// one node per wall vertex (first appearance in `wall`), inward layers from the core out to the
// original wall, then the outward layers; prisms layer by layer in the same order, in `wall`
// order. Each prism's bottom (0,1,2) lies on the inner side, counter-clockwise seen from outside,
// 3 above 0 (the ThinPrismVessel order). Internal if some element stays invalid after
// max_shrink_rounds.
absl::StatusOr<BoundaryLayerReport> GrowBoundaryLayers(
    MeshDraft& draft, std::span<const std::array<NodeId, 3>> wall,
    std::span<const std::vector<std::array<NodeId, 3>>> caps, std::span<const CapPlane> planes,
    const BoundaryLayerOptions& options);

// Distance from the wall of layer boundary k (0 at the wall): first·(growth^k − 1)/(growth − 1).
double LayerOffset(double first_layer_height, double growth_ratio, int k);

}  // namespace getme::meshgen
