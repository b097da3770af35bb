#include "cli/remote_output.h"

#include <cstdio>

#include "absl/strings/str_format.h"
#include "events/json_output.h"
#include "formats/grid_mesh.h"
#include "getme_wire/boundary_reports.h"
#include "getme_wire/enums.h"
#include "getme_wire/reports.h"
#include "getme_wire/status.h"
#include "spdlog/spdlog.h"

namespace getme::cli {

absl::Status WriteSmoothedFile(std::span<const double> coordinates, const OutputTarget& output,
                               formats::MeshDocument& document) {
  formats::UnstructuredGrid& file = document.grid;
  if (absl::Status status = remote::ApplyCoordinates(coordinates, file); !status.ok()) {
    return status;
  }
  absl::StatusOr<formats::GridMesh> smoothed = formats::GridToMesh(file);
  if (!smoothed.ok()) return smoothed.status();
  if (absl::Status status =
          formats::UpdateGridFromMesh(smoothed->mesh, smoothed->cell_elements, file);
      !status.ok()) {
    return status;
  }
  return WriteOutputMesh(document, output);
}

events::SmoothReport MakeRemoteSmoothReport(const std::string& input, const std::string& output,
                                            Method method, const formats::UnstructuredGrid& file,
                                            const remote::GridWireMesh& sent,
                                            const v1::SmoothResult& result) {
  events::SmoothReport report;
  report.input = input;
  report.output = output;
  report.method = method;
  report.nodes = file.point_count();
  const v1::Mesh& mesh = sent.mesh;
  report.elements_by_type[TypeIndex(ElementType::kTetrahedron)] = mesh.tetrahedra_size() / 4;
  report.elements_by_type[TypeIndex(ElementType::kHexahedron)] = mesh.hexahedra_size() / 8;
  report.elements_by_type[TypeIndex(ElementType::kPrism)] = mesh.wedges_size() / 6;
  report.elements_by_type[TypeIndex(ElementType::kPyramid)] = mesh.pyramids_size() / 5;
  report.passthrough_cells =
      file.cells.size() - static_cast<std::int64_t>(sent.element_cells.size());
  report.result = wire::FromWireResult(result);
  report.boundary = wire::BoundaryName(result.boundary());
  wire::SurfaceReports surface = wire::FromWireSurfaceReports(result);
  report.boundary_surface = surface.boundary_surface;
  report.layers = std::move(surface.layers);
  return report;
}

const char* JobStateName(v1::JobState state) {
  switch (state) {
    case v1::JOB_STATE_QUEUED:
      return "QUEUED";
    case v1::JOB_STATE_RUNNING:
      return "RUNNING";
    case v1::JOB_STATE_SUCCEEDED:
      return "SUCCEEDED";
    case v1::JOB_STATE_FAILED:
      return "FAILED";
    case v1::JOB_STATE_CANCELLED:
      return "CANCELLED";
    default:
      return "UNSPECIFIED";
  }
}

void AnnounceRestart(const v1::ProgressEvent& event, bool json) {
  if (json) {
    std::printf("%s\n", events::JsonObject()
                            .AddString("event", "restarted")
                            .AddString("job_id", event.job_id())
                            .AddInt("attempt", event.attempt())
                            .Build()
                            .c_str());
    std::fflush(stdout);
    return;
  }
  std::fprintf(stderr,
               "[info] job %s restarted from the beginning (attempt %u): the replica running it "
               "was lost\n",
               event.job_id().c_str(), event.attempt());
}

std::string JobJson(const v1::Job& job) {
  const v1::ProgressEvent& latest = job.latest_progress();
  return events::JsonObject()
      .AddString("event", "job")
      .AddString("job_id", job.job_id())
      .AddString("state", JobStateName(job.state()))
      .AddString("method", MethodName(wire::MethodOrGetme(job.method())))
      .AddInt("nodes", static_cast<std::int64_t>(job.nodes()))
      .AddInt("elements", static_cast<std::int64_t>(job.elements()))
      .AddString("phase", PhaseName(wire::PhaseOrSimultaneous(latest.phase())))
      .AddInt("iteration", latest.iteration())
      .AddDouble("q_min", latest.q_min())
      .AddDouble("q_mean", latest.q_mean())
      .AddBool("result_available", job.result_available())
      .AddString("error_code", job.error_code() == 0
                                   ? ""
                                   : absl::StatusCodeToString(wire::FromWireJobError(job).code()))
      .AddString("error_message", job.error_message())
      .Build();
}

std::string FormatJobLine(const v1::Job& job) {
  const v1::ProgressEvent& latest = job.latest_progress();
  std::string line = absl::StrFormat(
      "%-20s %-9s %-13s %9d nodes %9d elements", job.job_id(), JobStateName(job.state()),
      MethodName(wire::MethodOrGetme(job.method())), job.nodes(), job.elements());
  if (job.has_latest_progress()) {
    absl::StrAppendFormat(&line, "  %s it %d  q_min %.6f  q_mean %.6f",
                          PhaseName(wire::PhaseOrSimultaneous(latest.phase())), latest.iteration(),
                          latest.q_min(), latest.q_mean());
  }
  if (job.result_available()) line += "  result ready";
  if (!job.error_message().empty()) {
    absl::StrAppendFormat(&line, "  %s: %s",
                          absl::StatusCodeToString(wire::FromWireJobError(job).code()),
                          job.error_message());
  }
  return line;
}

}  // namespace getme::cli
