#include "cli/remote_commands.h"

#include <unistd.h>

#include <cstdio>

#include "absl/strings/str_cat.h"
#include "cli/failure.h"
#include "cli/interrupt_flag.h"
#include "cli/json_events.h"
#include "cli/json_output.h"
#include "cli/progress_printer.h"
#include "cli/remote_output.h"
#include "cli/text_reports.h"
#include "formats/vtk_cell_type.h"
#include "formats/vtk_reader.h"
#include "remote/smoother_client.h"
#include "remote/wire_conversion.h"
#include "remote/wire_mesh.h"
#include "spdlog/spdlog.h"

namespace getme::cli {
namespace {

absl::Status WithInput(const std::string& input, const absl::Status& status) {
  return absl::Status(status.code(), absl::StrCat(input, ": ", status.message()));
}

int SubmitDetached(remote::SmootherClient& client, const remote::VtkWireMesh& sent,
                   const remote::SmoothJobOptions& job, const SmoothCommandOptions& options) {
  absl::StatusOr<v1::Job> submitted = client.SubmitJob(sent.mesh, job);
  if (!submitted.ok()) return ReportRemoteFailure(submitted.status(), options.json, kExitFailure);
  if (options.json) {
    std::printf("%s\n", JobJson(*submitted).c_str());
  } else {
    std::printf("%s\n", submitted->job_id().c_str());
  }
  std::fflush(stdout);
  spdlog::info("queued job {} on {}; 'getme jobs watch {} --server {}' follows it",
               submitted->job_id(), options.server, submitted->job_id(), options.server);
  return kExitSuccess;
}

}  // namespace

int RunRemoteSmoothCommand(const SmoothCommandOptions& options) {
  const auto fail = [&](const absl::Status& status, int exit_status) {
    return ReportFailure(status, options.json, exit_status);
  };
  absl::StatusOr<formats::VtkFile> file = formats::ReadVtkFile(options.input);
  if (!file.ok()) return fail(file.status(), kExitFailure);
  absl::StatusOr<remote::VtkWireMesh> sent = remote::ToWireMesh(*file);
  if (!sent.ok()) return fail(WithInput(options.input, sent.status()), kExitFailure);

  const SmoothingParams params = ToSmoothingParams(options);
  if (absl::Status status = params.Validate(); !status.ok()) return fail(status, kExitUsage);
  remote::SmoothJobOptions job;
  job.parameters = remote::ToWireParameters(params);
  job.result_options.set_coordinates_only(true);
  spdlog::info("read {}: {} nodes, {} volume elements; smoothing on {}", options.input,
               file->point_count(), sent->element_cells.size(), options.server);

  remote::SmootherClient client(remote::SmootherClient::CreateChannel(options.server));
  if (options.detach) return SubmitDetached(client, *sent, job, options);

  ProgressPrinter printer(stderr, isatty(fileno(stderr)) != 0);
  const remote::ProgressHandler progress = [&](const v1::ProgressEvent& wire_event) {
    // The job's closing marker repeats the state of the last phase end; it is not an engine
    // event, and local mode has no such line.
    if (wire_event.final() && !wire_event.phase_done()) return;
    const ProgressEvent event = remote::FromWireProgress(wire_event);
    if (options.json) {
      std::printf("%s\n", ProgressEventJson(event).c_str());
      std::fflush(stdout);
    } else if (!options.quiet) {
      printer.OnEvent(event);
    }
  };
  absl::StatusOr<remote::RemoteSmoothResult> result;
  bool interrupted = false;
  {
    InterruptFlagScope interrupt;
    remote::CallOptions call;
    call.cancel = &interrupt.flag();
    result = client.Smooth(sent->mesh, job, progress, call);
    interrupted = interrupt.interrupted();
  }
  printer.Finish();
  if (!result.ok()) {
    if (interrupted && result.status().code() == absl::StatusCode::kCancelled) {
      return fail(absl::CancelledError(absl::StrCat("interrupted; the job was cancelled on ",
                                                    options.server, " and ", options.output,
                                                    " was not written")),
                  kExitInterrupted);
    }
    return ReportRemoteFailure(result.status(), options.json, kExitFailure);
  }
  const SmoothReport report = MakeRemoteSmoothReport(options.input, options.output, options.method,
                                                     *file, *sent, result->result);
  if (absl::Status status = WriteSmoothedFile(remote::CoordinatesOf(result->mesh), options.output,
                                              options.encoding, *file);
      !status.ok()) {
    return fail(status, kExitFailure);
  }
  if (options.json) {
    std::printf("%s\n", SmoothResultJson(report).c_str());
  } else {
    std::fputs(FormatSmoothSummary(report).c_str(), stdout);
  }
  std::fflush(stdout);
  return kExitSuccess;
}

int RunRemoteQualityCommand(const QualityCommandOptions& options) {
  absl::StatusOr<formats::VtkFile> file = formats::ReadVtkFile(options.input);
  if (!file.ok()) return ReportFailure(file.status(), options.json, kExitFailure);
  absl::StatusOr<remote::VtkWireMesh> sent = remote::ToWireMesh(*file);
  if (!sent.ok()) {
    return ReportFailure(WithInput(options.input, sent.status()), options.json, kExitFailure);
  }
  remote::SmootherClient client(remote::SmootherClient::CreateChannel(options.server));
  absl::StatusOr<v1::QualityReport> wire_report =
      client.EvaluateQuality(sent->mesh, static_cast<std::uint32_t>(options.bins));
  if (!wire_report.ok()) {
    return ReportRemoteFailure(wire_report.status(), options.json, kExitFailure);
  }
  QualityReport report;
  report.input = options.input;
  report.nodes = file->point_count();
  report.passthrough_cells =
      file->cells.size() - static_cast<std::int64_t>(sent->element_cells.size());
  report.quality = remote::FromWireQuality(*wire_report);
  // The server numbers elements by type (mesh.proto); report them as the local mode does: element
  // ids in file order of the volume cells, and the file's cell numbers.
  std::vector<ElementId> file_order_ids(file->cells.size(), -1);
  ElementId next_id = 0;
  for (std::int64_t cell = 0; cell < file->cells.size(); ++cell) {
    if (formats::ElementTypeOfCell(file->cells.types[cell])) file_order_ids[cell] = next_id++;
  }
  for (ElementId& element : report.quality.first_invalid) {
    if (element < 0 || element >= static_cast<ElementId>(sent->element_cells.size())) continue;
    const std::int64_t cell = sent->element_cells[element];
    report.first_invalid_cells.push_back(cell);
    element = file_order_ids[cell];
  }
  if (options.json) {
    std::printf("%s\n", QualityReportJson(report).c_str());
  } else {
    std::fputs(FormatQualityReport(report).c_str(), stdout);
  }
  std::fflush(stdout);
  return kExitSuccess;
}

}  // namespace getme::cli
