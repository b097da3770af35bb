#pragma once

#include "absl/status/statusor.h"
#include "getme/smoothing/smoother.h"
#include "getme/smoothing/smoothing_context.h"

namespace getme {

// Plain Laplacian smoothing: every free node moves to the mean of its edge neighbours, all at
// once, until q_mean changes by less than laplace_tolerance. Quality-unaware: it may invert
// elements, which are counted in the progress events and the result, never hidden.
absl::StatusOr<PhaseSummary> RunLaplace(SmoothingContext& context);

// Smart Laplacian smoothing, the baseline of Sec. 4 (docs/paper-notes.md#smart-laplace): a node
// moves to the mean of its edge neighbours only if the mean quality of its adjacent elements
// improves and none becomes invalid; sweeps until q_mean of two consecutive sweeps differs by less
// than laplace_tolerance.
absl::StatusOr<PhaseSummary> RunSmartLaplace(SmoothingContext& context);

}  // namespace getme
