#pragma once

// What a run with kept layers reports (issue 15, item 3): the columns found and why they stop,
// and their layers' heights, lean and quality before and after. Plain data, so the CLI, the
// service and the wire share it.

#include <cstdint>

#include "getme/parallel/thread_pool.h"
#include "getme_surface/layer_heights.h"
#include "getme_surface/surface_slide.h"

namespace getme::surface {

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
  std::int64_t layer_nodes = 0;  // nodes above the walls, moved only with their column
  int layers = 0;
  std::int64_t conflicting_nodes = 0;  // where columns collide: left to the ordinary phases
  // Why the columns stop (layer_columns.h, ColumnEnds).
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

// The heights, lean and quality of `slide`'s columns in `mesh` as it is now.
LayerHeights MeasureKeptLayers(const Mesh& mesh, const SurfaceSlide& slide, ThreadPool& pool);

LayerReport MakeLayerReport(const SurfaceSlide& slide, const LayerHeights& before,
                            const LayerHeights& after);

}  // namespace getme::surface
