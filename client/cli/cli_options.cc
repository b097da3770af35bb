#include "cli/cli_options.h"

#include <functional>
#include <map>

#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"

namespace getme::cli {

const char kMainUsage[] =
    R"(getme: GETMe smoothing of mixed volume meshes (tetrahedra, hexahedra, pyramids, prisms)

Usage:
  getme smooth IN.vtk OUT.vtk [options]   smooth a VTK legacy unstructured grid
  getme quality IN.vtk [options]          report the element quality of a mesh
  getme jobs list|watch|cancel|fetch      manage jobs on a getme-server
  getme --help                            this text
  getme --version                         the version

Run 'getme <command> --help' for the options of a command.
)";

const char kSmoothUsage[] = R"(Usage: getme smooth IN.vtk OUT.vtk [options]

Smooths a VTK legacy unstructured grid (ASCII or BINARY) of tetrahedra (VTK type 10),
hexahedra (12), wedges (13) and pyramids (14), and writes it with the smoothed coordinates and
the per-cell arrays mean_ratio, warpage and valid. Other linear cells (vertices, lines,
triangles, quads) are kept and move with their nodes; their mean_ratio and warpage are -1.
Nodes with a nonzero point-data value `fixed` never move; boundary nodes stay fixed unless
--free-boundary is given.

Options:
  --method M           getme (default), simultaneous, sequential, warpage, smart-laplace,
                       laplace
  --threads N          worker threads; 0 = all cores (default). Results do not depend on it.
  --max-iterations N   cap on the iterations of every phase (untangle, simultaneous,
                       sequential, Laplace)
  --free-boundary      let boundary nodes move too
  --literal            the paper's literal algorithm: no safeguards (docs/thin-layers.md)
  --no-untangle        refuse a mesh with invalid elements instead of untangling it
  --binary, --ascii    output encoding (default: the input's)
  --json               one JSON object per line on stdout: progress events, then the result
  --quiet              no progress or log lines on stderr (errors are still reported)
  --server HOST:PORT   smooth on a getme-server instead of in-process (same output; Ctrl-C
                       cancels the job on the server)
  --detach             with --server: queue the job, print its id and return; OUT.vtk may
                       be left out ('getme jobs fetch' writes it later)
  -h, --help           this text

Exit status: 0 success; 1 failure (input unreadable or not smoothable, output not written,
server error: "getme: CODE: message"); 2 usage error; 130 interrupted (the output is not
written).
)";

const char kQualityUsage[] = R"(Usage: getme quality IN.vtk [options]

Reports the mean ratio quality (paper, Def. 3) of every volume element of a VTK legacy file:
counts and q_min / q_mean per element type and overall, invalid elements, warpage, and a
histogram of the mean ratio.

Options:
  --bins N      histogram bins (default 20)
  --threads N   worker threads; 0 = all cores (default)
  --json        one JSON object on stdout
  --server HOST:PORT  evaluate on a getme-server instead of in-process
  -h, --help    this text

Exit status: 0 success; 1 the file cannot be read or holds no volume elements, or the server
failed ("getme: CODE: message"); 2 usage error.
)";

const char kJobsUsage[] = R"(Usage: getme jobs ACTION [options]

Manages smoothing jobs on a getme-server (queued with 'getme smooth --server … --detach').

Actions:
  list                                 every job the server knows, newest first
  watch ID                             live progress until the job ends (Ctrl-C stops
                                       watching; the job goes on)
  cancel ID                            cancel a queued or running job
  fetch ID OUT.vtk --input IN.vtk      write IN.vtk with the job's smoothed coordinates to
                                       OUT.vtk (the result can be fetched once)

Options:
  --server HOST:PORT   the server (default 127.0.0.1:50051)
  --input IN.vtk       fetch: the file the job was submitted from
  --binary, --ascii    fetch: output encoding (default: the input's)
  --json               JSON objects on stdout (one per job, event or result)
  -h, --help           this text

Exit status: 0 success (watch: the job succeeded); 1 failure or the watched job failed or was
cancelled ("getme: CODE: message"); 2 usage error; 130 interrupted.
)";

