#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "getme/v1/mesh.pb.h"
#include "getme/v1/smoother.pb.h"
#include "getme_server/job_directory.h"
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

// HTTP POST /v1/jobs: a CreateJobRequest as protobuf JSON (INVALID_ARGUMENT naming the field or
// the syntax error), checked like every request, its mesh built through wire::ToEngineMesh. The
// gateway and the fuzz target (fuzz/http_job_fuzzer.cc) both call it, so the fuzzer reaches
// exactly what the endpoint does with a body. `keep_upload`: the submission also carries the
// serialized mesh (a shared job store sends it to the replica that runs the job).
absl::StatusOr<JobSubmission> SubmissionFromJson(const std::string& body,
                                                 const ServerOptions& options, bool keep_upload);

}  // namespace getme::server
