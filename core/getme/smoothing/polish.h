#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "absl/status/statusor.h"
#include "getme/mesh/node_colouring.h"
#include "getme/smoothing/smoothing_context.h"

namespace getme {

// The node colouring the polish sweeps by, and the elements each colour finishes
// (node_colouring.h). A function of the mesh's connectivity and the free nodes alone, neither of
// which a phase changes, so Smooth() makes it on a second thread while the sequential substep
// runs one pick at a time (meshes below the batches' size), which leaves the other core idle: it
// was 2–5 % of a whole default run's time on the shared meshes, serial, at the polish's start.
struct PolishColouring {
  NodeColouring colouring;
  CompressedRows final_after_colour;  // ElementsByLastColour(mesh, colouring)
};
PolishColouring MakePolishColouring(const Mesh& mesh, std::span<const std::uint8_t> movable);

// The polish stage of issue 14 (item 1), beyond the paper: GETMe's fixed point is not the
// optimum of q_mean (the paper's own tables show GETMe ~0.01 below Mesquite's q_mean), so after
// it each free node (context.movable) takes over-relaxed, damped Newton steps on the costs of its
// elements (c(E), mean_ratio_derivatives.h: convex in one node where the elements are valid, +∞
// past Def. 2's barrier). A step is kept only if the node's cost falls and none of its elements
// becomes invalid. Two stages, each handing on its best state:
//   1. worst elements: cost Σ c(E)^p, p = params.polish_worst_exponent, no q_min floor while it
//      runs, the best-q_min state handed on (skipped for p ≤ 1);
//   2. mean: cost Σ c(E), no element below the q_min the stage began with, the best-q_mean state
//      handed on;
//   3. worst cluster, only where q_min < params.polish_cluster_trigger × q_mean after stage 2: the
//      free nodes of all the worst elements move together (worst_cluster.h), then stage 2 runs
//      again above the q_min that reached.
// So the mesh's q_min never falls below the polish's input and nothing inverts.
//
// A sliding boundary node (context.sliding) takes the Newton step of its cost restricted to its
// surface's tangent plane, or its feature curve's tangent, and the trial is put back onto the
// surface before it is judged (docs/boundary.md#when-nodes-slide).
//
// Nodes are swept one colour of a node colouring (node_colouring.h) at a time: nodes of one
// colour share no element, so they move in parallel and any thread count gives the same bits.
// A stage stops after two sweeps without a new best, when no node moved, when the gain still to
// come (extrapolated from the last two sweeps' gains) is below its tolerance, or at its sweep cap
// (docs/quality.md#polish). One progress event per sweep of either stage (Phase::kPolish,
// numbered on; reverted_nodes = nodes whose step was refused). Keeps context.quality up to date.
// Cancelled between colours, with the mesh left in the best state so far (valid).
//
// `colouring`, if given, must be MakePolishColouring of the mesh and context.movable as they are
// now; without it RunPolish makes it.
absl::StatusOr<PhaseSummary> RunPolish(SmoothingContext& context,
                                       std::optional<PolishColouring> colouring = std::nullopt);

}  // namespace getme
