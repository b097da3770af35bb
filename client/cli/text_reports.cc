#include "cli/text_reports.h"

#include <algorithm>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_join.h"

namespace getme::cli {
namespace {

constexpr std::array<const char*, kElementTypeCount> kPluralNames = {"tetrahedra", "hexahedra",
                                                                     "pyramids", "prisms"};

// "445 tetrahedra, 305 hexahedra, 190 pyramids"
std::string TypeCountsText(const std::array<std::int64_t, kElementTypeCount>& counts) {
  std::vector<std::string> parts;
  for (const ElementType type : kAllElementTypes) {
    const std::int64_t count = counts[TypeIndex(type)];
    if (count > 0) {
      parts.push_back(
          absl::StrCat(count, " ", count == 1 ? TypeName(type) : kPluralNames[TypeIndex(type)]));
    }
  }
  return absl::StrJoin(parts, ", ");
}

}  // namespace

std::string FormatProgressLine(const ProgressEvent& event) {
  std::string line =
      absl::StrFormat("%-13s iteration %-7d q_min %.6f  q_mean %.6f", PhaseName(event.phase),
                      event.iteration, event.q_min, event.q_mean);
  if (event.invalid > 0) absl::StrAppendFormat(&line, "  invalid %d", event.invalid);
  absl::StrAppendFormat(&line, "  %.1f s", event.elapsed_seconds);
  return line;
}

std::string FormatSmoothSummary(const events::SmoothReport& report) {
  const SmoothingResult& result = report.result;
  const MeshQuality& before = result.before;
  const MeshQuality& after = result.after;
  std::string out = absl::StrFormat("%s -> %s  (method %s, %d thread%s, %.3f s)\n\n", report.input,
                                    report.output, MethodName(report.method), result.threads,
                                    result.threads == 1 ? "" : "s", result.seconds);
  const auto row_int = [&](absl::string_view label, std::int64_t a, std::int64_t b) {
    absl::StrAppendFormat(&out, "%-16s %14d %14d\n", label, a, b);
  };
  const auto row_double = [&](absl::string_view label, double a, double b) {
    absl::StrAppendFormat(&out, "%-16s %14.6f %14.6f\n", label, a, b);
  };
  absl::StrAppendFormat(&out, "%-16s %14s %14s\n", "", "before", "after");
  row_int("nodes", report.nodes, report.nodes);
  row_int("elements", before.elements, after.elements);
  for (const ElementType type : kAllElementTypes) {
    const int t = TypeIndex(type);
    if (report.elements_by_type[t] == 0) continue;
    row_int(absl::StrCat("  ", TypeName(type)), before.by_type[t].count, after.by_type[t].count);
  }
  if (report.passthrough_cells > 0) {
    row_int("passthrough cells", report.passthrough_cells, report.passthrough_cells);
  }
  row_double("q_min", before.q_min, after.q_min);
  row_double("q_mean", before.q_mean, after.q_mean);
  row_int("invalid", before.invalid, after.invalid);
  row_double("warpage max", before.warpage_max, after.warpage_max);
  row_double("warpage mean", before.warpage_mean, after.warpage_mean);
  if (!result.phases.empty()) {
    absl::StrAppendFormat(&out, "\n%-16s %10s %10s %10s %10s %9s\n", "phase", "iterations",
                          "seconds", "q_min", "q_mean", "reverted");
    for (const PhaseSummary& phase : result.phases) {
      absl::StrAppendFormat(&out, "%-16s %10d %10.3f %10.6f %10.6f %9d\n", PhaseName(phase.phase),
                            phase.iterations, phase.seconds, phase.q_min, phase.q_mean,
                            phase.reverted_nodes);
    }
  }
  if (result.boundary_slide && report.boundary_surface) {
    const BoundarySlideSummary& slide = *result.boundary_slide;
    absl::StrAppendFormat(
        &out,
        "\nboundary         slide: %d of %d sliding nodes moved, at most %.3g from the input's "
        "surface\n                 %d surface groups, %d feature edges in %d curves, %d corners "
        "(fixed)\n",
        slide.slid_nodes, slide.sliding_nodes, slide.max_distance,
        report.boundary_surface->surface_groups, report.boundary_surface->feature_edges,
        report.boundary_surface->feature_curves, report.boundary_surface->corners);
  }
  if (report.layers) {
    const surface::LayerReport& layers = *report.layers;
    absl::StrAppendFormat(
        &out,
        "\nlayers           kept: %d columns of %d elements, %d layers, %d nodes held at their "
        "wall distance\n                 columns end at: %d tetrahedra, %d pyramids, %d prism "
        "sides, %d thick elements, %d other columns, %d boundary; %d nodes where columns collide "
        "(free)\n",
        layers.columns, layers.column_elements, layers.layers, layers.layer_nodes,
        layers.ends_tetrahedron, layers.ends_pyramid, layers.ends_prism_side, layers.ends_isotropic,
        layers.ends_taken, layers.ends_boundary, layers.conflicting_nodes);
    absl::StrAppendFormat(&out, "%-16s %10s %10s\n", "", "before", "after");
    const auto layer_row = [&](const char* name, double before, double after) {
      absl::StrAppendFormat(&out, "  %-14s %10.4g %10.4g\n", name, before, after);
    };
    layer_row("first min", layers.before.first_min, layers.after.first_min);
    layer_row("first mean", layers.before.first_mean, layers.after.first_mean);
    layer_row("first max", layers.before.first_max, layers.after.first_max);
    layer_row("lean (deg)", layers.before.mean_lean_degrees, layers.after.mean_lean_degrees);
    layer_row("q_min", layers.before.q_min, layers.after.q_min);
    layer_row("q_mean", layers.before.q_mean, layers.after.q_mean);
    absl::StrAppendFormat(&out, "  %-14s %.3g\n", "height change", layers.max_height_change);
  }
  absl::StrAppendFormat(&out, "\n%-16s %.3f\n%-16s %d\n", "seconds", result.seconds, "threads",
                        result.threads);
  return out;
}

std::string FormatQualityReport(const events::QualityReport& report) {
  const MeshQuality& quality = report.quality;
  std::array<std::int64_t, kElementTypeCount> counts{};
  for (const ElementType type : kAllElementTypes) {
    counts[TypeIndex(type)] = quality.by_type[TypeIndex(type)].count;
  }
  std::string out =
      absl::StrFormat("%s: %d nodes, %d element%s (%s)", report.input, report.nodes,
                      quality.elements, quality.elements == 1 ? "" : "s", TypeCountsText(counts));
  if (report.passthrough_cells > 0) {
    absl::StrAppendFormat(&out, ", %d passthrough cells", report.passthrough_cells);
  }
  absl::StrAppendFormat(&out, "\n\n%-12s %10s %10s %10s %8s\n", "type", "count", "q_min", "q_mean",
                        "invalid");
  for (const ElementType type : kAllElementTypes) {
    const TypeQuality& entry = quality.by_type[TypeIndex(type)];
    if (entry.count == 0) continue;
    absl::StrAppendFormat(&out, "%-12s %10d %10.6f %10.6f %8d\n", TypeName(type), entry.count,
                          entry.q_min, entry.q_mean, entry.invalid);
  }
  absl::StrAppendFormat(&out, "%-12s %10d %10.6f %10.6f %8d\n", "all", quality.elements,
                        quality.q_min, quality.q_mean, quality.invalid);
  absl::StrAppendFormat(&out, "\nwarpage max %.6f, mean %.6f (elements with quad faces)\n",
                        quality.warpage_max, quality.warpage_mean);
  if (quality.invalid > 0) {
    std::vector<std::string> listed;
    for (std::size_t i = 0; i < quality.first_invalid.size(); ++i) {
      listed.push_back(i < report.first_invalid_cells.size() &&
                               report.first_invalid_cells[i] != quality.first_invalid[i]
                           ? absl::StrCat(quality.first_invalid[i], " (cell ",
                                          report.first_invalid_cells[i], ")")
                           : absl::StrCat(quality.first_invalid[i]));
    }
    absl::StrAppendFormat(&out, "invalid elements: %d; first: %s\n", quality.invalid,
                          absl::StrJoin(listed, ", "));
  }
  const std::size_t bins = quality.histogram.size();
  if (bins > 0) {
    const std::int64_t largest = std::max<std::int64_t>(
        1, *std::max_element(quality.histogram.begin(), quality.histogram.end()));
    constexpr int kBarWidth = 40;
    absl::StrAppendFormat(&out, "\nmean ratio histogram (%d bins)\n", bins);
    for (std::size_t i = 0; i < bins; ++i) {
      const double low = static_cast<double>(i) / bins;
      const double high = static_cast<double>(i + 1) / bins;
      const std::int64_t count = quality.histogram[i];
      const int bar = static_cast<int>((count * kBarWidth + largest - 1) / largest);
      absl::StrAppendFormat(&out, "  [%.3f, %.3f%c %10d%s%s\n", low, high,
                            i + 1 == bins ? ']' : ')', count, bar > 0 ? "  " : "",
                            std::string(bar, '#'));
    }
  }
  return out;
}

}  // namespace getme::cli
