#pragma once

// What a run with a sliding boundary or kept layers reports beside the engine's result (issue 15,
// item 3): the input surface's features and the kept layers' report, both computed by surface/
// from the input mesh (the server the way the CLI does), between surface/'s plain data and
// getme.v1.SmoothResult, both directions.

#include <optional>

#include "getme/v1/smoother.pb.h"
#include "getme_surface/boundary_surface_counts.h"
#include "getme_surface/layer_report.h"

namespace getme::wire {

struct SurfaceReports {
  std::optional<surface::BoundarySurfaceCounts> boundary_surface;  // a sliding boundary
  std::optional<surface::LayerReport> layers;                      // kept layers
};

// Into result.boundary_slide (feature counts; the engine's part is ToWireSmoothResult's) and
// result.layers.
void AddSurfaceReports(const SurfaceReports& reports, v1::SmoothResult& result);

// boundary_surface only for a result whose boundary is BOUNDARY_SLIDE, as the CLI reports it only
// with --boundary slide; layers when the result has them.
SurfaceReports FromWireSurfaceReports(const v1::SmoothResult& result);

}  // namespace getme::wire
