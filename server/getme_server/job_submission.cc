#include "getme_server/job_submission.h"

#include <utility>

#include "absl/strings/str_cat.h"
#include "getme_server/http_json.h"
#include "getme_server/upload_meter.h"
#include "getme_wire/params.h"

namespace getme::server {
namespace {

constexpr std::uint32_t kMaxHistogramBins = 10'000;

}  // namespace

absl::Status CheckHistogramBins(std::uint32_t bins, const char* field) {
  if (bins <= kMaxHistogramBins) return absl::OkStatus();
  return absl::InvalidArgumentError(absl::StrCat(
      field, " = ", bins, " is out of range: must be in [0, ", kMaxHistogramBins, "] (0 = 20)"));
}

absl::StatusOr<SmoothingParams> CheckJobRequest(const v1::SmoothHeader& header,
                                                const ServerOptions& options) {
  absl::StatusOr<SmoothingParams> params =
      wire::ToEngineParams(header.parameters(), options.threads_per_job);
  if (!params.ok()) return params.status();
  if (auto s = CheckHistogramBins(header.result_options().histogram_bins(),
                                  "result_options.histogram_bins");
      !s.ok()) {
    return s;
  }
  return params;
}

std::shared_ptr<Job> CreateJob(const v1::SmoothHeader& header, const SmoothingParams& params,
                               wire::UploadedMesh mesh, std::int64_t upload_bytes,
                               JobRegistry& registry, const ServerOptions& options,
                               ServerMetrics* metrics) {
  return std::make_shared<Job>(registry.NewJobId(), std::move(mesh), upload_bytes, params,
                               header.result_options(), options.progress_interval, metrics);
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
  absl::StatusOr<SmoothingParams> params = CheckJobRequest(header, options);
  if (!params.ok()) return params.status();
  const v1::Mesh& wire_mesh = request.mesh();
  if (auto s = CheckNodeCount(wire_mesh.coordinates_size() / 3, options.max_nodes); !s.ok()) {
    return s;
  }
  absl::StatusOr<wire::UploadedMesh> mesh = wire::ToEngineMesh(wire_mesh, options.max_elements);
  if (!mesh.ok()) return mesh.status();
  const auto upload_bytes = static_cast<std::int64_t>(wire_mesh.ByteSizeLong());
  request.clear_mesh();  // held once, by the job
  return CreateJob(header, *params, *std::move(mesh), upload_bytes, registry, options, metrics);
}

}  // namespace getme::server
