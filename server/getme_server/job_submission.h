#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "getme/v1/mesh.pb.h"
#include "getme/v1/smoother.pb.h"
#include "getme_server/job.h"
#include "getme_server/job_registry.h"
#include "getme_server/server_metrics.h"
#include "getme_server/server_options.h"
#include "getme_wire/mesh_upload.h"

namespace getme::server {

// Job creation shared by every front end (gRPC SubmitJob/Smooth and HTTP POST /v1/jobs), so both
// validate requests the same way and their jobs are alike.

// INVALID_ARGUMENT naming `field` when more histogram bins are asked for than the server makes.
absl::Status CheckHistogramBins(std::uint32_t bins, const char* field);

// The engine parameters of a request, after checking them and its result options
// (INVALID_ARGUMENT naming the field). Made before the uploaded mesh is built, so a bad request
// is named before a bad mesh, as the header comes before the mesh.
absl::StatusOr<SmoothingParams> CheckJobRequest(const v1::SmoothHeader& header,
                                                const ServerOptions& options);

// A job with a fresh id around an uploaded mesh (validated by wire::MeshUpload) of `upload_bytes`
// encoded bytes; the caller submits it to the registry.
std::shared_ptr<Job> CreateJob(const v1::SmoothHeader& header, const SmoothingParams& params,
                               wire::UploadedMesh mesh, std::int64_t upload_bytes,
                               JobRegistry& registry, const ServerOptions& options,
                               ServerMetrics* metrics);

// HTTP POST /v1/jobs: a CreateJobRequest as protobuf JSON (INVALID_ARGUMENT naming the field or
// the syntax error), then CreateJob. The gateway and the fuzz target (fuzz/http_job_fuzzer.cc) both
// call it, so the fuzzer reaches exactly what the endpoint does with a body. The mesh takes the
// same path as a gRPC upload: one part through wire::MeshUpload.
absl::StatusOr<std::shared_ptr<Job>> CreateJobFromJson(const std::string& body,
                                                       JobRegistry& registry,
                                                       const ServerOptions& options,
                                                       ServerMetrics* metrics);

}  // namespace getme::server
