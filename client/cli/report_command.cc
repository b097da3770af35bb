#include "cli/report_command.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "absl/strings/str_cat.h"
#include "absl/strings/strip.h"
#include "cli/failure.h"
#include "cli/report_plot.h"
#include "cli/trace_reader.h"
#include "formats/file_io.h"
#include "formats/grid_mesh.h"
#include "formats/mesh_file.h"
#include "getme/mesh/mesh_quality.h"
#include "getme/parallel/thread_pool.h"
#include "spdlog/spdlog.h"

extern char** environ;

namespace getme::cli {
namespace {

absl::StatusOr<MeshQuality> EvaluateFile(const std::string& path,
                                         std::optional<formats::FileFormat> format, int bins) {
  absl::StatusOr<formats::MeshDocument> document = formats::ReadMeshDocument(path, format);
  if (!document.ok()) return document.status();
  absl::StatusOr<formats::GridMesh> converted = formats::GridToMesh(document->grid);
  if (!converted.ok()) {
    return absl::Status(converted.status().code(),
                        absl::StrCat(path, ": ", converted.status().message()));
  }
  ThreadPool pool(0);
  QualityOptions quality_options;
  quality_options.histogram_bins = bins;
  return EvaluateMeshQuality(converted->mesh, pool, quality_options);
}

std::string FileName(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

// OUT without its extension + "-report.<format>".
std::string DefaultPicturePath(const std::string& output, const std::string& format) {
  std::filesystem::path path(output);
  path.replace_extension();
  return absl::StrCat(path.string(), "-report.", format);
}

// A private directory for gnuplot's inputs, removed with the object.
class TemporaryDirectory {
 public:
  static absl::StatusOr<TemporaryDirectory> Create() {
    const char* base = std::getenv("TMPDIR");
    std::string pattern =
        absl::StrCat(base != nullptr && *base != '\0' ? base : "/tmp", "/getme-report-XXXXXX");
    if (mkdtemp(pattern.data()) == nullptr) {
      const int error = errno;
      return absl::ErrnoToStatus(error, "cannot create a temporary directory for gnuplot");
    }
    return TemporaryDirectory(pattern);
  }
  TemporaryDirectory(TemporaryDirectory&& other) noexcept : path_(std::move(other.path_)) {
    other.path_.clear();
  }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(TemporaryDirectory&&) = delete;
  ~TemporaryDirectory() {
    if (path_.empty()) return;
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::string& path() const { return path_; }

 private:
  explicit TemporaryDirectory(std::string path) : path_(std::move(path)) {}
  std::string path_;
};

// Runs `gnuplot script` (found on PATH) with its stderr in `log`; FailedPrecondition if gnuplot
// is not installed, Internal with gnuplot's messages if it fails.
absl::Status RunGnuplot(const std::string& script, const std::string& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  std::string program = "gnuplot";
  std::string script_argument = script;
  char* argv[] = {program.data(), script_argument.data(), nullptr};
  pid_t pid = 0;
  const int spawn_error = posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawn_error == ENOENT) {
    return absl::FailedPreconditionError(
        "gnuplot not found on PATH: 'getme report' draws with gnuplot (Debian package "
        "gnuplot-nox; scripts/setup.sh installs it)");
  }
  if (spawn_error != 0) return absl::ErrnoToStatus(spawn_error, "cannot start gnuplot");
  int wait_status = 0;
  while (waitpid(pid, &wait_status, 0) < 0) {
    if (errno != EINTR) return absl::ErrnoToStatus(errno, "waiting for gnuplot");
  }
  if (WIFEXITED(wait_status) && WEXITSTATUS(wait_status) == 0) return absl::OkStatus();
  absl::StatusOr<std::string> messages = formats::ReadFileBytes(log);
  return absl::InternalError(
      absl::StrCat("gnuplot failed: ", messages.ok() ? absl::StripAsciiWhitespace(*messages)
                                                     : absl::string_view("no output")));
}

}  // namespace

int RunReportCommand(const ReportCommandOptions& options) {
  const auto fail = [](const absl::Status& status) {
    return ReportFailure(status, /*json=*/false, kExitFailure);
  };
  std::string format = options.picture_format;
  if (format.empty()) {
    format = std::filesystem::path(options.picture).extension() == ".png" ? "png" : "svg";
  }
  const std::string picture =
      options.picture.empty() ? DefaultPicturePath(options.output, format) : options.picture;

  absl::StatusOr<MeshQuality> before =
      EvaluateFile(options.input, options.input_format, options.bins);
  if (!before.ok()) return fail(before.status());
  absl::StatusOr<MeshQuality> after =
      EvaluateFile(options.output, options.input_format, options.bins);
  if (!after.ok()) return fail(after.status());
  if (before->elements != after->elements) {
    return fail(absl::InvalidArgumentError(absl::StrCat(
        options.input, " has ", before->elements, " volume elements but ", options.output, " has ",
        after->elements, ": not the same mesh before and after smoothing")));
  }

  ReportData data;
  data.before_name = FileName(options.input);
  data.after_name = FileName(options.output);
  data.histogram_before = before->histogram;
  data.histogram_after = after->histogram;
  data.q_min_before = before->q_min;
  data.q_mean_before = before->q_mean;
  data.q_min_after = after->q_min;
  data.q_mean_after = after->q_mean;
  data.by_iteration = options.by_iteration;
  data.title = options.title;
  if (!options.trace.empty()) {
    absl::StatusOr<std::vector<TracePoint>> trace = ReadTrace(options.trace);
    if (!trace.ok()) return fail(trace.status());
    if (trace->empty()) {
      return fail(absl::InvalidArgumentError(
          absl::StrCat(options.trace,
                       ": no progress events (record one with 'getme smooth "
                       "--trace FILE')")));
    }
    data.trace = *std::move(trace);
  }

  const std::string table = ReportDataTable(data);
  if (!options.data.empty()) {
    if (absl::Status status = formats::WriteFileAtomically(options.data, table); !status.ok()) {
      return fail(status);
    }
  }
  absl::StatusOr<TemporaryDirectory> directory = TemporaryDirectory::Create();
  if (!directory.ok()) return fail(directory.status());
  const std::string data_path = directory->path() + "/report.tsv";
  const std::string script_path = directory->path() + "/report.gp";
  const std::string picture_temporary = directory->path() + "/picture." + format;
  for (const auto& [path, text] :
       {std::pair{data_path, table},
        std::pair{script_path, ReportGnuplotScript(data, data_path, format, picture_temporary)}}) {
    if (absl::Status status = formats::WriteFileAtomically(path, text); !status.ok()) {
      return fail(status);
    }
  }
  if (absl::Status status = RunGnuplot(script_path, directory->path() + "/gnuplot.log");
      !status.ok()) {
    return fail(status);
  }
  // gnuplot writes into the private directory; the picture appears under its name complete.
  absl::StatusOr<std::string> bytes = formats::ReadFileBytes(picture_temporary);
  if (!bytes.ok()) return fail(bytes.status());
  if (absl::Status status = formats::WriteFileAtomically(picture, *bytes); !status.ok()) {
    return fail(status);
  }
  spdlog::info("wrote {} ({}; q_mean {:.4f} → {:.4f}{})", picture, format, before->q_mean,
               after->q_mean,
               data.trace.empty() ? "" : absl::StrCat(", ", data.trace.size(), " progress events"));
  std::printf("%s\n", picture.c_str());
  return kExitSuccess;
}

}  // namespace getme::cli
