#include "getme_server/job_run.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "getme/mesh/mesh_quality.h"
#include "getme/parallel/thread_pool.h"
#include "getme/smoothing/smoother.h"
#include "getme_surface/boundary_surface_counts.h"
#include "getme_surface/layer_report.h"
#include "getme_surface/surface_slide.h"
#include "getme_wire/boundary_reports.h"
#include "getme_wire/enums.h"
#include "getme_wire/reports.h"

namespace getme::server {
namespace {

// The input's surface, its features and its boundary-layer columns, built from the uploaded mesh
// before anything moves, as `getme smooth` builds them from its input file. A mesh they cannot be
// built from is the caller's: INVALID_ARGUMENT with the surface's message.
absl::StatusOr<std::unique_ptr<surface::SurfaceSlide>> BuildSurfaceSlide(
    const Mesh& mesh, std::span<const surface::GroupedFace> groups, const SmoothingParams& params) {
  surface::SlideOptions options;
  // The caller's tagged faces, as a file's: the interfaces between volumes are counted, not
  // refused (mesh.proto).
  options.groups = groups;
  options.skip_interior_groups = true;
  options.feature_angle_degrees = params.feature_angle_degrees;
  options.slide_boundary = params.slide_boundary;
  options.keep_layers = params.keep_layers;
  absl::StatusOr<std::unique_ptr<surface::SurfaceSlide>> slide =
      surface::SurfaceSlide::Build(mesh, options);
  if (!slide.ok()) return absl::InvalidArgumentError(slide.status().message());
  return slide;
}

}  // namespace

absl::Status RunSmoothing(JobResult& work, const SmoothingParams& params,
                          const std::function<void(const ProgressEvent&)>& publish,
                          const CancellationToken* cancel) {
  // Quality and layer measurements outside the engine share one pool, made when first needed.
  std::unique_ptr<ThreadPool> pool;
  const auto measuring_pool = [&]() -> ThreadPool& {
    if (!pool) pool = std::make_unique<ThreadPool>(params.threads);
    return *pool;
  };
  // The engine reports its histograms with the default bins; other bins need their own pass.
  const int bins = work.options.histogram_bins() == 0
                       ? QualityOptions{}.histogram_bins
                       : static_cast<int>(work.options.histogram_bins());
  std::optional<MeshQuality> custom_before;
  if (bins != QualityOptions{}.histogram_bins) {
    custom_before = EvaluateMeshQuality(work.mesh, measuring_pool(), {.histogram_bins = bins});
  }
  std::unique_ptr<surface::SurfaceSlide> slide;
  std::optional<surface::LayerHeights> layers_before;
  if (params.slide_boundary || params.keep_layers) {
    absl::StatusOr<std::unique_ptr<surface::SurfaceSlide>> built =
        BuildSurfaceSlide(work.mesh, work.surface_groups, params);
    if (!built.ok()) return built.status();
    slide = *std::move(built);
    if (params.keep_layers) {
      layers_before = surface::MeasureKeptLayers(work.mesh, *slide, measuring_pool());
    }
  }
  absl::StatusOr<SmoothingResult> result = Smooth(work.mesh, params, publish, cancel, slide.get());
  if (result.ok()) {
    const MeshQuality after =
        custom_before ? EvaluateMeshQuality(work.mesh, measuring_pool(), {.histogram_bins = bins})
                      : result->after;
    work.summary = wire::ToWireSmoothResult(
        *result, custom_before ? *custom_before : result->before, after, work.ids);
    work.summary.set_boundary(wire::ToWireBoundary(params));
    wire::SurfaceReports reports;
    if (params.slide_boundary) reports.boundary_surface = surface::CountFeatures(slide->surface());
    if (layers_before) {
      reports.layers = surface::MakeLayerReport(
          *slide, *layers_before, surface::MeasureKeptLayers(work.mesh, *slide, measuring_pool()));
    }
    wire::AddSurfaceReports(reports, work.summary);
    work.summary.set_coordinates_only(work.options.coordinates_only());
    work.summary.set_nodes(static_cast<std::uint64_t>(work.mesh.node_count()));
    return absl::OkStatus();
  }
  const absl::Status& failure = result.status();
  if (failure.code() != absl::StatusCode::kFailedPrecondition || work.ids.element_ids.empty()) {
    return failure;
  }
  // The engine names elements by number; callers who sent ids get theirs too.
  ThreadPool ids_pool(1);
  std::vector<std::string> ids;
  for (ElementId e : EvaluateMeshQuality(work.mesh, ids_pool).first_invalid) {
    ids.push_back(absl::StrCat(work.ids.ElementId(e)));
  }
  return absl::FailedPreconditionError(
      absl::StrCat(failure.message(), " (as Mesh.element_ids: ", absl::StrJoin(ids, ", "), ")"));
}

}  // namespace getme::server
