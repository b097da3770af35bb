#include "cli/quality_command.h"

#include <cstdio>

#include "absl/strings/str_cat.h"
#include "cli/failure.h"
#include "cli/text_reports.h"
#include "events/json_events.h"
#include "formats/grid_mesh.h"
#include "formats/mesh_file.h"
#include "getme/mesh/mesh_quality.h"
#include "getme/parallel/thread_pool.h"

namespace getme::cli {

int RunQualityCommand(const QualityCommandOptions& options) {
  absl::StatusOr<formats::MeshDocument> document =
      formats::ReadMeshDocument(options.input, options.input_format);
  if (!document.ok()) return ReportFailure(document.status(), options.json, kExitFailure);
  const formats::UnstructuredGrid* file = &document->grid;
  absl::StatusOr<formats::GridMesh> converted = formats::GridToMesh(*file);
  if (!converted.ok()) {
    return ReportFailure(
        absl::Status(converted.status().code(),
                     absl::StrCat(options.input, ": ", converted.status().message())),
        options.json, kExitFailure);
  }
  ThreadPool pool(options.threads);
  QualityOptions quality_options;
  quality_options.histogram_bins = options.bins;

  events::QualityReport report;
  report.input = options.input;
  report.nodes = converted->mesh.node_count();
  report.passthrough_cells = file->cells.size() - converted->mesh.element_count();
  report.quality = EvaluateMeshQuality(converted->mesh, pool, quality_options);
  for (const ElementId element : report.quality.first_invalid) {
    report.first_invalid_cells.push_back(converted->element_cells[element]);
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
