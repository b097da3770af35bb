#include "cli/cli_options.h"

#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "cmdline/flag_parser.h"
#include "cmdline/smoothing_flags.h"

namespace getme::cli {

const char kMainUsage[] =
    R"(getme: GETMe smoothing of mixed volume meshes (tetrahedra, hexahedra, pyramids, prisms)

Usage:
  getme smooth IN OUT [options]        smooth a mesh file (.vtk .vtu .msh .mesh .su2 .exo .cgns)
  getme quality IN [options]           report the element quality of a mesh
  getme report IN OUT [options]        draw quality histograms and q against time
  getme convert IN OUT [options]       write a mesh in another format, unchanged
  getme jobs list|watch|cancel|fetch   manage jobs on a getme-server
  getme --help                         this text
  getme --version                      the version

Run 'getme <command> --help' for the options of a command.
)";

const char kSmoothUsage[] = R"(Usage: getme smooth IN OUT [options]

Smooths the tetrahedra, hexahedra, prisms (wedges) and pyramids of a mesh file and writes it
with the smoothed coordinates and the per-element arrays mean_ratio, warpage and valid (cell
data; Gmsh: $ElementData; MEDIT: OUT.sol; SU2 cannot hold them). Formats, by extension or
--format: .vtk (VTK legacy, ASCII or BINARY), .vtu (VTK XML), .msh (Gmsh 2.2 and 4.1, ASCII or
binary), .mesh (MEDIT), .su2 (SU2 native), .cgns (CGNS, HDF5 or ADF; written as HDF5, the
quality as cell-centred solution fields), .exo .e .ex2 .g (Exodus II; the quality as element
variables), an OpenFOAM polyMesh directory (IN a case or its
constant/polyMesh; OUT with --format openfoam, an existing directory, or any path without
extension when IN is OpenFOAM, is a case: OUT/constant/polyMesh; only the points file changes;
polyhedral cells stay fixed).
Surface cells, lines and vertices are kept with their tags and move with their nodes (their
mean_ratio and warpage are -1), as is every other array of the input. Nodes with a nonzero
point array `fixed` (MEDIT: RequiredVertices) never move; boundary nodes stay fixed unless
--boundary free (or --free-boundary) is given, or slide along the input's surface with
--boundary slide.

