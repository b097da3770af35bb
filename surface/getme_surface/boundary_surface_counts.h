#pragma once

// What a run with a sliding boundary reports of the input's surface (issue 15, item 3): its
// feature edges, the curves they form, its corners and its surface groups. Plain data, so the
// CLI, the service and the wire share it, as they share the kept layers' report
// (layer_report.h).

#include <cstdint>

#include "getme_surface/boundary_surface.h"

namespace getme::surface {

struct BoundarySurfaceCounts {
  std::int64_t feature_edges = 0;
  std::int64_t feature_curves = 0;
  std::int64_t corners = 0;                 // nodes on other than two feature edges: they stay
  std::int64_t surface_groups = 0;          // the input's tagged groups, plus group 0
  std::int64_t interior_grouped_faces = 0;  // tagged faces not on the boundary (interfaces)
};

inline BoundarySurfaceCounts CountFeatures(const BoundarySurface& surface) {
  return BoundarySurfaceCounts{static_cast<std::int64_t>(surface.feature_edges.size()),
                               surface.curve_count, surface.corner_count, surface.group_count,
                               surface.interior_grouped_faces};
}

}  // namespace getme::surface
