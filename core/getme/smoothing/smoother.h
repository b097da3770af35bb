#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "absl/status/statusor.h"
#include "getme/mesh/mesh.h"
#include "getme/mesh/mesh_quality.h"
#include "getme/smoothing/boundary_slide.h"
#include "getme/smoothing/progress.h"
#include "getme/smoothing/smoothing_params.h"

namespace getme {

struct PhaseSummary {
  Phase phase = Phase::kSimultaneous;
  std::int64_t iterations = 0;
  double seconds = 0.0;
  double q_min = 0.0;  // after the phase (the state it handed on)
  double q_mean = 0.0;
  std::int64_t reverted_nodes = 0;
};

// What a sliding boundary did (SmoothingParams::slide_boundary and keep_layers, issue 15).
struct BoundarySlideSummary {
  std::int64_t sliding_nodes = 0;  // boundary nodes that could slide (not corners, not fixed)
  std::int64_t slid_nodes = 0;     // of those, the ones that moved
  double max_distance = 0.0;       // the largest distance of one from the input's surface
  // Nodes above the walls in kept boundary-layer columns (keep_layers).
  std::int64_t layer_nodes = 0;
};

struct SmoothingResult {
  MeshQuality before;
  MeshQuality after;
  // The per-element measures `after` summarises, for callers that write them out (the CLI's
  // quality arrays) instead of measuring the same mesh again.
  ElementMeasures after_elements;
  std::vector<PhaseSummary> phases;  // in the order they ran
  std::int64_t iterations_untangle = 0;
  std::int64_t iterations_simultaneous = 0;
  std::int64_t iterations_sequential = 0;  // includes the q_γ sequential substep
  std::int64_t iterations_laplace = 0;
  std::int64_t iterations_polish = 0;  // sweeps over the free nodes (SmoothingParams::polish)
  std::int64_t iterations_layers = 0;  // passes over the kept columns (keep_layers)
  double seconds = 0.0;
  int threads = 1;
  // Doubles per vector in the whole-mesh element passes (SmoothingParams::kernel_lanes resolved
  // on this machine): 2, 4 or 8. Like `threads`, it changes the time, not the result.
  int kernel_lanes = 2;
  // With a sliding boundary or kept layers only.
  std::optional<BoundarySlideSummary> boundary_slide;
};

// Smooths the free nodes of `mesh` in place with params.method. Invalid input is untangled first
// (params.untangle) or refused with FailedPrecondition naming the first invalid elements.
// Returns Cancelled if `cancel` fires; the mesh is then left valid (the best state so far).
// Success means the result passed ResultCheck (result_check.h): valid, fixed nodes bit-identical,
// finite, `after` its quality; a result failing it is returned as Internal, never as success.
// Plain Laplace (Method::kLaplace) may invert elements: that is FailedPrecondition, naming them.
// After any error but Cancelled the mesh holds no result and must not be used.
// With `slide`, the boundary nodes it says slide move along the input's surface instead of
// staying fixed (params.fix_boundary; boundary_slide.h); the result check then also checks that
// each lies on the surface. Without it (the default) nothing changes.
absl::StatusOr<SmoothingResult> Smooth(Mesh& mesh, const SmoothingParams& params,
                                       const ProgressCallback& progress = {},
                                       const CancellationToken* cancel = nullptr,
                                       const BoundarySlide* slide = nullptr);

}  // namespace getme
