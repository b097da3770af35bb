#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "getme/elements/element_type.h"
#include "getme/mesh/mesh_quality.h"
#include "getme/smoothing/smoother.h"
#include "getme/smoothing/smoothing_params.h"

namespace getme::events {

// What a finished smoothing run reports, in text (summary table) or JSON (result line). Plain
// data, so the gRPC client can fill it from the wire.
// The input's boundary surface as `--boundary slide` saw it (surface/, docs/boundary.md).
struct BoundarySurfaceCounts {
  std::int64_t feature_edges = 0;
  std::int64_t feature_curves = 0;
  std::int64_t corners = 0;
};

// The boundary-layer columns as `--keep-layers` found and kept them (surface/layer_columns.h):
// their layers' heights (distances from the wall) and quality before and after.
struct LayerState {
  double first_min = 0.0;  // first-layer height over the columns
  double first_mean = 0.0;
  double first_max = 0.0;
  double mean_lean_degrees = 0.0;  // column edges from the wall normal
  double q_min = 0.0;              // over the columns' elements
  double q_mean = 0.0;
};

struct LayerReport {
  std::int64_t columns = 0;  // wall faces a column grows from
  std::int64_t column_elements = 0;
  std::int64_t layer_nodes = 0;  // nodes held at their wall distance
  int layers = 0;
  std::int64_t conflicting_nodes = 0;  // where columns collide: left free
  // Why the columns stop: at a tetrahedron, a pyramid, a prism's side, an element no longer
  // thinner than wide, another column's element, the boundary.
  std::int64_t ends_tetrahedron = 0;
  std::int64_t ends_pyramid = 0;
  std::int64_t ends_prism_side = 0;
  std::int64_t ends_isotropic = 0;
  std::int64_t ends_taken = 0;
  std::int64_t ends_boundary = 0;
  LayerState before;
  LayerState after;
  double max_height_change = 0.0;  // the largest |after / before − 1| of one layer at one node
};

struct SmoothReport {
  std::string input;
  std::string output;
  Method method = Method::kGetme;
  std::int64_t nodes = 0;
  std::array<std::int64_t, kElementTypeCount> elements_by_type{};
  std::int64_t passthrough_cells = 0;
  SmoothingResult result;
  std::string boundary = "fixed";                         // fixed, free or slide
  std::optional<BoundarySurfaceCounts> boundary_surface;  // with --boundary slide only
  std::optional<LayerReport> layers;                      // with --keep-layers only
};

// What `getme quality` reports.
struct QualityReport {
  std::string input;
  std::int64_t nodes = 0;
  std::int64_t passthrough_cells = 0;
  MeshQuality quality;
  // The file's cell index of each entry of quality.first_invalid (element ids count volume
  // cells only, so they differ from the cell numbers a viewer shows when surface cells exist).
  std::vector<std::int64_t> first_invalid_cells;
};

}  // namespace getme::events
