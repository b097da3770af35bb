#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "cli/cli_options.h"
#include "cli/mesh_files.h"
#include "cli/progress_printer.h"
#include "events/reports.h"
#include "events/trace_file.h"
#include "formats/mesh_document.h"
#include "getme/smoothing/progress.h"

namespace getme::cli {

// What `getme smooth` does before and around smoothing, in-process or on a server alike: the
// input read, the output resolved (before any work, so a bad name fails at once), the nodes
// the options fix, the trace opened.
struct SmoothRun {
  formats::MeshDocument document;
  std::optional<OutputTarget> output;      // absent for --detach without OUT
  std::vector<std::uint8_t> option_fixed;  // --fix-physical / --fix-surfaces; empty if neither
  std::unique_ptr<events::TraceFile> trace;
};

// Errors name the file or option; the caller reports them with exit status 1.
absl::StatusOr<SmoothRun> PrepareSmoothRun(const SmoothCommandOptions& options);

// Where progress events go: --json lines on stdout, the progress line on stderr (unless
// --quiet), and the --trace file.
class ProgressSink {
 public:
  ProgressSink(const SmoothCommandOptions& options, events::TraceFile* trace);
  void OnEvent(const ProgressEvent& event);
  // Ends a progress line left open.
  void Finish() { printer_.Finish(); }

 private:
  bool json_;
  bool quiet_;
  events::TraceFile* trace_;
  ProgressPrinter printer_;
};

// Writes the report (text or JSON) to stdout and the result line to the trace; closes the trace.
absl::Status FinishSmoothRun(const events::SmoothReport& report, bool json, SmoothRun& run);

}  // namespace getme::cli
