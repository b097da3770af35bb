#pragma once

#include "absl/status/statusor.h"
#include "getme/smoothing/smoother.h"
#include "getme/smoothing/smoothing_context.h"

namespace getme {

// Untangling before smoothing (beyond the paper, which requires valid input; docs/untangling.md).
// The regularizing transformation also regularizes invalid elements (paper Fig. 4a), so each
// invalid element is transformed in place (with decreasing relaxation) or has single nodes moved
// to their transformed or neighbour-mean positions, keeping a move only if it lowers the number of
// invalid elements around it, or their total inversion. Passes repeat until no element is invalid.
// Fails with FailedPrecondition naming the elements it could not repair.
absl::StatusOr<PhaseSummary> RunUntangle(SmoothingContext& context);

}  // namespace getme
