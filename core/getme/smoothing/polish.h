#pragma once

#include <cstdint>

#include "absl/status/statusor.h"
#include "getme/smoothing/smoothing_context.h"

namespace getme {

// What the polish stage did.
struct PolishSummary {
  std::int64_t sweeps = 0;        // sweeps over all free nodes
  std::int64_t moved_nodes = 0;   // accepted node steps, summed over the sweeps
  double mean_cost_before = 0.0;  // mean over elements of InverseMeanRatioCost
  double mean_cost_after = 0.0;
  double seconds = 0.0;
};

// The polish stage of issue 14 (item 1), beyond the paper: GETMe's fixed point is not the
// optimum of q_mean (the paper's own tables show GETMe ~0.01 below Mesquite's q_mean), so after
// it each free node (context.movable) takes damped Newton steps on the summed inverse mean ratio
// cost of its elements (mean_ratio_derivatives.h: convex in one node where the elements are
// valid, +∞ past Def. 2's barrier). A step is kept only if the node's cost falls, none of its
// elements becomes invalid and the smallest mean ratio of its elements does not drop, so the
// mesh's q_min never falls and nothing inverts.
//
// Nodes are swept one colour of a node colouring (node_colouring.h) at a time: nodes of one
// colour share no element, so they move in parallel and any thread count gives the same bits.
// Sweeps stop when the mean cost falls by less than params.polish_tolerance of itself over a
// sweep, or after params.polish_max_sweeps. Keeps context.quality up to date. Cancelled between
// colours, with the mesh valid. It reports no progress events: that would need a new Phase,
// and so new wire mappings.
absl::StatusOr<PolishSummary> RunPolish(SmoothingContext& context);

}  // namespace getme
