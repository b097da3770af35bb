#include "getme_server/upload_meter.h"

#include "absl/strings/str_cat.h"

namespace getme::server {

absl::Status CheckNodeCount(std::int64_t nodes, std::int64_t max_nodes) {
  if (nodes <= max_nodes) return absl::OkStatus();
  return absl::InvalidArgumentError(absl::StrCat(
      "mesh has ", nodes, " nodes, more than the server's limit of ", max_nodes, " (--max_nodes)"));
}

absl::Status UploadMeter::CheckDeclared(const v1::MeshSize& expected) const {
  if (expected.nodes() <= static_cast<std::uint64_t>(options_.max_nodes)) {
    return absl::OkStatus();
  }
  return absl::InvalidArgumentError(absl::StrCat("expected_size declares ", expected.nodes(),
                                                 " nodes, more than the server's limit of ",
                                                 options_.max_nodes, " (--max_nodes)"));
}

absl::Status UploadMeter::AddChunk(const v1::MeshChunk& chunk, std::int64_t nodes) {
  if (auto s = CheckNodeCount(nodes, options_.max_nodes); !s.ok()) return s;
  bytes_ += static_cast<std::int64_t>(chunk.ByteSizeLong());
  if (bytes_ > options_.max_upload_bytes) {
    return absl::ResourceExhaustedError(
        absl::StrCat("the upload passed ", bytes_,
                     " bytes of mesh chunks, more than the server's "
                     "limit of ",
                     options_.max_upload_bytes, " bytes per job (--max_upload_bytes)"));
  }
  if (jobs_ == nullptr) return absl::OkStatus();
  const std::int64_t held = jobs_->HeldBytes();
  if (held + bytes_ > options_.max_queued_bytes) {
    return absl::ResourceExhaustedError(
        absl::StrCat("queued and running jobs hold ", held, " bytes of meshes; with this upload's ",
                     bytes_, " bytes so far that passes the server's limit of ",
                     options_.max_queued_bytes, " bytes (--max_queued_bytes); retry later"));
  }
  return absl::OkStatus();
}

}  // namespace getme::server
