#include "cli/smooth_run.h"

#include <unistd.h>

#include <cstdio>

#include "absl/strings/str_cat.h"
#include "cli/text_reports.h"
#include "events/json_events.h"

namespace getme::cli {

absl::StatusOr<SmoothRun> PrepareSmoothRun(const SmoothCommandOptions& options) {
  SmoothRun run;
  absl::StatusOr<formats::MeshDocument> document = ReadInputMesh(options.input, options.files);
  if (!document.ok()) return document.status();
  run.document = *std::move(document);
  if (!options.output.empty()) {
    absl::StatusOr<OutputTarget> output =
        ResolveOutput(run.document, options.output, options.files);
    if (!output.ok()) return output.status();
    run.output = *std::move(output);
  }
  absl::StatusOr<std::vector<std::uint8_t>> fixed = FixedNodesFromOptions(run.document, options);
  if (!fixed.ok()) {
    return absl::Status(fixed.status().code(),
                        absl::StrCat(options.input, ": ", fixed.status().message()));
  }
  run.option_fixed = *std::move(fixed);
  if (!options.trace.empty()) {
    absl::StatusOr<std::unique_ptr<events::TraceFile>> trace =
        events::TraceFile::Open(options.trace);
    if (!trace.ok()) return trace.status();
    run.trace = *std::move(trace);
  }
  return run;
}

ProgressSink::ProgressSink(const SmoothCommandOptions& options, events::TraceFile* trace)
    : json_(options.json),
      quiet_(options.quiet),
      trace_(trace),
      printer_(stderr, isatty(fileno(stderr)) != 0) {}

void ProgressSink::OnEvent(const ProgressEvent& event) {
  if (json_ || trace_ != nullptr) {
    const std::string line = events::ProgressEventJson(event);
    if (trace_ != nullptr) trace_->WriteLine(line);
    if (json_) {
      std::printf("%s\n", line.c_str());
      std::fflush(stdout);
    }
  }
  if (!json_ && !quiet_) printer_.OnEvent(event);
}

absl::Status FinishSmoothRun(const events::SmoothReport& report, bool json, SmoothRun& run) {
  const std::string result_json = events::SmoothResultJson(report);
  if (json) {
    std::printf("%s\n", result_json.c_str());
  } else {
    std::fputs(FormatSmoothSummary(report).c_str(), stdout);
  }
  std::fflush(stdout);
  if (run.trace == nullptr) return absl::OkStatus();
  run.trace->WriteLine(result_json);
  return run.trace->Close();
}

}  // namespace getme::cli
