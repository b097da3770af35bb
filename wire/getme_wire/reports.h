#pragma once

#include "getme/mesh/mesh_quality.h"
#include "getme/smoothing/smoother.h"
#include "getme/v1/quality.pb.h"
#include "getme/v1/smoother.pb.h"
#include "getme_wire/mesh_ids.h"

namespace getme::wire {

// Quality reports, phase summaries and smoothing results between engine and wire, both
// directions. Element ids in wire reports are the caller's (WireMeshIds.element_ids, when given).

v1::QualityReport ToWireReport(const MeshQuality& quality, const WireMeshIds& ids);
MeshQuality FromWireQuality(const v1::QualityReport& report);

v1::PhaseSummary ToWirePhaseSummary(const PhaseSummary& summary);

// The summary of a finished run: `before` and `after` are the qualities to report (the engine's,
// or ones evaluated with the caller's histogram bins). Job id, nodes and result options are the
// job's to set, and so are the boundary the job ran with and what the input's surface reported
// (boundary_reports.h).
v1::SmoothResult ToWireSmoothResult(const SmoothingResult& result, const MeshQuality& before,
                                    const MeshQuality& after, const WireMeshIds& ids);
// As the engine struct the CLI's reports and JSON print.
SmoothingResult FromWireResult(const v1::SmoothResult& result);

}  // namespace getme::wire
