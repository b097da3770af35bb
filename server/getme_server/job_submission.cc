#include "getme_server/job_submission.h"

#include <utility>

#include "absl/strings/str_cat.h"
#include "getme_server/http_json.h"
#include "getme_server/mesh_conversion.h"
#include "getme_server/params_conversion.h"
#include "getme_server/upload_meter.h"

namespace getme::server {
namespace {

constexpr std::uint32_t kMaxHistogramBins = 10'000;

}  // namespace

absl::Status CheckHistogramBins(std::uint32_t bins, const char* field) {
  if (bins <= kMaxHistogramBins) return absl::OkStatus();
  return absl::InvalidArgumentError(absl::StrCat(
      field, " = ", bins, " is out of range: must be in [0, ", kMaxHistogramBins, "] (0 = 20)"));
}

absl::StatusOr<std::shared_ptr<Job>> CreateJob(const v1::SmoothHeader& header, v1::Mesh mesh,
                                               JobRegistry& registry, const ServerOptions& options,
                                               ServerMetrics* metrics) {
  absl::StatusOr<SmoothingParams> params =
      ToEngineParams(header.parameters(), options.threads_per_job);
  if (!params.ok()) return params.status();
  if (auto s = CheckHistogramBins(header.result_options().histogram_bins(),
                                  "result_options.histogram_bins");
      !s.ok()) {
    return s;
  }
  if (auto s = CheckNodeCount(mesh.coordinates_size() / 3, options.max_nodes); !s.ok()) return s;
  absl::StatusOr<Mesh> engine_mesh = ToEngineMesh(mesh, options.max_elements);
  if (!engine_mesh.ok()) return engine_mesh.status();
  return std::make_shared<Job>(registry.NewJobId(), std::move(mesh), *std::move(engine_mesh),
                               *params, header.result_options(), options.progress_interval,
                               metrics);
}

absl::StatusOr<std::shared_ptr<Job>> CreateJobFromJson(const std::string& body,
                                                       JobRegistry& registry,
                                                       const ServerOptions& options,
                                                       ServerMetrics* metrics) {
  v1::CreateJobRequest request;
  if (auto s = FromJson(body, request); !s.ok()) return s;
  v1::SmoothHeader header;
  *header.mutable_parameters() = request.parameters();
  *header.mutable_result_options() = request.result_options();
  return CreateJob(header, std::move(*request.mutable_mesh()), registry, options, metrics);
}

}  // namespace getme::server
