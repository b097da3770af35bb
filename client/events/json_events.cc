#include "events/json_events.h"

#include "absl/strings/str_cat.h"
#include "events/json_output.h"

namespace getme::events {

std::string ProgressEventJson(const ProgressEvent& event) {
  return JsonObject()
      .AddString("event", "progress")
      .AddString("phase", PhaseName(event.phase))
      .AddInt("iteration", event.iteration)
      .AddDouble("q_min", event.q_min)
      .AddDouble("q_mean", event.q_mean)
      .AddInt("invalid", event.invalid)
      .AddInt("reverted_nodes", event.reverted_nodes)
      .AddDouble("elapsed_seconds", event.elapsed_seconds)
      .AddBool("phase_done", event.phase_done)
      .Build();
}

std::string SmoothResultJson(const SmoothReport& report) {
  const SmoothingResult& result = report.result;
  std::string phases = "[";
  for (std::size_t i = 0; i < result.phases.size(); ++i) {
    const PhaseSummary& phase = result.phases[i];
    absl::StrAppend(&phases, i > 0 ? "," : "",
                    JsonObject()
                        .AddString("phase", PhaseName(phase.phase))
                        .AddInt("iterations", phase.iterations)
                        .AddDouble("seconds", phase.seconds)
                        .AddDouble("q_min", phase.q_min)
                        .AddDouble("q_mean", phase.q_mean)
                        .AddInt("reverted_nodes", phase.reverted_nodes)
                        .Build());
  }
  phases += "]";
  JsonObject object;
  object.AddString("event", "result")
      .AddInt("nodes", report.nodes)
      .AddInt("elements", result.after.elements)
      .AddDouble("q_min_before", result.before.q_min)
      .AddDouble("q_mean_before", result.before.q_mean)
      .AddDouble("q_min", result.after.q_min)
      .AddDouble("q_mean", result.after.q_mean)
      .AddInt("invalid", result.after.invalid)
      .AddInt("invalid_before", result.before.invalid)
      .AddDouble("warpage_max_before", result.before.warpage_max)
      .AddDouble("warpage_mean_before", result.before.warpage_mean)
      .AddDouble("warpage_max", result.after.warpage_max)
      .AddDouble("warpage_mean", result.after.warpage_mean)
      .AddInt("iterations_untangle", result.iterations_untangle)
      .AddInt("iterations_simultaneous", result.iterations_simultaneous)
      .AddInt("iterations_sequential", result.iterations_sequential)
      .AddInt("iterations_laplace", result.iterations_laplace)
      .AddInt("iterations_polish", result.iterations_polish)
      .AddRaw("phases", phases)
      .AddString("boundary", report.boundary);
  if (result.boundary_slide && report.boundary_surface) {
    object.AddRaw(
        "boundary_slide",
        JsonObject()
            .AddInt("sliding_nodes", result.boundary_slide->sliding_nodes)
            .AddInt("slid_nodes", result.boundary_slide->slid_nodes)
            .AddDouble("max_distance", result.boundary_slide->max_distance)
            .AddInt("feature_edges", report.boundary_surface->feature_edges)
            .AddInt("feature_curves", report.boundary_surface->feature_curves)
            .AddInt("corners", report.boundary_surface->corners)
            .AddInt("surface_groups", report.boundary_surface->surface_groups)
            .AddInt("interior_grouped_faces", report.boundary_surface->interior_grouped_faces)
            .Build());
  }
  if (report.layers) {
    const surface::LayerReport& layers = *report.layers;
    const auto state = [](const surface::LayerState& s) {
      return JsonObject()
          .AddDouble("first_min", s.first_min)
          .AddDouble("first_mean", s.first_mean)
          .AddDouble("first_max", s.first_max)
          .AddDouble("mean_lean_degrees", s.mean_lean_degrees)
          .AddDouble("q_min", s.q_min)
          .AddDouble("q_mean", s.q_mean)
          .Build();
    };
    object.AddRaw("layers", JsonObject()
                                .AddInt("columns", layers.columns)
                                .AddInt("column_elements", layers.column_elements)
                                .AddInt("layer_nodes", layers.layer_nodes)
                                .AddInt("layers", layers.layers)
                                .AddInt("conflicting_nodes", layers.conflicting_nodes)
                                .AddRaw("ends", JsonObject()
                                                    .AddInt("tetrahedron", layers.ends_tetrahedron)
                                                    .AddInt("pyramid", layers.ends_pyramid)
                                                    .AddInt("prism_side", layers.ends_prism_side)
                                                    .AddInt("isotropic", layers.ends_isotropic)
                                                    .AddInt("other_column", layers.ends_taken)
                                                    .AddInt("boundary", layers.ends_boundary)
                                                    .Build())
                                .AddRaw("before", state(layers.before))
                                .AddRaw("after", state(layers.after))
                                .AddDouble("max_height_change", layers.max_height_change)
                                .Build());
  }
  return object.AddDouble("seconds", result.seconds)
      .AddInt("threads", result.threads)
      .AddString("method", MethodName(report.method))
      .AddString("input", report.input)
      .AddString("output", report.output)
      .Build();
}

std::string QualityReportJson(const QualityReport& report) {
  const MeshQuality& quality = report.quality;
  JsonObject by_type;
  for (const ElementType type : kAllElementTypes) {
    const TypeQuality& entry = quality.by_type[TypeIndex(type)];
    by_type.AddRaw(TypeName(type), JsonObject()
                                       .AddInt("count", entry.count)
                                       .AddDouble("q_min", entry.q_min)
                                       .AddDouble("q_mean", entry.q_mean)
                                       .AddInt("invalid", entry.invalid)
                                       .Build());
  }
  const std::vector<std::int64_t> first_invalid(quality.first_invalid.begin(),
                                                quality.first_invalid.end());
  return JsonObject()
      .AddString("event", "quality")
      .AddString("input", report.input)
      .AddInt("nodes", report.nodes)
      .AddInt("elements", quality.elements)
      .AddInt("passthrough_cells", report.passthrough_cells)
      .AddDouble("q_min", quality.q_min)
      .AddDouble("q_mean", quality.q_mean)
      .AddInt("invalid", quality.invalid)
      .AddRaw("first_invalid", JsonIntArray(first_invalid))
      .AddRaw("first_invalid_cells", JsonIntArray(report.first_invalid_cells))
      .AddDouble("warpage_max", quality.warpage_max)
      .AddDouble("warpage_mean", quality.warpage_mean)
      .AddRaw("by_type", by_type.Build())
      .AddRaw("histogram", JsonIntArray(quality.histogram))
      .Build();
}

std::string ErrorJson(const absl::Status& status) {
  return JsonObject()
      .AddString("event", "error")
      .AddString("code", absl::StatusCodeToString(status.code()))
      .AddString("message", status.message())
      .Build();
}

}  // namespace getme::events
