#include "getme/meshgen/thin_prism_vessel.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "absl/strings/str_cat.h"
#include "getme/meshgen/gmsh_tet_vessel.h"
#include "getme/meshgen/mesh_draft.h"
#include "getme/meshgen/prism_layer_extrusion.h"
#include "getme/meshgen/vessel_segments.h"

namespace getme::meshgen {
namespace {

absl::Status ValidateOptions(const ThinPrismVesselOptions& options) {
  const auto positive = [](double value) { return std::isfinite(value) && value > 0.0; };
  if (!positive(options.radius) || !positive(options.length) || !positive(options.mesh_size)) {
    return absl::InvalidArgumentError(absl::StrCat(
        "ThinPrismVessel: radius, length and mesh_size must be finite and > 0, got radius=",
        options.radius, " length=", options.length, " mesh_size=", options.mesh_size));
  }
  if (!(options.bend_angle >= 0.0 && options.bend_angle < 2.0 * std::numbers::pi)) {
    return absl::InvalidArgumentError(
        absl::StrCat("ThinPrismVessel: bend_angle must be in [0, 2π), got ", options.bend_angle));
  }
  if (options.bend_angle > 0.0 && options.length / options.bend_angle <= options.radius) {
    return absl::InvalidArgumentError(absl::StrCat(
        "ThinPrismVessel: the bend's centreline radius length/bend_angle = ",
        options.length / options.bend_angle, " must exceed the vessel radius ", options.radius));
  }
  if (options.layers < 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("ThinPrismVessel: layers must be >= 0, got ", options.layers));
  }
  if (!positive(options.layer_height_ratio)) {
    return absl::InvalidArgumentError(
        absl::StrCat("ThinPrismVessel: layer_height_ratio must be finite and > 0, got ",
                     options.layer_height_ratio));
  }
  if (options.segments < 1) {
    return absl::InvalidArgumentError(
        absl::StrCat("ThinPrismVessel: segments must be >= 1, got ", options.segments));
  }
  if (options.segments > 1 && options.bend_angle != 0.0) {
    return absl::InvalidArgumentError(
        "ThinPrismVessel: segments > 1 needs a straight vessel (bend_angle 0)");
  }
  return absl::OkStatus();
}

}  // namespace

ThinPrismVesselOptions VesselOptionsForElements(std::int64_t target_elements,
                                                const ThinPrismVesselOptions& base) {
  ThinPrismVesselOptions options = base;
  const double r = base.radius, h = base.mesh_size;
  // Fitted to gmsh's Delaunay meshes of radius-1 cylinders with h = 0.12 and 0.25.
  const double per_length = 15.0 * r * r / (h * h * h) + 15.0 * base.layers * r / (h * h);
  options.bend_angle = 0.0;
  options.length = static_cast<double>(target_elements) / per_length;
  options.segments = static_cast<int>(
      std::max<std::int64_t>(1, (target_elements + kMaxSegmentElements - 1) / kMaxSegmentElements));
  return options;
}

absl::StatusOr<Mesh> ThinPrismVessel(const ThinPrismVesselOptions& options) {
  if (absl::Status status = ValidateOptions(options); !status.ok()) return status;
  MeshDraft draft;
  absl::StatusOr<TetVessel> vessel = MeshTetVessel(options, draft);
  if (!vessel.ok()) return vessel.status();
  const double layer_height =
      options.layer_height_ratio * MeanEdgeLength(draft, vessel->wall_triangles);
  if (absl::Status status =
          StackSegments(draft, vessel->wall_triangles, SegmentLength(options), options.segments);
      !status.ok()) {
    return status;
  }
  const std::int64_t tet_nodes = draft.node_count();
  if (absl::Status status =
          ExtrudePrismLayers(draft, vessel->wall_triangles, options.layers, layer_height);
      !status.ok()) {
    return status;
  }
  absl::StatusOr<Mesh> mesh = std::move(draft).Build();
  if (!mesh.ok() || !options.fix_outer_wall) return mesh;
  if (options.layers == 0) {
    for (const auto& triangle : vessel->wall_triangles) {
      for (NodeId node : triangle) mesh->set_fixed(node, true);
    }
  } else {
    // Layer nodes come layer by layer after the tetrahedra's: the last layer is the outer wall.
    const std::int64_t per_layer = (mesh->node_count() - tet_nodes) / options.layers;
    for (std::int64_t node = mesh->node_count() - per_layer; node < mesh->node_count(); ++node) {
      mesh->set_fixed(static_cast<NodeId>(node), true);
    }
  }
  return mesh;
}

}  // namespace getme::meshgen
