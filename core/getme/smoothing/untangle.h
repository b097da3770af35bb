#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "absl/status/statusor.h"
#include "getme/mesh/mesh.h"
#include "getme/smoothing/smoother.h"
#include "getme/smoothing/smoothing_context.h"
#include "getme/smoothing/smoothing_params.h"

namespace getme {

// Untangling before smoothing (beyond the paper, which requires valid input; docs/untangling.md).
// Minimises Σ_E Σ_k max(0, 1 − det D(T_k)/β_E)³ over the node tetrahedra T_k (eq. 9) of every
// element, a Mesquite-style "untangle beta" objective, by damped Newton steps of one free node at
// a time. Each det D(T_k) is affine in any one node's position, so the objective is convex in it.
// Nodes are swept in the independent sets of a node colouring, so any thread count gives the same
// bits. Ends when no element is invalid (Def. 2), or fails with FailedPrecondition: with a proof
// when an inverted corner has only immovable nodes, else naming the elements left invalid when a
// sweep no longer makes progress.
absl::StatusOr<PhaseSummary> RunUntangle(SmoothingContext& context);

// The nodes untangling may move: `movable`, plus with params.untangle_free_boundary every node of
// an element that is invalid now (quality[e] < 0) that the input did not mark fixed. Smooth() also
// uses it for the result check, which must expect those nodes to move.
std::vector<std::uint8_t> UntangleMovable(const Mesh& mesh, const SmoothingParams& params,
                                          std::span<const std::uint8_t> movable,
                                          std::span<const double> quality);

}  // namespace getme
