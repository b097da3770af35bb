#include "cli/convert_command.h"

#include "cli/failure.h"
#include "cli/mesh_files.h"
#include "spdlog/spdlog.h"

namespace getme::cli {

int RunConvertCommand(const ConvertCommandOptions& options) {
  const auto fail = [](const absl::Status& status) {
    return ReportFailure(status, /*json=*/false, kExitFailure);
  };
  absl::StatusOr<formats::MeshDocument> document = ReadInputMesh(options.input, options.files);
  if (!document.ok()) return fail(document.status());
  absl::StatusOr<OutputTarget> output = ResolveOutput(*document, options.output, options.files);
  if (!output.ok()) return fail(output.status());
  spdlog::info("read {} ({}): {} points, {} cells", options.input,
               formats::FormatDisplayName(document->format), document->grid.point_count(),
               document->grid.cells.size());
  if (absl::Status status = WriteOutputMesh(*document, *output); !status.ok()) return fail(status);
  return kExitSuccess;
}

}  // namespace getme::cli
