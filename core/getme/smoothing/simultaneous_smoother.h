#pragma once

#include "absl/status/statusor.h"
#include "getme/smoothing/smoother.h"
#include "getme/smoothing/smoothing_context.h"

namespace getme {

// GETMe simultaneous (Sec. 3.1): all elements transformed at once, nodes moved to the
// quality-weighted mean of their transformed positions, invalid elements repaired by reverting
// their nodes, until q_mean changes by less than the tolerance. Hands on the best-q_mean state.
// Requires a valid mesh; returns Cancelled (mesh valid, best state restored) if cancelled.
absl::StatusOr<PhaseSummary> RunSimultaneous(SmoothingContext& context);

}  // namespace getme
