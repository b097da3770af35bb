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

absl::StatusOr<JobSubmission> SubmissionFromJson(const std::string& body,
                                                 const ServerOptions& options, bool keep_upload) {
  v1::CreateJobRequest request;
  if (auto s = FromJson(body, request); !s.ok()) return s;
  JobSubmission submission;
  *submission.header.mutable_parameters() = request.parameters();
  *submission.header.mutable_result_options() = request.result_options();
  absl::StatusOr<SmoothingParams> params = CheckJobRequest(submission.header, options);
  if (!params.ok()) return params.status();
  submission.params = *params;
  const v1::Mesh& wire_mesh = request.mesh();
  if (auto s = CheckNodeCount(wire_mesh.coordinates_size() / 3, options.max_nodes); !s.ok()) {
    return s;
  }
  absl::StatusOr<wire::UploadedMesh> mesh = wire::ToEngineMesh(wire_mesh, options.max_elements);
  if (!mesh.ok()) return mesh.status();
  submission.mesh = *std::move(mesh);
  submission.upload_bytes = static_cast<std::int64_t>(wire_mesh.ByteSizeLong());
  if (keep_upload) submission.received.whole_mesh = wire_mesh.SerializeAsString();
  return submission;
}

}  // namespace getme::server
