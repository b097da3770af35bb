#pragma once

// What --keep-layers reports and keeps (issue 15, item 3): the layer heights of the boundary-layer
// columns (layer_columns.h), each a difference of distances from the input's walls
// (wall_distance.h), and how far the column edges lean from the wall's normal.

#include <cstdint>
#include <span>
#include <vector>

#include "getme/mesh/mesh.h"
#include "getme/smoothing/kept_layers.h"
#include "getme_surface/layer_columns.h"
#include "getme_surface/wall_distance.h"

namespace getme::surface {

struct LayerHeights {
  std::int64_t columns = 0;  // wall nodes with a first-layer node above them
  int layers = 0;
  // The first layer's height over those columns.
  double first_min = 0.0;
  double first_mean = 0.0;
  double first_max = 0.0;
  // The mean angle, in degrees, between a column edge and the wall's normal at the column's wall
  // node (area-weighted over its wall faces as they are now): 0 for straight columns on the
  // normal, the orthogonality a CFD user checks.
  double mean_lean_degrees = 0.0;
  // Mean ratio over the columns' elements (an invalid element counts as 0).
  double q_min = 0.0;
  double q_mean = 0.0;
  // Per node: the height of the layer below it, for nodes in a layer (LayerColumns::InLayer);
  // 0 elsewhere.
  std::vector<double> height;
};

// `quality` is the mesh's per-element mean ratio (ComputeElementQualities; negative: invalid).
// `kept` describes the same columns (kept_columns.h).
LayerHeights MeasureLayerHeights(const Mesh& mesh, const LayerColumns& columns,
                                 const WallDistance& walls, const KeptLayers& kept,
                                 std::span<const double> quality);

// The largest |after / before − 1| over the nodes in a layer whose height `before` is positive.
double MaxRelativeHeightChange(const LayerHeights& before, const LayerHeights& after);

}  // namespace getme::surface
