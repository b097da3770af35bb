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

namespace getme::server {

// Job creation shared by every front end (gRPC SubmitJob/Smooth and HTTP POST /v1/jobs), so both
// validate requests the same way and their jobs are alike.

// INVALID_ARGUMENT naming `field` when more histogram bins are asked for than the server makes.
absl::Status CheckHistogramBins(std::uint32_t bins, const char* field);

// Validates parameters, result options and mesh (INVALID_ARGUMENT naming what is wrong) and
// builds a job with a fresh id; the caller submits it to the registry.
absl::StatusOr<std::shared_ptr<Job>> CreateJob(const v1::SmoothHeader& header, v1::Mesh mesh,
                                               JobRegistry& registry, const ServerOptions& options,
                                               ServerMetrics* metrics);

// HTTP POST /v1/jobs: a CreateJobRequest as protobuf JSON (INVALID_ARGUMENT naming the field or
// the syntax error), then CreateJob. The gateway and the fuzz target (fuzz/http_job_fuzzer.cc) both
// call it, so the fuzzer reaches exactly what the endpoint does with a body.
absl::StatusOr<std::shared_ptr<Job>> CreateJobFromJson(const std::string& body,
                                                       JobRegistry& registry,
                                                       const ServerOptions& options,
                                                       ServerMetrics* metrics);

}  // namespace getme::server
