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
#include "getme_wire/reports.h"

namespace getme::server {

absl::Status RunSmoothing(JobResult& work, const SmoothingParams& params,
                          const std::function<void(const ProgressEvent&)>& publish,
                          const CancellationToken* cancel) {
  // The engine reports its histograms with the default bins; other bins need their own pass.
  const int bins = work.options.histogram_bins() == 0
                       ? QualityOptions{}.histogram_bins
                       : static_cast<int>(work.options.histogram_bins());
  std::optional<MeshQuality> custom_before;
  std::unique_ptr<ThreadPool> pool;
  if (bins != QualityOptions{}.histogram_bins) {
    pool = std::make_unique<ThreadPool>(params.threads);
    custom_before = EvaluateMeshQuality(work.mesh, *pool, {.histogram_bins = bins});
  }
  absl::StatusOr<SmoothingResult> result = Smooth(work.mesh, params, publish, cancel);
  if (result.ok()) {
    const MeshQuality after =
        pool ? EvaluateMeshQuality(work.mesh, *pool, {.histogram_bins = bins}) : result->after;
    work.summary = wire::ToWireSmoothResult(
        *result, custom_before ? *custom_before : result->before, after, work.ids);
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
