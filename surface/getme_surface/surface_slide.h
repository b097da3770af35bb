#pragma once

// The engine's BoundarySlide (core/getme/smoothing/boundary_slide.h) on the input's own surface:
// surface and feature nodes slide, corners stay, and a moved node goes back to the nearest point
// of its group's faces or its feature curve in the input (boundary_surface.h,
// surface_projector.h). Built once from the input mesh, before smoothing.
//
// Boundary-layer columns (layer_columns.h) are found in any case, because a boundary node of a
// column (a wall node, or a layer node on an end cap) must not slide alone: a wall node that
// slides under a 0.5 %-thick layer shears it (docs/boundary.md measures it). So without
// keep_layers such nodes stay where they are, and with it the engine moves them only with their
// whole column (kept_layers.h), which this class describes.

#include <memory>
#include <span>

#include "absl/status/statusor.h"
#include "getme/smoothing/boundary_slide.h"
#include "getme_surface/boundary_surface.h"
#include "getme_surface/kept_columns.h"
#include "getme_surface/layer_columns.h"
#include "getme_surface/node_triangles.h"
#include "getme_surface/surface_projector.h"
#include "getme_surface/wall_distance.h"

namespace getme::surface {

// How far, relative to it, a moved column node's wall distance may be from its input distance.
inline constexpr double kWallDistanceTolerance = 1e-3;

struct SlideOptions {
  std::span<const GroupedFace> groups;  // surface groups of boundary faces (boundary_surface.h)
  bool skip_interior_groups = false;    // ExtractBoundarySurface's: a file's interfaces
  double feature_angle_degrees = kDefaultFeatureAngleDegrees;
  bool slide_boundary = true;  // SmoothingParams::slide_boundary
  bool keep_layers = false;    // SmoothingParams::keep_layers: describe the columns to keep
};

class SurfaceSlide final : public BoundarySlide {
 public:
  static absl::StatusOr<std::unique_ptr<SurfaceSlide>> Build(const Mesh& mesh,
                                                             const SlideOptions& options = {});

  bool Slides(NodeId node) const override;
  Vec3 Project(NodeId node, const Vec3& point, const Vec3* near = nullptr) const override;
  double DistanceToSurface(NodeId node, const Vec3& point) const override;
  // From the node's own boundary faces (or its two curve neighbours) at their current corners,
  // which the smoothers keep on the surface: the plane of their summed area vectors, or the
  // chord between the neighbours. No nearest-point query (each costs about 0.7 µs, and the
  // polish asks for a tangent space at every step of a sliding node). Falls back to
  // BoundarySlide's projections where the faces give no direction.
  int TangentSpace(const Mesh& mesh, NodeId node, std::array<Vec3, 2>& basis) const override;
  const KeptLayers* kept_layers() const override { return options_.keep_layers ? &kept_ : nullptr; }
  // The point of the ray at the node's input wall distance, the distance along it corrected by
  // nearest-point queries on the input's walls (AlongToWallDistance); a boundary node's ray is
  // first turned into its surface. nullopt unless the point found is within
  // kWallDistanceTolerance of the distance wanted (near a crease or a narrow gap between walls,
  // where the nearest wall point jumps).
  std::optional<Vec3> OnColumn(std::int64_t index, const Vec3& from,
                               const Vec3& direction) const override;

  const BoundarySurface& surface() const { return surface_; }
  // The boundary-layer columns and their walls as the input had them.
  const LayerColumns& layers() const { return layers_; }
  // With keep_layers only: the walls and the columns as the engine keeps them.
  const WallDistance& walls() const { return *walls_; }
  const KeptLayers& columns() const { return kept_; }
  const NodeTriangles& node_triangles() const { return node_triangles_; }

 private:
  SurfaceSlide(const SlideOptions& options, BoundarySurface surface, SurfaceProjector projector,
               LayerColumns layers, std::unique_ptr<WallDistance> walls)
      : options_{{},
                 options.skip_interior_groups,
                 options.feature_angle_degrees,
                 options.slide_boundary,
                 options.keep_layers},  // the groups are copied

        surface_(std::move(surface)),
        projector_(std::move(projector)),
        layers_(std::move(layers)),
        walls_(std::move(walls)) {}

  void IndexNeighbourhoods(std::int64_t node_count);
  void ListNodeTriangles(const Mesh& mesh);

  SlideOptions options_;
  BoundarySurface surface_;
  SurfaceProjector projector_;
  LayerColumns layers_;
  std::unique_ptr<WallDistance> walls_;
  KeptLayers kept_;
  std::vector<double> wall_distance_;  // per kept column node: its input distance from the wall
  // Per node (CSR): the boundary faces of a surface node (indices into surface_.faces), the two
  // neighbours along its curve of a feature node; empty for other nodes.
  std::vector<std::int64_t> neighbourhood_offsets_;
  std::vector<std::int64_t> neighbourhood_;
  // The sliding surface nodes' own triangle lists, which answer most of Project()'s queries
  // before the grid is asked.
  NodeTriangles node_triangles_;
};

}  // namespace getme::surface
