#pragma once

#include "absl/status/statusor.h"
#include "getme/smoothing/smoothing_params.h"
#include "getme/v1/params.pb.h"

namespace getme::wire {

// SmoothingParameters → SmoothingParams: unset fields keep the paper's defaults, `literal`
// switches the safeguards off first (explicit fields still win), threads 0/unset =
// default_threads. boundary (or its older spelling free_boundary) sets fix_boundary and
// slide_boundary. Bad values fail with InvalidArgument naming the field; so do combinations that
// contradict each other (free_boundary = true with BOUNDARY_SLIDE, keep_layers with a free
// boundary, feature_angle_degrees without BOUNDARY_SLIDE), naming both fields.
absl::StatusOr<SmoothingParams> ToEngineParams(const v1::SmoothingParameters& wire,
                                               int default_threads);

// SmoothingParams → SmoothingParameters. Only fields that differ from the engine's defaults are
// set: an unset field means the paper's default on the server too, and automatic values (0 for
// the sequential stop window and cap) keep meaning "automatic". threads 0 stays unset (the
// server's --threads_per_job). A sliding boundary is sent as BOUNDARY_SLIDE, a free one as
// free_boundary = true (which servers that predate the enum understand too).
v1::SmoothingParameters ToWireParameters(const SmoothingParams& params);

}  // namespace getme::wire
