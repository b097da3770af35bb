#pragma once

#include <functional>
#include <vector>

#include "absl/status/status.h"
#include "getme/mesh/mesh.h"
#include "getme/smoothing/progress.h"
#include "getme/smoothing/smoothing_params.h"
#include "getme/v1/smoother.pb.h"
#include "getme_surface/boundary_surface.h"
#include "getme_wire/mesh_ids.h"

namespace getme::server {

// What a job works on and, once it succeeded, hands out once: the uploaded mesh (smoothed in
// place), the caller's ids and fixed-node list (echoed with the result), the surface groups a
// sliding boundary keeps its nodes in, the result options, and the summary.
struct JobResult {
  v1::SmoothResult summary;
  Mesh mesh;
  wire::WireMeshIds ids;
  std::vector<surface::GroupedFace> surface_groups;
  v1::ResultOptions options;
};

// Runs the engine on a job's mesh on the calling thread: smooths `work.mesh` in place, calling
// `publish` with each progress event, and on success fills `work.summary` (quality before and
// after with the caller's histogram bins, phases, iterations, nodes; the job id is the job's to
// set). With a sliding boundary or kept layers (params.slide_boundary, keep_layers) it first builds
// the input's surface and layer columns from `work.mesh` (surface/, as the CLI does; a mesh they
// cannot be built from is InvalidArgument) and adds their reports to the summary. Fails with the
// engine's status; an invalid result names the caller's element ids too.
absl::Status RunSmoothing(JobResult& work, const SmoothingParams& params,
                          const std::function<void(const ProgressEvent&)>& publish,
                          const CancellationToken* cancel);

}  // namespace getme::server
