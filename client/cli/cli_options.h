#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "formats/vtk_file.h"
#include "getme/smoothing_params.h"

namespace getme::cli {

extern const char kMainUsage[];
extern const char kSmoothUsage[];
extern const char kQualityUsage[];
extern const char kJobsUsage[];

struct SmoothCommandOptions {
  bool help = false;
  std::string input;
  std::string output;
  Method method = Method::kGetme;
  int threads = 0;  // 0 = all cores
  std::optional<std::int64_t> max_iterations;
  bool free_boundary = false;
  bool literal = false;                          // the paper's literal algorithm, safeguards off
  bool no_untangle = false;                      // refuse invalid input instead of untangling it
  std::optional<formats::VtkEncoding> encoding;  // default: the input's
  bool json = false;
  bool quiet = false;
  std::string server;   // HOST:PORT of a getme-server; empty = smooth in-process
  bool detach = false;  // with --server: queue the job, print its id, return (OUT not needed)
};

struct QualityCommandOptions {
  bool help = false;
  std::string input;
  int bins = 20;
  int threads = 0;
  bool json = false;
  std::string server;  // HOST:PORT of a getme-server; empty = evaluate in-process
};

enum class JobsAction { kList, kWatch, kCancel, kFetch };

// `getme jobs list|watch ID|cancel ID|fetch ID OUT.vtk --input IN.vtk`.
struct JobsCommandOptions {
  bool help = false;
  JobsAction action = JobsAction::kList;
  std::string job_id;
  std::string input;   // fetch: the file the job was submitted from (topology, passthrough cells)
  std::string output;  // fetch: where the smoothed file goes
  std::optional<formats::VtkEncoding> encoding;  // fetch; default: the input's
  std::string server = "127.0.0.1:50051";
  bool json = false;
};

// Parse the arguments after the command name. A usage error is InvalidArgument with a message
// that names the offending argument; `--help` anywhere sets `help` and skips the checks.
absl::StatusOr<SmoothCommandOptions> ParseSmoothArguments(const std::vector<std::string>& args);
absl::StatusOr<QualityCommandOptions> ParseQualityArguments(const std::vector<std::string>& args);
absl::StatusOr<JobsCommandOptions> ParseJobsArguments(const std::vector<std::string>& args);

// The engine parameters the smooth options select: method, threads, fix_boundary, and the
// iteration cap applied to every phase.
SmoothingParams ToSmoothingParams(const SmoothCommandOptions& options);

}  // namespace getme::cli
