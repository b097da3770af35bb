#pragma once

// The kept layers' own phase (SmoothingParams::keep_layers, issue 15, docs/boundary.md#layers).
// The ordinary phases hold every column node (kept_layers.h); this phase moves whole columns, so
// that every layer keeps its height:
//   - kStraighten, before the ordinary phases: each column's nodes go onto the straight line
//     from its wall node along the wall's normal, each at its input distance from the wall, which
//     removes the layers' lean (their skew against the wall) without changing a height;
//   - kFollowWall, after them, with a sliding boundary: each column's wall node slides towards
//     the mean of its wall neighbours (Laplace on the wall, projected onto the input's surface)
//     and its column follows it, straight.
// A column move is kept only if every element around the column stays valid and their q_min
// does not fall, nor their q_mean (kFollowWall: one of the two rises), else it is halved, up to
// kLayerBacktrackingSteps times, then dropped. Columns are visited in order, one at a time:
// the result is the same for every thread count.

#include "absl/status/statusor.h"
#include "getme/smoothing/smoother.h"
#include "getme/smoothing/smoothing_context.h"

namespace getme {

enum class LayerStage { kStraighten, kFollowWall };

inline constexpr int kLayerBacktrackingSteps = 3;

absl::StatusOr<PhaseSummary> RunLayers(SmoothingContext& context, LayerStage stage);

}  // namespace getme
