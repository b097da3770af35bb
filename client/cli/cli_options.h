#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "cmdline/smoothing_flags.h"
#include "formats/mesh_file.h"
#include "formats/unstructured_grid.h"
#include "getme/smoothing/smoothing_params.h"

namespace getme::cli {

extern const char kMainUsage[];
extern const char kSmoothUsage[];
extern const char kQualityUsage[];
extern const char kJobsUsage[];
extern const char kReportUsage[];
extern const char kConvertUsage[];

// How the mesh files of a command are read and written (--input-format, --format, --binary,
// --ascii, --compress). Unset: by extension (input: else by content); the input's encoding.
struct FileOptions {
  std::optional<formats::FileFormat> input_format;
  std::optional<formats::FormatChoice> output_format;
  std::optional<formats::Encoding> encoding;
  bool compress = false;  // .vtu: zlib-compressed blocks
};

// How `--server` is reached when it has access control on (docs/reliability.md): the bearer
// token in --token-file (else the GETME_TOKEN environment variable; never a token on the command
// line, where `ps` shows it), TLS trusting --tls-ca, a client certificate for mutual TLS.
struct ServerAccessOptions {
  std::string token_file;
  std::string tls_ca;
  std::string tls_cert;  // with tls_key
  std::string tls_key;
  bool any() const {
    return !token_file.empty() || !tls_ca.empty() || !tls_cert.empty() || !tls_key.empty();
  }
};

struct SmoothCommandOptions {
  bool help = false;
  std::string input;
  std::string output;
  cmdline::SmoothingFlags smoothing;  // --method, --threads, --max-iterations, ...
  FileOptions files;
  std::vector<std::string> fix_groups;  // --fix-physical: physical groups / refs whose nodes stay
  bool fix_surfaces = false;            // --fix-surfaces: nodes of every surface/line/vertex cell
  std::string trace;                    // --trace FILE: progress events + result as JSON lines
  bool json = false;
  bool quiet = false;
  std::string server;   // HOST:PORT of a getme-server; empty = smooth in-process
  bool detach = false;  // with --server: queue the job, print its id, return (OUT not needed)
  ServerAccessOptions access;
};

struct QualityCommandOptions {
  bool help = false;
  std::string input;
  std::optional<formats::FileFormat> input_format;
  int bins = 20;
  int threads = 0;
  bool json = false;
  std::string server;  // HOST:PORT of a getme-server; empty = evaluate in-process
  ServerAccessOptions access;
};

enum class JobsAction { kList, kWatch, kCancel, kFetch };

// `getme jobs list|watch ID|cancel ID|fetch ID OUT.vtk --input IN.vtk`.
struct JobsCommandOptions {
  bool help = false;
  JobsAction action = JobsAction::kList;
  std::string job_id;
  std::string input;   // fetch: the file the job was submitted from (topology, passthrough cells)
  std::string output;  // fetch: where the smoothed file goes
  FileOptions files;   // fetch
  std::string server = "127.0.0.1:50051";
  bool json = false;
  ServerAccessOptions access;
};

// `getme report IN OUT [--trace T] [--picture-format svg|png] [-o FILE]`: quality histograms
// before/after and, with a trace, q_min / q_mean against time (paper Figs. 7–8, 11–12, 15–16).
struct ReportCommandOptions {
  bool help = false;
  std::string input;   // the mesh before smoothing
  std::string output;  // the mesh after smoothing
  std::optional<formats::FileFormat> input_format;
  std::string trace;           // JSON lines of `getme smooth --json` / `--trace`
  std::string picture_format;  // svg or png; default: from --output's extension, else svg
  std::string picture;         // the picture file; default OUT's stem + "-report.<format>"
  int bins = 20;
  bool by_iteration = false;  // x axis: progress events in order instead of seconds
  std::string title;
  std::string data;  // --data FILE: the plotted numbers as tab-separated text
};

// `getme convert IN OUT`: the same mesh in another format (or encoding), nothing smoothed.
struct ConvertCommandOptions {
  bool help = false;
  std::string input;
  std::string output;
  FileOptions files;
};

// Parse the arguments after the command name. A usage error is InvalidArgument with a message
// that names the offending argument; `--help` anywhere sets `help` and skips the checks.
absl::StatusOr<SmoothCommandOptions> ParseSmoothArguments(const std::vector<std::string>& args);
absl::StatusOr<QualityCommandOptions> ParseQualityArguments(const std::vector<std::string>& args);
absl::StatusOr<JobsCommandOptions> ParseJobsArguments(const std::vector<std::string>& args);
absl::StatusOr<ReportCommandOptions> ParseReportArguments(const std::vector<std::string>& args);
absl::StatusOr<ConvertCommandOptions> ParseConvertArguments(const std::vector<std::string>& args);

// The engine parameters the smooth options select: method, threads, fix_boundary, and the
// iteration cap applied to every phase.
SmoothingParams ToSmoothingParams(const SmoothCommandOptions& options);

}  // namespace getme::cli
