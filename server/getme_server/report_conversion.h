#pragma once

#include "getme/mesh/mesh_quality.h"
#include "getme/smoothing/progress.h"
#include "getme/smoothing/smoother.h"
#include "getme/v1/mesh.pb.h"
#include "getme/v1/quality.pb.h"
#include "getme/v1/smoother.pb.h"

namespace getme::server {

// Engine quality statistics, progress and phase summaries → wire messages. Element ids in the
// report are the caller's (Mesh.element_ids of `wire`, when given).
v1::QualityReport ToWireReport(const MeshQuality& quality, const v1::Mesh& wire);
// Without job id and sequence: the job stamps those when it publishes the event.
v1::ProgressEvent ToWireEvent(const ProgressEvent& event);
v1::PhaseSummary ToWirePhaseSummary(const PhaseSummary& summary);

}  // namespace getme::server
