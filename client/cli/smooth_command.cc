#include "cli/smooth_command.h"

#include <unistd.h>

#include <csignal>
#include <cstdio>

#include "absl/strings/str_cat.h"
#include "cli/failure.h"
#include "cli/json_events.h"
#include "cli/progress_printer.h"
#include "cli/text_reports.h"
#include "formats/vtk_mesh.h"
#include "formats/vtk_reader.h"
#include "formats/vtk_writer.h"
#include "getme/smoother.h"
#include "spdlog/spdlog.h"

namespace getme::cli {
namespace {

// The token SIGINT cancels. CancellationToken::Cancel is a relaxed store to a lock-free atomic,
// which is safe in a signal handler.
CancellationToken* interrupt_token = nullptr;

extern "C" void CancelOnInterrupt(int /*signal*/) {
  if (interrupt_token != nullptr) interrupt_token->Cancel();
}

// Routes SIGINT to `token` while in scope.
class InterruptScope {
 public:
  explicit InterruptScope(CancellationToken& token) {
    interrupt_token = &token;
    previous_ = std::signal(SIGINT, CancelOnInterrupt);
  }
  ~InterruptScope() {
    std::signal(SIGINT, previous_);
    interrupt_token = nullptr;
  }
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

 private:
  void (*previous_)(int);
};

absl::Status WithInput(const std::string& input, const absl::Status& status) {
  return absl::Status(status.code(), absl::StrCat(input, ": ", status.message()));
}

}  // namespace

int RunSmoothCommand(const SmoothCommandOptions& options) {
  const auto fail = [&](const absl::Status& status, int exit_status) {
    return ReportFailure(status, options.json, exit_status);
  };
  absl::StatusOr<formats::VtkFile> file = formats::ReadVtkFile(options.input);
  if (!file.ok()) return fail(file.status(), kExitFailure);
  absl::StatusOr<formats::VtkMesh> converted = formats::ToMesh(*file);
  if (!converted.ok()) return fail(WithInput(options.input, converted.status()), kExitFailure);
  Mesh& mesh = converted->mesh;

  SmoothReport report;
  report.input = options.input;
  report.output = options.output;
  report.method = options.method;
  report.nodes = mesh.node_count();
  for (const ElementType type : kAllElementTypes) {
    report.elements_by_type[TypeIndex(type)] = mesh.element_count(type);
  }
  report.passthrough_cells = file->cells.size() - mesh.element_count();
  std::int64_t fixed_nodes = 0;
  for (const std::uint8_t fixed : mesh.fixed_flags()) fixed_nodes += fixed != 0 ? 1 : 0;
  spdlog::info("read {}: {} nodes, {} elements, {} passthrough cells, {} fixed nodes",
               options.input, mesh.node_count(), mesh.element_count(), report.passthrough_cells,
               fixed_nodes);

  const SmoothingParams params = ToSmoothingParams(options);
  if (absl::Status status = params.Validate(); !status.ok()) return fail(status, kExitUsage);

  ProgressPrinter printer(stderr, isatty(fileno(stderr)) != 0);
  const ProgressCallback progress = [&](const ProgressEvent& event) {
    if (options.json) {
      std::printf("%s\n", ProgressEventJson(event).c_str());
      std::fflush(stdout);
    } else if (!options.quiet) {
      printer.OnEvent(event);
    }
  };
  CancellationToken cancel;
  absl::StatusOr<SmoothingResult> result;
  {
    InterruptScope interrupt(cancel);
    result = Smooth(mesh, params, progress, &cancel);
  }
  printer.Finish();
  if (!result.ok()) {
    if (result.status().code() == absl::StatusCode::kCancelled) {
      return fail(
          absl::CancelledError(absl::StrCat("interrupted; ", options.output, " was not written")),
          kExitInterrupted);
    }
    return fail(WithInput(options.input, result.status()), kExitFailure);
  }
  report.result = *std::move(result);

  if (absl::Status status = formats::UpdateFromMesh(mesh, converted->cell_elements, *file);
      !status.ok()) {
    return fail(status, kExitFailure);
  }
  const formats::VtkEncoding encoding = options.encoding.value_or(file->encoding);
  if (absl::Status status = formats::WriteVtkFile(options.output, *file, encoding); !status.ok()) {
    return fail(status, kExitFailure);
  }
  spdlog::info("wrote {} ({})", options.output,
               encoding == formats::VtkEncoding::kBinary ? "binary" : "ascii");

  if (options.json) {
    std::printf("%s\n", SmoothResultJson(report).c_str());
  } else {
    std::fputs(FormatSmoothSummary(report).c_str(), stdout);
  }
  std::fflush(stdout);
  return kExitSuccess;
}

}  // namespace getme::cli
