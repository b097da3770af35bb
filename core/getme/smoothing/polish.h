#pragma once

#include <cstdint>

#include "absl/status/statusor.h"
#include "getme/smoothing/smoothing_context.h"

namespace getme {

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
// Sweeps stop when the q_mean still to gain, extrapolated from the last two sweeps' gains, is
// below params.polish_tolerance, when a sweep gains nothing, or after params.polish_max_sweeps.
// One progress event per sweep (Phase::kPolish; reverted_nodes = free nodes whose step was
// refused). Keeps context.quality up to date. Cancelled between colours, with the mesh valid.
absl::StatusOr<PhaseSummary> RunPolish(SmoothingContext& context);

}  // namespace getme