namespace {

// A flag: whether it takes a value, and what to do with it.
struct FlagSpec {
  bool takes_value;
  std::function<absl::Status(const std::string& value)> apply;
};

// Walks `args`: "--name value", "--name=value", positionals (everything after "--" too).
absl::Status ParseArguments(absl::string_view command, const std::vector<std::string>& args,
                            const std::map<std::string, FlagSpec>& flags,
                            std::vector<std::string>& positionals, bool& help) {
  bool only_positionals = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (only_positionals || arg.size() < 2 || arg[0] != '-') {
      positionals.push_back(arg);
      continue;
    }
    if (arg == "--") {
      only_positionals = true;
      continue;
    }
    if (arg == "-h" || arg == "--help") {
      help = true;
      continue;
    }
    const std::size_t equals = arg.find('=');
    const std::string name = arg.substr(0, equals);
    const auto flag = flags.find(name);
    if (flag == flags.end()) {
      return absl::InvalidArgumentError(absl::StrCat("unknown option '", name, "' for 'getme ",
                                                     command, "'; see 'getme ", command,
                                                     " --help'"));
    }
    std::string value;
    if (flag->second.takes_value) {
      if (equals != std::string::npos) {
        value = arg.substr(equals + 1);
      } else if (i + 1 < args.size()) {
        value = args[++i];
      } else {
        return absl::InvalidArgumentError(absl::StrCat("option ", name, " needs a value"));
      }
    } else if (equals != std::string::npos) {
      return absl::InvalidArgumentError(absl::StrCat("option ", name, " takes no value"));
    }
    if (absl::Status status = flag->second.apply(value); !status.ok()) return status;
  }
  return absl::OkStatus();
}

template <typename Int>
std::function<absl::Status(const std::string&)> IntegerFlag(absl::string_view name, Int& target,
                                                            Int min, Int max) {
  return [name = std::string(name), &target, min, max](const std::string& value) {
    Int parsed = 0;
    if (!absl::SimpleAtoi(value, &parsed) || parsed < min || parsed > max) {
      return absl::InvalidArgumentError(absl::StrCat("option ", name, " expects an integer in [",
                                                     min, ", ", max, "], got '", value, "'"));
    }
    target = parsed;
    return absl::OkStatus();
  };
}

std::function<absl::Status(const std::string&)> SetTrue(bool& target) {
  return [&target](const std::string&) {
    target = true;
    return absl::OkStatus();
  };
}

constexpr int kMaxThreads = 1024;

// HOST:PORT, [IPv6]:PORT, or any other gRPC target with a scheme (unix:/path, dns:///host:port).
std::function<absl::Status(const std::string&)> ServerFlag(std::string& target) {
  return [&target](const std::string& value) {
    const bool has_scheme =
        value.find(":/") != std::string::npos || absl::StartsWith(value, "unix:");
    const std::size_t colon = value.rfind(':');
    if (value.empty() ||
        (!has_scheme && (colon == std::string::npos || colon == 0 || colon + 1 == value.size()))) {
      return absl::InvalidArgumentError(absl::StrCat(
          "option --server expects HOST:PORT (e.g. 127.0.0.1:50051), got '", value, "'"));
    }
    target = value;
    return absl::OkStatus();
  };
}

}  // namespace

absl::StatusOr<SmoothCommandOptions> ParseSmoothArguments(const std::vector<std::string>& args) {
  SmoothCommandOptions options;
  std::int64_t max_iterations = 0;
  bool binary = false;
  bool ascii = false;
  const std::map<std::string, FlagSpec> flags = {
      {"--method",
       {true,
        [&](const std::string& value) -> absl::Status {
          absl::StatusOr<Method> method = ParseMethod(value);
          if (!method.ok()) return method.status();
          options.method = *method;
          return absl::OkStatus();
        }}},
      {"--threads", {true, IntegerFlag<int>("--threads", options.threads, 0, kMaxThreads)}},
      {"--max-iterations",
       {true,
        IntegerFlag<std::int64_t>("--max-iterations", max_iterations, 1, std::int64_t{1} << 40)}},
      {"--free-boundary", {false, SetTrue(options.free_boundary)}},
      {"--literal", {false, SetTrue(options.literal)}},
      {"--no-untangle", {false, SetTrue(options.no_untangle)}},
      {"--binary", {false, SetTrue(binary)}},
      {"--ascii", {false, SetTrue(ascii)}},
      {"--json", {false, SetTrue(options.json)}},
      {"--quiet", {false, SetTrue(options.quiet)}},
      {"--server", {true, ServerFlag(options.server)}},
      {"--detach", {false, SetTrue(options.detach)}},
  };
  std::vector<std::string> positionals;
  if (absl::Status status = ParseArguments("smooth", args, flags, positionals, options.help);
      !status.ok()) {
    return status;
  }
  if (options.help) return options;
  if (binary && ascii) return absl::InvalidArgumentError("--binary and --ascii exclude each other");
  if (binary) options.encoding = formats::VtkEncoding::kBinary;
  if (ascii) options.encoding = formats::VtkEncoding::kAscii;
  if (max_iterations > 0) options.max_iterations = max_iterations;
  if (options.detach && options.server.empty()) {
    return absl::InvalidArgumentError("--detach needs --server HOST:PORT (a job to detach from)");
  }
  if (options.detach && positionals.size() == 1) {
    options.input = positionals[0];
    return options;
  }
  if (positionals.size() != 2) {
    return absl::InvalidArgumentError(
        absl::StrCat("'getme smooth' needs an input and an output file (IN.vtk OUT.vtk), got ",
                     positionals.size(), " file argument", positionals.size() == 1 ? "" : "s",
                     "; see 'getme smooth --help'"));
  }
  options.input = positionals[0];
  options.output = positionals[1];
  return options;
}

