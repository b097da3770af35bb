#pragma once

#include <cstdint>

#include "absl/status/status.h"
#include "getme/v1/mesh.pb.h"
#include "getme/v1/smoother.pb.h"
#include "getme_server/job_directory.h"
#include "getme_server/server_options.h"

namespace getme::server {

// INVALID_ARGUMENT naming --max_nodes when a mesh has more nodes than the server takes (like
// --max_elements: a mesh that can never be accepted here).
absl::Status CheckNodeCount(std::int64_t nodes, std::int64_t max_nodes);

// Meters one upload as its messages arrive and refuses it as soon as it passes a limit, so an
// oversized mesh is never buffered whole: the declared size against --max_nodes before any chunk,
// then after each chunk the nodes so far, the encoded chunk bytes against --max_upload_bytes
// (RESOURCE_EXHAUSTED), and, for uploads that become jobs, those bytes plus what queued and
// running jobs already hold against --max_queued_bytes (RESOURCE_EXHAUSTED).
class UploadMeter {
 public:
  // `jobs` null: the upload does not become a job (EvaluateQuality), no queue budget applies.
  UploadMeter(const ServerOptions& options, const JobDirectory* jobs)
      : options_(options), jobs_(jobs) {}

  absl::Status CheckDeclared(const v1::MeshSize& expected) const;
  // `nodes` counts the nodes uploaded so far, `chunk`'s included.
  absl::Status AddChunk(const v1::MeshChunk& chunk, std::int64_t nodes);

  std::int64_t bytes() const { return bytes_; }

 private:
  const ServerOptions& options_;
  const JobDirectory* const jobs_;
  std::int64_t bytes_ = 0;
};

}  // namespace getme::server