Options:
  --method M           getme (default), simultaneous, sequential, warpage, smart-laplace,
                       laplace
  --threads N          worker threads; 0 = all cores (default). Results do not depend on it.
  --max-iterations N   cap on the iterations of every phase (untangle, simultaneous,
                       sequential, Laplace; polish: sweeps and worst-cluster rounds)
  --boundary B         fixed (default): boundary nodes stay; free: they move like the others;
                       slide: they move along the input's own surface, nodes on feature
                       edges along their edge, corners stay (docs/boundary.md)
  --free-boundary      the same as --boundary free
  --feature-angle DEG  with --boundary slide: faces meeting at more than DEG degrees (default
                       45) have a feature edge between them
  --keep-layers        boundary-layer columns (prisms or hexahedra stacked on a wall face,
                       thinner than wide) keep every layer's height, its distance from the
                       wall, while their skew is smoothed; needs --boundary fixed or slide
                       (docs/boundary.md#layers)
  --literal            the paper's literal algorithm: no safeguards (docs/thin-layers.md)
  --no-untangle        refuse a mesh with invalid elements instead of untangling it
  --untangle-boundary  while untangling, let the boundary nodes of invalid elements move
                       (nodes marked fixed never do): for an inverted corner whose nodes are
                       all on the boundary (docs/untangling.md)
  --no-polish          end --method getme after the sequential substep: no polish stage,
                       which otherwise raises q_mean to the global optimiser's level
                       without lowering q_min (docs/quality.md#polish)
  --sequential-batch N sequential picks per batch, evaluated in parallel (default 128); 1 picks
                       one element at a time, as the paper (docs/parallel-sequential.md)
  --fix-physical G     keep the nodes of group G fixed: a Gmsh physical group by name, tag or
                       DIM:TAG, an SU2 marker, OpenFOAM patch or CGNS boundary condition or
                       family by name; a number also matches
                       gmsh:physical / medit:ref / su2:tag cell data. Exodus II: a node
                       set, side set or element block by name or id. Repeatable.
  --fix-surfaces       keep the nodes of every surface cell, line and vertex fixed
  --input-format F     read IN as F: vtk, vtu, msh, mesh, su2, cgns, exodus, openfoam
                       (default: by extension, a directory as openfoam, else content)
  --format F           write OUT as F: vtk, vtu, msh (the input's version, else 4.1), msh2,
                       msh4, mesh, su2, cgns, exodus, openfoam (default: by OUT's extension)
  --binary, --ascii    output encoding (default: the input's)
  --compress           .vtu: zlib-compressed arrays
  --trace FILE         record the progress events and the result as JSON lines (for
                       'getme report --trace')
  --json               one JSON object per line on stdout: progress events, then the result
  --quiet              no progress or log lines on stderr (errors are still reported)
  --server HOST:PORT   smooth on a getme-server instead of in-process (same output; Ctrl-C
                       cancels the job on the server)
  --detach             with --server: queue the job, print its id and return; OUT.vtk may
                       be left out ('getme jobs fetch' writes it later)
  --token-file FILE    with --server: send the bearer token in FILE to a server with --auth_tokens_file
                       (default: the GETME_TOKEN environment variable)
  --tls-ca FILE        connect over TLS, trusting the server certificate this PEM CA signed
  --tls-cert FILE, --tls-key FILE
                       client certificate and key (PEM) for a server that requires one
  -h, --help           this text

Exit status: 0 success; 1 failure (input unreadable or not smoothable, output not written,
server error: "getme: CODE: message", e.g. UNAUTHENTICATED without a valid token); 2 usage
error; 130 interrupted (the output is not written).
)";

const char kQualityUsage[] = R"(Usage: getme quality IN [options]

Reports the mean ratio quality (paper, Def. 3) of every volume element of a mesh file (.vtk,
.vtu, .msh, .mesh): counts and q_min / q_mean per element type and overall, invalid elements,
warpage, and a histogram of the mean ratio.

Options:
  --bins N      histogram bins (default 20)
  --input-format F  read IN as F: vtk, vtu, msh, mesh, su2, cgns, exodus, openfoam
                    (default: by extension, a directory as openfoam, else content)
  --threads N   worker threads; 0 = all cores (default)
  --json        one JSON object on stdout
  --server HOST:PORT  evaluate on a getme-server instead of in-process
  --token-file FILE    with --server: send the bearer token in FILE to a server with --auth_tokens_file
                       (default: the GETME_TOKEN environment variable)
  --tls-ca FILE        connect over TLS, trusting the server certificate this PEM CA signed
  --tls-cert FILE, --tls-key FILE
                       client certificate and key (PEM) for a server that requires one
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
  fetch ID OUT --input IN              write IN with the job's smoothed coordinates to OUT
                                       (the result can be fetched once)

Options:
  --server HOST:PORT   the server (default 127.0.0.1:50051)
  --input IN           fetch: the file the job was submitted from
  --input-format F, --format F, --binary, --ascii, --compress
                       fetch: as for 'getme smooth')
  --json               JSON objects on stdout (one per job, event or result)
  --token-file FILE    send the bearer token in FILE to a server with --auth_tokens_file
                       (default: the GETME_TOKEN environment variable)
  --tls-ca FILE        connect over TLS, trusting the server certificate this PEM CA signed
  --tls-cert FILE, --tls-key FILE
                       client certificate and key (PEM) for a server that requires one
  -h, --help           this text

Exit status: 0 success (watch: the job succeeded); 1 failure or the watched job failed or was
cancelled ("getme: CODE: message"); 2 usage error; 130 interrupted.
)";

const char kReportUsage[] = R"(Usage: getme report IN OUT [options]

Draws what the paper's Figs. 7, 11 and 15 show: the histogram of the element mean ratio of IN
(before smoothing) and OUT (after); and, given a trace recorded with 'getme smooth --trace FILE'
(or the --json lines of 'getme smooth'), what Figs. 8, 12 and 16 show: q_min and q_mean against
time, each phase marked. Plots with gnuplot (Debian package gnuplot-nox).

Options:
  --trace FILE          progress events as JSON lines
  -o, --output FILE     the picture (default: OUT without its extension + "-report.svg")
  --format F            svg or png (default: from --output's extension, else svg);
                        also --picture-format
  --bins N              histogram bins (default 20)
  --by-iteration        x axis: progress events in order instead of seconds
  --title TEXT          a title above the plots
  --data FILE           also write the plotted numbers as tab-separated text
  --input-format F      read IN and OUT as F (default: by extension, else content)
  -h, --help            this text

Exit status: 0 success; 1 a file cannot be read or gnuplot failed; 2 usage error.
)";

const char kConvertUsage[] = R"(Usage: getme convert IN OUT [options]

Writes the mesh of IN to OUT in the format OUT's extension (or --format) names, with every
cell, tag and array kept: .vtk (VTK legacy), .vtu (VTK XML), .msh (Gmsh 2.2 / 4.1), .mesh
(MEDIT), .su2 (SU2), .cgns (CGNS), .exo (Exodus II), an OpenFOAM polyMesh directory
(--format openfoam). Nothing is smoothed.

Options:
  --input-format F     read IN as F: vtk, vtu, msh, mesh, su2, cgns, exodus, openfoam
                       (default: by extension, a directory as openfoam, else content)
  --format F           write OUT as F: vtk, vtu, msh, msh2, msh4, mesh, su2, cgns, exodus,
                       openfoam
  --binary, --ascii    output encoding (default: the input's)
  --compress           .vtu: zlib-compressed arrays
  -h, --help           this text

Exit status: 0 success; 1 IN cannot be read or OUT cannot be written; 2 usage error.
)";

namespace {

using cmdline::FlagSpec;
using cmdline::IntegerFlag;
using cmdline::SetTrue;
using cmdline::StringFlag;

// Walks `args` (cmdline::ParseFlags): "--name value", "--name=value", positionals (everything
// after "--" too); a flag not in `flags` is refused naming the command.
absl::Status ParseArguments(absl::string_view command, const std::vector<std::string>& args,
                            const cmdline::FlagTable& flags, std::vector<std::string>& positionals,
                            bool& help) {
  cmdline::ParseRules rules;
  rules.positional = [&positionals](const std::string& arg) {
    positionals.push_back(arg);
    return absl::OkStatus();
  };
  rules.unknown = [command](const std::string& name) -> absl::StatusOr<FlagSpec> {
    return absl::InvalidArgumentError(absl::StrCat("unknown option '", name, "' for 'getme ",
                                                   command, "'; see 'getme ", command, " --help'"));
  };
  return cmdline::ParseFlags(args, flags, rules, help);
}

cmdline::FlagAction InputFormatFlag(std::optional<formats::FileFormat>& target) {
  return [&target](const std::string& value) -> absl::Status {
    absl::StatusOr<formats::FormatChoice> choice = formats::ParseFormatName(value);
    if (!choice.ok()) return choice.status();
    target = choice->format;
    return absl::OkStatus();
  };
}

// The flags every command that reads and writes mesh files takes. `binary` / `ascii` are
// resolved by ResolveFileFlags once all arguments are seen.
void AddFileFlags(FileOptions& files, bool& binary, bool& ascii, cmdline::FlagTable& flags) {
  flags["--input-format"] = {true, InputFormatFlag(files.input_format)};
  flags["--format"] = {true, [&files](const std::string& value) -> absl::Status {
                         absl::StatusOr<formats::FormatChoice> choice =
                             formats::ParseFormatName(value);
                         if (!choice.ok()) return choice.status();
                         files.output_format = *choice;
                         return absl::OkStatus();
                       }};
  flags["--binary"] = {false, SetTrue(binary)};
  flags["--ascii"] = {false, SetTrue(ascii)};
  flags["--compress"] = {false, SetTrue(files.compress)};
}

absl::Status ResolveFileFlags(bool binary, bool ascii, FileOptions& files) {
  if (binary && ascii) return absl::InvalidArgumentError("--binary and --ascii exclude each other");
  if (binary) files.encoding = formats::Encoding::kBinary;
  if (ascii) files.encoding = formats::Encoding::kAscii;
  return absl::OkStatus();
}

constexpr int kMaxThreads = 1024;

// HOST:PORT, [IPv6]:PORT, or any other gRPC target with a scheme (unix:/path, dns:///host:port).
cmdline::FlagAction ServerFlag(std::string& target) {
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

void AddAccessFlags(ServerAccessOptions& access, cmdline::FlagTable& flags) {
  flags["--token-file"] = {true, StringFlag(access.token_file)};
  flags["--tls-ca"] = {true, StringFlag(access.tls_ca)};
  flags["--tls-cert"] = {true, StringFlag(access.tls_cert)};
  flags["--tls-key"] = {true, StringFlag(access.tls_key)};
}

absl::Status CheckAccessFlags(const ServerAccessOptions& access, bool remote) {
  if (access.tls_cert.empty() != access.tls_key.empty()) {
    return absl::InvalidArgumentError(
        "--tls-cert and --tls-key go together (the client certificate and its key)");
  }
  if (access.any() && !remote) {
    return absl::InvalidArgumentError(
        "--token-file, --tls-ca, --tls-cert and --tls-key need --server HOST:PORT");
  }
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<SmoothCommandOptions> ParseSmoothArguments(const std::vector<std::string>& args) {
  SmoothCommandOptions options;
  std::int64_t max_iterations = 0;
  std::string boundary;  // --boundary, empty if not given
  bool feature_angle_given = false;
  bool binary = false;
  bool ascii = false;
  cmdline::FlagTable flags = {
      {"--method",
       {true,
        [&](const std::string& value) -> absl::Status {
          absl::StatusOr<Method> method = ParseMethod(value);
          if (!method.ok()) return method.status();
          options.smoothing.method = *method;
          return absl::OkStatus();
        }}},
      {"--threads",
       {true, IntegerFlag<int>("--threads", options.smoothing.threads, 0, kMaxThreads)}},
      {"--max-iterations",
       {true,
        IntegerFlag<std::int64_t>("--max-iterations", max_iterations, 1, std::int64_t{1} << 40)}},
      {"--free-boundary", {false, SetTrue(options.smoothing.free_boundary)}},
      {"--boundary",
       {true,
        [&](const std::string& value) -> absl::Status {
          if (value != "fixed" && value != "slide" && value != "free") {
            return absl::InvalidArgumentError(
                absl::StrCat("--boundary '", value, "': expected fixed, slide or free"));
          }
          boundary = value;
          return absl::OkStatus();
        }}},
      {"--feature-angle",
       {true,
        [&](const std::string& value) -> absl::Status {
          double angle = 0.0;
          if (!absl::SimpleAtod(value, &angle) || !(angle >= 0.0 && angle <= 180.0)) {
            return absl::InvalidArgumentError(
                absl::StrCat("--feature-angle '", value, "': expected degrees in [0, 180]"));
          }
          options.smoothing.feature_angle_degrees = angle;
          feature_angle_given = true;
          return absl::OkStatus();
        }}},
      {"--keep-layers", {false, SetTrue(options.smoothing.keep_layers)}},
      {"--literal", {false, SetTrue(options.smoothing.literal)}},
      {"--no-untangle", {false, SetTrue(options.smoothing.no_untangle)}},
      {"--no-polish", {false, SetTrue(options.smoothing.no_polish)}},
      {"--sequential-batch",
       {true, IntegerFlag<std::int64_t>("--sequential-batch", options.smoothing.sequential_batch, 1,
                                        65536)}},
      {"--untangle-boundary", {false, SetTrue(options.smoothing.untangle_boundary)}},
      {"--fix-physical",
       {true,
        [&](const std::string& value) {
          if (value.empty()) return absl::InvalidArgumentError("--fix-physical needs a group");
          options.fix_groups.push_back(value);
          return absl::OkStatus();
        }}},
      {"--fix-surfaces", {false, SetTrue(options.fix_surfaces)}},
      {"--trace", {true, StringFlag(options.trace)}},
      {"--json", {false, SetTrue(options.json)}},
      {"--quiet", {false, SetTrue(options.quiet)}},
      {"--server", {true, ServerFlag(options.server)}},
      {"--detach", {false, SetTrue(options.detach)}},
  };
  AddFileFlags(options.files, binary, ascii, flags);
  AddAccessFlags(options.access, flags);
  std::vector<std::string> positionals;
  if (absl::Status status = ParseArguments("smooth", args, flags, positionals, options.help);
      !status.ok()) {
    return status;
  }
  if (options.help) return options;
  if (absl::Status status = ResolveFileFlags(binary, ascii, options.files); !status.ok()) {
    return status;
  }
  if (max_iterations > 0) options.smoothing.max_iterations = max_iterations;
  if (!boundary.empty()) {
    if (options.smoothing.free_boundary && boundary != "free") {
      return absl::InvalidArgumentError(absl::StrCat("--free-boundary and --boundary ", boundary,
                                                     " contradict each other: give one"));
    }
    options.smoothing.free_boundary = boundary == "free";
    options.smoothing.slide_boundary = boundary == "slide";
  }
  if (feature_angle_given && !options.smoothing.slide_boundary) {
    return absl::InvalidArgumentError(
        "--feature-angle only shapes a sliding boundary: it needs --boundary slide");
  }
  if (options.smoothing.keep_layers && options.smoothing.free_boundary) {
    return absl::InvalidArgumentError(
        "--keep-layers measures layer heights from the input's walls, which a free boundary "
        "moves: use it with --boundary fixed or slide");
  }
  if (auto s = CheckAccessFlags(options.access, !options.server.empty()); !s.ok()) return s;
  if (options.detach && options.server.empty()) {
    return absl::InvalidArgumentError("--detach needs --server HOST:PORT (a job to detach from)");
  }
  if (options.detach && positionals.size() == 1) {
    options.input = positionals[0];
    return options;
  }
  if (positionals.size() != 2) {
    return absl::InvalidArgumentError(absl::StrCat(
        "'getme smooth' needs an input and an output file (IN OUT), got ", positionals.size(),
        " file argument", positionals.size() == 1 ? "" : "s", "; see 'getme smooth --help'"));
  }
  options.input = positionals[0];
  options.output = positionals[1];
  return options;
}

absl::StatusOr<QualityCommandOptions> ParseQualityArguments(const std::vector<std::string>& args) {
  QualityCommandOptions options;
  cmdline::FlagTable flags = {
      {"--bins", {true, IntegerFlag<int>("--bins", options.bins, 1, 10000)}},
      {"--threads", {true, IntegerFlag<int>("--threads", options.threads, 0, kMaxThreads)}},
      {"--json", {false, SetTrue(options.json)}},
      {"--server", {true, ServerFlag(options.server)}},
      {"--input-format", {true, InputFormatFlag(options.input_format)}},
  };
  AddAccessFlags(options.access, flags);
  std::vector<std::string> positionals;
  if (absl::Status status = ParseArguments("quality", args, flags, positionals, options.help);
      !status.ok()) {
    return status;
  }
  if (options.help) return options;
  if (auto s = CheckAccessFlags(options.access, !options.server.empty()); !s.ok()) return s;
  if (positionals.size() != 1) {
    return absl::InvalidArgumentError(
        absl::StrCat("'getme quality' needs one input file (IN), got ", positionals.size(),
                     " file arguments; see 'getme quality --help'"));
  }
  options.input = positionals[0];
  return options;
}

absl::StatusOr<JobsCommandOptions> ParseJobsArguments(const std::vector<std::string>& args) {
  JobsCommandOptions options;
  bool binary = false;
  bool ascii = false;
  cmdline::FlagTable flags = {
      {"--server", {true, ServerFlag(options.server)}},
      {"--input", {true, StringFlag(options.input)}},
      {"--json", {false, SetTrue(options.json)}},
  };
  AddFileFlags(options.files, binary, ascii, flags);
  AddAccessFlags(options.access, flags);
  std::vector<std::string> positionals;
  if (absl::Status status = ParseArguments("jobs", args, flags, positionals, options.help);
      !status.ok()) {
    return status;
  }
  if (options.help) return options;
  if (absl::Status status = ResolveFileFlags(binary, ascii, options.files); !status.ok()) {
    return status;
  }
  if (auto s = CheckAccessFlags(options.access, /*remote=*/true); !s.ok()) return s;
  if (positionals.empty()) {
    return absl::InvalidArgumentError(
        "'getme jobs' needs an action: list, watch ID, cancel ID or fetch ID OUT --input IN; "
        "see 'getme jobs --help'");
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
    shape = "'getme jobs fetch ID OUT --input IN'";
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
        "'getme jobs fetch' needs --input IN: the file the job was submitted from (the "
        "server returns coordinates only)");
  }
  return options;
}

absl::StatusOr<ReportCommandOptions> ParseReportArguments(const std::vector<std::string>& args) {
  ReportCommandOptions options;
  const auto picture_format = [&](const std::string& value) {
    if (value != "svg" && value != "png") {
      return absl::InvalidArgumentError(
          absl::StrCat("the picture format is svg or png, got '", value, "'"));
    }
    options.picture_format = value;
    return absl::OkStatus();
  };
  const cmdline::FlagTable flags = {
      {"--trace", {true, StringFlag(options.trace)}},
      {"--picture-format", {true, picture_format}},
      {"--format", {true, picture_format}},
      {"--output", {true, StringFlag(options.picture)}},
      {"-o", {true, StringFlag(options.picture)}},
      {"--bins", {true, IntegerFlag<int>("--bins", options.bins, 1, 1000)}},
      {"--by-iteration", {false, SetTrue(options.by_iteration)}},
      {"--title", {true, StringFlag(options.title)}},
      {"--data", {true, StringFlag(options.data)}},
      {"--input-format", {true, InputFormatFlag(options.input_format)}},
  };
  std::vector<std::string> positionals;
  if (absl::Status status = ParseArguments("report", args, flags, positionals, options.help);
      !status.ok()) {
    return status;
  }
  if (options.help) return options;
  if (positionals.size() != 2) {
    return absl::InvalidArgumentError(
        absl::StrCat("'getme report' needs the mesh before and after smoothing (IN OUT), got ",
                     positionals.size(), " file argument", positionals.size() == 1 ? "" : "s",
                     "; see 'getme report --help'"));
  }
  options.input = positionals[0];
  options.output = positionals[1];
  return options;
}

absl::StatusOr<ConvertCommandOptions> ParseConvertArguments(const std::vector<std::string>& args) {
  ConvertCommandOptions options;
  bool binary = false;
  bool ascii = false;
  cmdline::FlagTable flags;
  AddFileFlags(options.files, binary, ascii, flags);
  std::vector<std::string> positionals;
  if (absl::Status status = ParseArguments("convert", args, flags, positionals, options.help);
      !status.ok()) {
    return status;
  }
  if (options.help) return options;
  if (absl::Status status = ResolveFileFlags(binary, ascii, options.files); !status.ok()) {
    return status;
  }
  if (positionals.size() != 2) {
    return absl::InvalidArgumentError(absl::StrCat(
        "'getme convert' needs an input and an output file (IN OUT), got ", positionals.size(),
        " file argument", positionals.size() == 1 ? "" : "s", "; see 'getme convert --help'"));
  }
  options.input = positionals[0];
  options.output = positionals[1];
  return options;
}

SmoothingParams ToSmoothingParams(const SmoothCommandOptions& options) {
  return cmdline::ToSmoothingParams(options.smoothing);
}

}  // namespace getme::cli
