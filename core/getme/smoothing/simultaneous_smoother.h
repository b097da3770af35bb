#pragma once

#include "absl/status/statusor.h"
#include "getme/smoothing/smoother.h"
#include "getme/smoothing/smoothing_context.h"

namespace getme {

// When the simultaneous substep stops.
enum class SimultaneousStop {
  // Sec. 4: q_mean of two consecutive iterations differs by less than simultaneous_tolerance
  // (docs/paper-notes.md#simultaneous-stop-rule). The paper's rule, and the one the
  // simultaneous-only method and GETMe without the polish use.
  kSettled,
  // Beyond the paper (issue 14, item 2): the polish follows, so stop as soon as q_mean rose by
  // less than simultaneous_handoff_gain per iteration over the last simultaneous_handoff_window
  // iterations, or by the kSettled rule, whichever comes first. Near its plateau an iteration
  // buys ever less of q_mean, and GETMe's fixed point lies below the optimum of q_mean anyway
  // (Sec. 4's tables; docs/quality.md has the measured trade-off).
  kHandOnToPolish,
};

// GETMe simultaneous (Sec. 3.1): all elements transformed at once, nodes moved to the
// quality-weighted mean of their transformed positions, invalid elements repaired by reverting
// their nodes, until `stop` says so. Hands on the best-q_mean state. Requires a valid mesh;
// returns Cancelled (mesh valid, best state restored) if cancelled.
absl::StatusOr<PhaseSummary> RunSimultaneous(SmoothingContext& context, SimultaneousStop stop);

}  // namespace getme
