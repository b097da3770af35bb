#pragma once

#include "absl/status/statusor.h"
#include "getme/smoothing/smoothing_context.h"

namespace getme {

// The worst-cluster stage of the polish (issue 14, item 3: "a max-min local optimization of the
// free nodes of the worst elements"). Node-by-node steps, GETMe's sequential substep as well as
// the polish's node-local Newton steps, stall where several bad elements share their free nodes:
// at such a plateau every single-node move that lifts one element lowers another (the pinned cap
// prisms of a boundary-layer mesh, docs/thin-layers.md). This stage moves all free nodes of the
// worst elements together instead. Each round:
//   1. the cluster: every element within params.polish_cluster_band (relative) of the mesh's
//      q_min, their free nodes V (context.movable), and every element B that has a node in V;
//      if the worst element has no free node, nothing can lift q_min and the stage ends;
//   2. minimises f(V) = Σ_{e∈B} (q_min / q_e)^p, p = params.polish_cluster_exponent, a smooth
//      stand-in for max_V min_{e∈B} q_e, by limited-memory BFGS whose initial inverse Hessian is
//      scaled per node by the squared distance to its nearest neighbour, with a backtracking line
//      search on which an invalid element (Def. 2) counts as f = +∞, so no element ever inverts;
//      of its iterates it keeps the one with the highest min q over B;
//   3. keeps the result only if the mesh's q_min rose, else restores the round's start and ends.
// Rounds repeat while q_min rises by more than params.polish_cluster_tolerance (relative), up to
// params.polish_cluster_max_rounds, each of at most params.polish_cluster_iterations iterations.
// Then one last round, on the cluster where they stalled, ascends the minimum itself: up to
// params.polish_cluster_ascent_iterations steps along the point of smallest norm in the convex
// hull of the nearly-worst elements' gradients (min_norm_point.h), each the step length along it
// that gives the highest min q over B; kept, as a round is, only if the mesh's q_min rose. The
// stand-in's rounds come first because they find higher plateaus: run from the start, the ascent
// settles on the first local max-min point it meets.
// Element evaluations run in parallel and are summed in a fixed order, so any thread count gives
// the same bits. q_min never falls; q_mean may fall a little, which is why RunPolish runs its mean
// stage again afterwards. context.quality stays exact; `current` is the state handed on. One
// progress event per kept round (Phase::kPolish, numbered on from summary.iterations). Sliding
// boundary nodes take part: their gradient is turned into their surface and every trial point
// put back onto it, so the search follows the surface (docs/boundary.md).
absl::Status RunWorstCluster(SmoothingContext& context, SmoothingContext::Summary& current,
                             PhaseSummary& summary);

}  // namespace getme
