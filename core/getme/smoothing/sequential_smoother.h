#pragma once

#include "absl/status/statusor.h"
#include "getme/smoothing/smoother.h"
#include "getme/smoothing/smoothing_context.h"

namespace getme {

// What the sequential substep ranks elements by: the mean ratio (Sec. 3.2) or the combined
// criterion q_γ = min(q, γ(1 − w/2)) of the warpage variant (Sec. 4.4).
enum class SelectionCriterion { kMeanRatio, kQualityGamma };

// When the sequential substep stops (docs/paper-notes.md#sequential-stop-rule; the paper leaves
// it open).
enum class SequentialStop {
  // The best minimum rose by less than sequential_improvement_tolerance over a window of
  // sequential_stall_iterations picks (0: max(1000, elements)), windows taken one after another.
  // The rule of --method sequential, the warpage variant and GETMe without the polish.
  kStalledWindow,
  // Beyond the paper (issue 14, item 2), when the polish follows: stop as soon as the last
  // sequential_handoff_window picks (0: max(1000, min(elements / 4, 8 × distinct elements picked
  // so far))) raised the best minimum by less than sequential_improvement_tolerance, a sliding
  // window. It stops one window after the rise ends instead of one to two mesh-sized windows
  // later, and the window is counted in rounds over the elements the picks work on, not in mesh
  // sizes (docs/quality.md has the measured trade).
  kHandOnToPolish,
};
// Either rule also stops as soon as the minimum is the quality of an element with no movable
// node: no pick can then give a new best state, so the state handed on is the same.

// Picks per batch: at most params.sequential_batch, and one per sequential_batch_elements
// elements; where that is fewer than 16, 1: one pick at a time, on the calling thread alone.
std::int64_t SequentialBatchLimit(const SmoothingParams& params, const Mesh& mesh);

// GETMe sequential (Sec. 3.2): repeatedly transform the element with the lowest corrected quality
// q + π in place (a min-heap of the lowest keys, with key updates), revert it if a neighbour
// becomes invalid, and adjust its penalty π. On large meshes the picks go in batches of
// independent elements evaluated in parallel, the same for every thread count
// (SmoothingParams::sequential_batch, docs/parallel-sequential.md). Hands on the best state seen
// (highest minimum criterion value).
// Requires a valid mesh; returns Cancelled (mesh valid, best state restored) if cancelled.
absl::StatusOr<PhaseSummary> RunSequential(SmoothingContext& context, SelectionCriterion criterion,
                                           SequentialStop stop = SequentialStop::kStalledWindow);

}  // namespace getme
