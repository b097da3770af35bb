#pragma once

#include "getme/mesh/mesh_quality.h"
#include "getme/smoothing/progress.h"
#include "getme/smoothing/smoother.h"
#include "getme/smoothing/smoothing_params.h"
#include "getme/v1/params.pb.h"
#include "getme/v1/quality.pb.h"
#include "getme/v1/smoother.pb.h"
#include "getme_wire/enums.h"

namespace getme::remote {

// Engine parameters as wire parameters. Only fields that differ from the engine's defaults are
// set: an unset field means the paper's default on the server too, and automatic values (0 for
// the sequential stop window and cap) keep meaning "automatic". threads 0 stays unset (the
// server's --threads_per_job).
v1::SmoothingParameters ToWireParameters(const SmoothingParams& params);
// For display: values a newer server may send fall back to GETMe / the simultaneous phase.
inline Method FromWireMethod(v1::Method method) {
  return wire::FromWireMethod(method).value_or(Method::kGetme);
}
inline Phase FromWirePhase(v1::Phase phase) {
  return wire::FromWirePhase(phase).value_or(Phase::kSimultaneous);
}

// Wire messages as the engine structs the CLI's reports and JSON already print.
ProgressEvent FromWireProgress(const v1::ProgressEvent& event);
MeshQuality FromWireQuality(const v1::QualityReport& report);
SmoothingResult FromWireResult(const v1::SmoothResult& result);

}  // namespace getme::remote
