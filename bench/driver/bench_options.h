#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "getme/smoothing/smoothing_params.h"

namespace getme::bench {

// A mesh to benchmark: a file (any format `getme` reads) or a getme-meshgen invocation without
// its output path ("hybrid --size 20 --seed 1"), so every generator kind meshgen knows, now or
// later, is a benchmark mesh by its name.
struct MeshSpec {
  enum class Source { kFile, kGenerator };
  Source source = Source::kFile;
  std::string path_or_arguments;
  std::string name;  // for tables and file names; default: file stem or the generator arguments
};

struct BenchOptions {
  bool help = false;
  std::vector<MeshSpec> meshes;
  std::vector<Method> methods = {Method::kSmartLaplace, Method::kSimultaneous, Method::kSequential,
                                 Method::kGetme, Method::kWarpage};
  std::vector<int> thread_counts = {1};
  int repeats = 3;
  // As `getme smooth` has them (cmdline::ToSmoothingParams): --free-boundary, --literal,
  // --no-polish, --sequential-batch, --max-iterations (a cap on every phase, e.g. to time a fixed
  // number of iterations on 10M elements).
  bool free_boundary = false;
  bool literal = false;
  bool no_polish = false;
  std::optional<std::int64_t> max_iterations;
  std::int64_t sequential_batch = 0;  // 0: the engine's default
  // SmoothingParams::kernel_lanes of the in-process runs: 0 = the widest this machine runs.
  int kernel_lanes = 0;
  // Seconds until a trace first reaches this q_mean (e.g. Mesquite's final q_mean − 0.005).
  std::optional<double> target_q_mean;
  std::string out_dir;  // empty: print the summary table only
  // Also write the input (when generated) and the smoothed mesh into out_dir, for `getme report`.
  bool write_meshes = false;
  // Also run every measurement through a getme-server on loopback (service overhead).
  bool service = false;
  std::string server;         // HOST:PORT of a running server; empty: start server_binary
  std::string server_binary;  // empty: getme-server beside getme-bench
};

extern const char kBenchUsage[];

// Parses the arguments after the program name. InvalidArgument names the offending argument.
absl::StatusOr<BenchOptions> ParseBenchOptions(const std::vector<std::string>& args);

}  // namespace getme::bench
