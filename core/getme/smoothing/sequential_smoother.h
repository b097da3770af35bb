#pragma once

#include "absl/status/statusor.h"
#include "getme/smoothing/smoother.h"
#include "getme/smoothing/smoothing_context.h"

namespace getme {

// What the sequential substep ranks elements by: the mean ratio (Sec. 3.2) or the combined
// criterion q_γ = min(q, γ(1 − w/2)) of the warpage variant (Sec. 4.4).
enum class SelectionCriterion { kMeanRatio, kQualityGamma };

// GETMe sequential (Sec. 3.2): repeatedly transform the element with the lowest corrected quality
// q + π in place (indexed min-heap with key updates), revert it if a neighbour becomes invalid,
// and adjust its penalty π. Hands on the best state seen (highest minimum criterion value).
// Requires a valid mesh; returns Cancelled (mesh valid, best state restored) if cancelled.
absl::StatusOr<PhaseSummary> RunSequential(SmoothingContext& context, SelectionCriterion criterion);

}  // namespace getme