absl::StatusOr<QualityCommandOptions> ParseQualityArguments(const std::vector<std::string>& args) {
  QualityCommandOptions options;
  const std::map<std::string, FlagSpec> flags = {
      {"--bins", {true, IntegerFlag<int>("--bins", options.bins, 1, 10000)}},
      {"--threads", {true, IntegerFlag<int>("--threads", options.threads, 0, kMaxThreads)}},
      {"--json", {false, SetTrue(options.json)}},
      {"--server", {true, ServerFlag(options.server)}},
  };
  std::vector<std::string> positionals;
  if (absl::Status status = ParseArguments("quality", args, flags, positionals, options.help);
      !status.ok()) {
    return status;
  }
  if (options.help) return options;
  if (positionals.size() != 1) {
    return absl::InvalidArgumentError(
        absl::StrCat("'getme quality' needs one input file (IN.vtk), got ", positionals.size(),
                     " file arguments; see 'getme quality --help'"));
  }
  options.input = positionals[0];
  return options;
}

absl::StatusOr<JobsCommandOptions> ParseJobsArguments(const std::vector<std::string>& args) {
  JobsCommandOptions options;
  bool binary = false;
  bool ascii = false;
  const std::map<std::string, FlagSpec> flags = {
      {"--server", {true, ServerFlag(options.server)}},
      {"--input",
       {true,
        [&](const std::string& value) {
          options.input = value;
          return absl::OkStatus();
        }}},
      {"--binary", {false, SetTrue(binary)}},
      {"--ascii", {false, SetTrue(ascii)}},
      {"--json", {false, SetTrue(options.json)}},
  };
  std::vector<std::string> positionals;
  if (absl::Status status = ParseArguments("jobs", args, flags, positionals, options.help);
      !status.ok()) {
    return status;
  }
  if (options.help) return options;
  if (binary && ascii) return absl::InvalidArgumentError("--binary and --ascii exclude each other");
  if (binary) options.encoding = formats::VtkEncoding::kBinary;
  if (ascii) options.encoding = formats::VtkEncoding::kAscii;
  if (positionals.empty()) {
    return absl::InvalidArgumentError(
        "'getme jobs' needs an action: list, watch ID, cancel ID or fetch ID OUT.vtk --input "
        "IN.vtk; see 'getme jobs --help'");
  }
  const std::string action = positionals.front();
  // Positionals each action takes after its name, and what they are.
  std::size_t expected = 0;
  const char* shape = "";
  if (action == "list") {
    options.action = JobsAction::kList;
    shape = "'getme jobs list'";
  } else if (action == "watch") {
    options.action = JobsAction::kWatch;
    expected = 1;
    shape = "'getme jobs watch ID'";
  } else if (action == "cancel") {
    options.action = JobsAction::kCancel;
    expected = 1;
    shape = "'getme jobs cancel ID'";
  } else if (action == "fetch") {
    options.action = JobsAction::kFetch;
    expected = 2;
    shape = "'getme jobs fetch ID OUT.vtk --input IN.vtk'";
  } else {
    return absl::InvalidArgumentError(
        absl::StrCat("unknown jobs action '", action, "'; expected list, watch, cancel or fetch"));
  }
  if (positionals.size() != expected + 1) {
    return absl::InvalidArgumentError(absl::StrCat(shape, " takes ", expected, " argument",
                                                   expected == 1 ? "" : "s", " after '", action,
                                                   "', got ", positionals.size() - 1));
  }
  if (expected >= 1) options.job_id = positionals[1];
  if (expected >= 2) options.output = positionals[2];
  if (options.action == JobsAction::kFetch && options.input.empty()) {
    return absl::InvalidArgumentError(
        "'getme jobs fetch' needs --input IN.vtk: the file the job was submitted from (the "
        "server returns coordinates only)");
  }
  return options;
}

SmoothingParams ToSmoothingParams(const SmoothCommandOptions& options) {
  SmoothingParams params;
  params.method = options.method;
  params.threads = options.threads;
  params.fix_boundary = !options.free_boundary;
  params.untangle = !options.no_untangle;
  if (options.literal) params.UseLiteralPaperAlgorithm();
  if (options.max_iterations) {
    params.untangle_max_iterations = *options.max_iterations;
    params.simultaneous_max_iterations = *options.max_iterations;
    params.sequential_max_iterations = *options.max_iterations;
    params.laplace_max_iterations = *options.max_iterations;
  }
  return params;
}

}  // namespace getme::cli
