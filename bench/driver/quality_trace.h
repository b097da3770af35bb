#pragma once

#include <optional>
#include <span>

#include "getme/smoothing/progress.h"

namespace getme::bench {

// The engine time (elapsed_seconds) at which q_mean first reaches `target`: 0 if the initial
// mesh already has it, else the first progress event with q_mean ≥ target; none if no event
// reaches it. Used for "time to Mesquite's final q_mean − 0.005".
std::optional<double> TimeToReach(std::span<const ProgressEvent> trace, double q_mean_before,
                                  double target);

// The time to reach `fraction` of the run's q_mean gain: q_mean ≥ before + fraction · (after −
// before). None when q_mean did not rise (there is no gain to reach).
std::optional<double> TimeToGainFraction(std::span<const ProgressEvent> trace, double q_mean_before,
                                         double q_mean_after, double fraction);

}  // namespace getme::bench
