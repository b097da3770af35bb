#include "cli/remote_commands.h"

#include <cstdio>

#include "absl/strings/str_cat.h"
#include "cli/failure.h"
#include "cli/interrupt_scope.h"
#include "cli/remote_output.h"
#include "cli/server_access.h"
#include "cli/smooth_run.h"
#include "cli/text_reports.h"
#include "events/json_events.h"
#include "events/json_output.h"
#include "formats/mesh_file.h"
#include "formats/vtk_cell_type.h"
#include "getme_wire/engine_mesh.h"
#include "getme_wire/params.h"
#include "getme_wire/progress.h"
#include "getme_wire/reports.h"
#include "remote/grid_upload.h"
#include "remote/smoother_client.h"
#include "spdlog/spdlog.h"

namespace getme::cli {
namespace {

absl::Status WithInput(const std::string& input, const absl::Status& status) {
  return absl::Status(status.code(), absl::StrCat(input, ": ", status.message()));
}

int SubmitDetached(remote::SmootherClient& client, const remote::GridWireMesh& sent,
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

// Adds the nodes the options fix to the wire mesh's fixed list (those not on it already).
void AddFixedNodes(const std::vector<std::uint8_t>& option_fixed, v1::Mesh& mesh) {
  if (option_fixed.empty()) return;
  std::vector<std::uint8_t> listed(option_fixed.size(), 0);
  for (const std::uint32_t node : mesh.fixed_nodes()) {
    if (node < listed.size()) listed[node] = 1;
  }
  for (std::size_t node = 0; node < option_fixed.size(); ++node) {
    if (option_fixed[node] != 0 && listed[node] == 0) {
      mesh.add_fixed_nodes(static_cast<std::uint32_t>(node));
    }
  }
}

}  // namespace

int RunRemoteSmoothCommand(const SmoothCommandOptions& options) {
  const auto fail = [&](const absl::Status& status, int exit_status) {
    return ReportFailure(status, options.json, exit_status);
  };
  const SmoothingParams params = ToSmoothingParams(options);
  if (absl::Status status = params.Validate(); !status.ok()) return fail(status, kExitUsage);
  absl::StatusOr<SmoothRun> run = PrepareSmoothRun(options);
  if (!run.ok()) return fail(run.status(), kExitFailure);
  absl::StatusOr<remote::GridWireMesh> sent = remote::ToWireMesh(run->document.grid);
  if (!sent.ok()) return fail(WithInput(options.input, sent.status()), kExitFailure);
  AddFixedNodes(run->option_fixed, sent->mesh);
  if (params.slide_boundary) {
    const std::vector<formats::TaggedFace> tagged = formats::TaggedSurfaceFaces(run->document);
    if (absl::Status status = remote::AddSurfaceGroups(tagged, sent->mesh); !status.ok()) {
      return fail(WithInput(options.input, status), kExitFailure);
    }
  }

  remote::SmoothJobOptions job;
  job.parameters = wire::ToWireParameters(params);
  job.result_options.set_coordinates_only(true);
  spdlog::info("read {} ({}): {} nodes, {} volume elements; smoothing on {}", options.input,
               formats::FormatDisplayName(run->document.format), run->document.grid.point_count(),
               sent->element_cells.size(), options.server);

  absl::StatusOr<std::shared_ptr<grpc::Channel>> channel =
      OpenServerChannel(options.server, options.access);
  if (!channel.ok()) return fail(channel.status(), kExitFailure);
  remote::SmootherClient client(*std::move(channel));
  if (options.detach) return SubmitDetached(client, *sent, job, options);

  ProgressSink sink(options, run->trace.get());
  const remote::ProgressHandler progress = [&](const v1::ProgressEvent& wire_event) {
    // The job's closing marker repeats the state of the last phase end; it is not an engine
    // event, and local mode has no such line.
    if (wire_event.final() && !wire_event.phase_done()) return;
    if (wire_event.restarted()) {
      AnnounceRestart(wire_event, options.json);
      return;
    }
    sink.OnEvent(wire::FromWireProgress(wire_event));
  };
  absl::StatusOr<remote::RemoteSmoothResult> result;
  bool interrupted = false;
  {
    InterruptScope interrupt;
    remote::CallOptions call;
    call.cancel = &interrupt.flag();
    result = client.Smooth(sent->mesh, job, progress, call);
    interrupted = interrupt.interrupted();
  }
  sink.Finish();
  if (!result.ok()) {
    if (interrupted && result.status().code() == absl::StatusCode::kCancelled) {
      return fail(absl::CancelledError(absl::StrCat("interrupted; the job was cancelled on ",
                                                    options.server, " and ", options.output,
                                                    " was not written")),
                  kExitInterrupted);
    }
    return ReportRemoteFailure(result.status(), options.json, kExitFailure);
  }
  const events::SmoothReport report =
      MakeRemoteSmoothReport(options.input, options.output, options.smoothing.method,
                             run->document.grid, *sent, result->result);
  if ((params.slide_boundary || params.keep_layers) &&
      result->result.boundary() == v1::BOUNDARY_UNSPECIFIED) {
    // A server that predates the field ignored the boundary it did not know and held it.
    spdlog::warn("{} does not know --boundary slide or --keep-layers: it kept the boundary fixed",
                 options.server);
  }
  if (absl::Status status =
          WriteSmoothedFile(wire::CoordinatesOf(result->mesh), *run->output, run->document);
      !status.ok()) {
    return fail(status, kExitFailure);
  }
  if (absl::Status status = FinishSmoothRun(report, options.json, *run); !status.ok()) {
    return fail(status, kExitFailure);
  }
  return kExitSuccess;
}

int RunRemoteQualityCommand(const QualityCommandOptions& options) {
  absl::StatusOr<formats::MeshDocument> document =
      formats::ReadMeshDocument(options.input, options.input_format);
  if (!document.ok()) return ReportFailure(document.status(), options.json, kExitFailure);
  const formats::UnstructuredGrid* file = &document->grid;
  absl::StatusOr<remote::GridWireMesh> sent = remote::ToWireMesh(*file);
  if (!sent.ok()) {
    return ReportFailure(WithInput(options.input, sent.status()), options.json, kExitFailure);
  }
  absl::StatusOr<std::shared_ptr<grpc::Channel>> channel =
      OpenServerChannel(options.server, options.access);
  if (!channel.ok()) return ReportFailure(channel.status(), options.json, kExitFailure);
  remote::SmootherClient client(*std::move(channel));
  absl::StatusOr<v1::QualityReport> wire_report =
      client.EvaluateQuality(sent->mesh, static_cast<std::uint32_t>(options.bins));
  if (!wire_report.ok()) {
    return ReportRemoteFailure(wire_report.status(), options.json, kExitFailure);
  }
  events::QualityReport report;
  report.input = options.input;
  report.nodes = file->point_count();
  report.passthrough_cells =
      file->cells.size() - static_cast<std::int64_t>(sent->element_cells.size());
  report.quality = wire::FromWireQuality(*wire_report);
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
    std::printf("%s\n", events::QualityReportJson(report).c_str());
  } else {
    std::fputs(FormatQualityReport(report).c_str(), stdout);
  }
  std::fflush(stdout);
  return kExitSuccess;
}

}  // namespace getme::cli
