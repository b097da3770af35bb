#pragma once

#include "absl/status/statusor.h"
#include "getme/smoothing/smoothing_params.h"
#include "getme/v1/params.pb.h"

namespace getme::server {

// SmoothingParameters → SmoothingParams: unset fields keep the paper's defaults, `literal` switches
// the safeguards off first (explicit fields still win), threads 0/unset = default_threads. Bad
// values fail with InvalidArgument naming the field.
absl::StatusOr<SmoothingParams> ToEngineParams(const v1::SmoothingParameters& wire,
                                               int default_threads);

}  // namespace getme::server
