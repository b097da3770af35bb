#pragma once

#include "getme/smoothing/progress.h"
#include "getme/v1/smoother.pb.h"

namespace getme::wire {

// The engine's progress events and the wire's, both directions.

// Without job id and sequence: the job stamps those when it publishes the event.
v1::ProgressEvent ToWireEvent(const ProgressEvent& event);
// For display: a phase a newer server may send reads as the simultaneous phase.
ProgressEvent FromWireProgress(const v1::ProgressEvent& event);

}  // namespace getme::wire
