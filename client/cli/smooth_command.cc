#include "cli/smooth_command.h"

#include <cstdio>
#include <filesystem>
#include <memory>

#include "absl/strings/str_cat.h"
#include "cli/failure.h"
#include "cli/interrupt_scope.h"
#include "cli/one_run_allocator.h"
#include "cli/smooth_run.h"
#include "formats/grid_mesh.h"
#include "getme/parallel/thread_pool.h"
#include "getme/smoothing/smoother.h"
#include "getme_surface/layer_report.h"
#include "getme_surface/surface_slide.h"
#include "spdlog/spdlog.h"

namespace getme::cli {
namespace {

// What a default run's heap peaks at per byte of its input file, about (an ASCII VTK file of
// tetrahedra: cub_wedge_like.vtk, 3.7 MB, peaks at 39 MB resident). Binary files hold more mesh
// per byte, so for them this asks for less than the run will use.
constexpr std::size_t kHeapPerInputByte = 8;

// The input file's size; 0 for a directory (OpenFOAM) or what cannot be read.
std::size_t InputBytes(const std::string& input) {
  std::error_code error;
  const auto size = std::filesystem::file_size(input, error);
  return error ? 0 : static_cast<std::size_t>(size);
}

absl::Status WithInput(const std::string& input, const absl::Status& status) {
  return absl::Status(status.code(), absl::StrCat(input, ": ", status.message()));
}

}  // namespace

int RunSmoothCommand(const SmoothCommandOptions& options) {
  const auto fail = [&](const absl::Status& status, int exit_status) {
    return ReportFailure(status, options.json, exit_status);
  };
  const SmoothingParams params = ToSmoothingParams(options);
  if (absl::Status status = params.Validate(); !status.ok()) return fail(status, kExitUsage);
  if (params.threads != 1) PrefaultHeapInBackground(kHeapPerInputByte * InputBytes(options.input));
  absl::StatusOr<SmoothRun> run = PrepareSmoothRun(options);
  if (!run.ok()) return fail(run.status(), kExitFailure);
  formats::UnstructuredGrid& grid = run->document.grid;
  absl::StatusOr<formats::GridMesh> converted = formats::GridToMesh(grid);
  if (!converted.ok()) return fail(WithInput(options.input, converted.status()), kExitFailure);
  Mesh& mesh = converted->mesh;
  for (std::size_t node = 0; node < run->option_fixed.size(); ++node) {
    if (run->option_fixed[node] != 0) mesh.set_fixed(static_cast<NodeId>(node), true);
  }

  events::SmoothReport report;
  report.input = options.input;
  report.output = options.output;
  report.method = options.smoothing.method;
  report.nodes = mesh.node_count();
  for (const ElementType type : kAllElementTypes) {
    report.elements_by_type[TypeIndex(type)] = mesh.element_count(type);
  }
  report.passthrough_cells = grid.cells.size() - mesh.element_count();
  std::int64_t fixed_nodes = 0;
  for (const std::uint8_t fixed : mesh.fixed_flags()) fixed_nodes += fixed != 0 ? 1 : 0;
  spdlog::info("read {} ({}): {} nodes, {} elements, {} passthrough cells, {} fixed nodes",
               options.input, formats::FormatDisplayName(run->document.format), mesh.node_count(),
               mesh.element_count(), report.passthrough_cells, fixed_nodes);

  report.boundary = options.smoothing.slide_boundary  ? "slide"
                    : options.smoothing.free_boundary ? "free"
                                                      : "fixed";
  // --boundary slide and --keep-layers: the input's surface, its features and corners, and its
  // boundary-layer columns, before anything moves.
  std::unique_ptr<surface::SurfaceSlide> slide;
  if (params.slide_boundary || params.keep_layers) {
    const std::vector<surface::GroupedFace> groups = SurfaceGroupsOf(run->document);
    surface::SlideOptions slide_options;
    slide_options.groups = groups;
    slide_options.skip_interior_groups = true;
    slide_options.feature_angle_degrees = params.feature_angle_degrees;
    slide_options.slide_boundary = params.slide_boundary;
    slide_options.keep_layers = params.keep_layers;
    absl::StatusOr<std::unique_ptr<surface::SurfaceSlide>> built =
        surface::SurfaceSlide::Build(mesh, slide_options);
    if (!built.ok()) return fail(WithInput(options.input, built.status()), kExitFailure);
    slide = *std::move(built);
  }
  std::optional<surface::LayerHeights> layers_before;
  if (params.keep_layers) {
    const surface::LayerColumns& columns = slide->layers();
    ThreadPool pool(params.threads);
    layers_before = surface::MeasureKeptLayers(mesh, *slide, pool);
    spdlog::info(
        "layers kept: {} columns of {} elements, {} layers; first-layer height {:.4g} to {:.4g}",
        columns.column_count(), columns.column_elements(), columns.layers, layers_before->first_min,
        layers_before->first_max);
  }
  if (params.slide_boundary) {
    const surface::BoundarySurface& boundary = slide->surface();
    report.boundary_surface = surface::CountFeatures(boundary);
    spdlog::info(
        "boundary slides: {} surface groups, {} feature edges in {} curves, {} corners (feature "
        "angle {}°); {} tagged faces not on the boundary (interfaces) left out",
        boundary.group_count, boundary.feature_edges.size(), boundary.curve_count,
        boundary.corner_count, params.feature_angle_degrees, boundary.interior_grouped_faces);
  }

  ProgressSink sink(options, run->trace.get());
  const ProgressCallback progress = [&](const ProgressEvent& event) { sink.OnEvent(event); };
  CancellationToken cancel;
  absl::StatusOr<SmoothingResult> result;
  {
    InterruptScope interrupt(&cancel);
    result = Smooth(mesh, params, progress, &cancel, slide.get());
  }
  sink.Finish();
  if (!result.ok()) {
    if (result.status().code() == absl::StatusCode::kCancelled) {
      return fail(
          absl::CancelledError(absl::StrCat("interrupted; ", options.output, " was not written")),
          kExitInterrupted);
    }
    return fail(WithInput(options.input, result.status()), kExitFailure);
  }
  report.result = *std::move(result);
  if (layers_before) {
    ThreadPool pool(params.threads);
    report.layers = surface::MakeLayerReport(*slide, *layers_before,
                                             surface::MeasureKeptLayers(mesh, *slide, pool));
  }

  if (absl::Status status = formats::UpdateGridFromMesh(mesh, converted->cell_elements, grid,
                                                        &report.result.after_elements);
      !status.ok()) {
    return fail(status, kExitFailure);
  }
  // As many threads as smoothed it format the file's numbers; its bytes do not depend on them.
  run->output->options.threads = report.result.threads;
  if (absl::Status status = WriteOutputMesh(run->document, *run->output); !status.ok()) {
    return fail(status, kExitFailure);
  }
  if (absl::Status status = FinishSmoothRun(report, options.json, *run); !status.ok()) {
    return fail(status, kExitFailure);
  }
  return kExitSuccess;
}

}  // namespace getme::cli
