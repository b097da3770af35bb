#pragma once

#include "absl/status/statusor.h"
#include "getme/smoothing/smoothing_params.h"
#include "getme/v1/params.pb.h"

namespace getme::wire {

// SmoothingParameters → SmoothingParams: unset fields keep the paper's defaults, `literal`
// switches the safeguards off first (explicit fields still win), threads 0/unset =
// default_threads. Bad values fail with InvalidArgument naming the field.
absl::StatusOr<SmoothingParams> ToEngineParams(const v1::SmoothingParameters& wire,
                                               int default_threads);

// SmoothingParams → SmoothingParameters. Only fields that differ from the engine's defaults are
// set: an unset field means the paper's default on the server too, and automatic values (0 for
// the sequential stop window and cap) keep meaning "automatic". threads 0 stays unset (the
// server's --threads_per_job).
v1::SmoothingParameters ToWireParameters(const SmoothingParams& params);

}  // namespace getme::wire
