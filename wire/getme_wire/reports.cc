#include "getme_wire/reports.h"

#include "getme_wire/enums.h"

namespace getme::wire {
namespace {

void ToWireTypeQuality(const TypeQuality& quality, v1::TypeQuality& wire) {
  wire.set_count(quality.count);
  wire.set_q_min(quality.q_min);
  wire.set_q_mean(quality.q_mean);
  wire.set_invalid_elements(quality.invalid);
}

TypeQuality FromWireTypeQuality(const v1::TypeQuality& wire) {
  TypeQuality quality;
  quality.count = wire.count();
  quality.q_min = wire.count() > 0 ? wire.q_min() : 1.0;
  quality.q_mean = wire.q_mean();
  quality.invalid = wire.invalid_elements();
  return quality;
}

}  // namespace

v1::QualityReport ToWireReport(const MeshQuality& quality, const WireMeshIds& ids) {
  v1::QualityReport report;
  report.set_elements(quality.elements);
  report.set_q_min(quality.q_min);
  report.set_q_mean(quality.q_mean);
  report.set_invalid_elements(quality.invalid);
  for (ElementId element : quality.first_invalid) {
    report.add_first_invalid_elements(ids.ElementId(element));
  }
  report.set_warpage_max(quality.warpage_max);
  report.set_warpage_mean(quality.warpage_mean);
  const auto& by_type = quality.by_type;
  ToWireTypeQuality(by_type[TypeIndex(ElementType::kTetrahedron)], *report.mutable_tetrahedra());
  ToWireTypeQuality(by_type[TypeIndex(ElementType::kHexahedron)], *report.mutable_hexahedra());
  ToWireTypeQuality(by_type[TypeIndex(ElementType::kPrism)], *report.mutable_wedges());
  ToWireTypeQuality(by_type[TypeIndex(ElementType::kPyramid)], *report.mutable_pyramids());
  for (std::int64_t count : quality.histogram) report.add_histogram(count);
  return report;
}

MeshQuality FromWireQuality(const v1::QualityReport& report) {
  MeshQuality quality;
  quality.elements = report.elements();
  quality.q_min = report.q_min();
  quality.q_mean = report.q_mean();
  quality.invalid = report.invalid_elements();
  for (const std::uint64_t element : report.first_invalid_elements()) {
    quality.first_invalid.push_back(static_cast<ElementId>(element));
  }
  quality.warpage_max = report.warpage_max();
  quality.warpage_mean = report.warpage_mean();
  quality.by_type[TypeIndex(ElementType::kTetrahedron)] = FromWireTypeQuality(report.tetrahedra());
  quality.by_type[TypeIndex(ElementType::kHexahedron)] = FromWireTypeQuality(report.hexahedra());
  quality.by_type[TypeIndex(ElementType::kPrism)] = FromWireTypeQuality(report.wedges());
  quality.by_type[TypeIndex(ElementType::kPyramid)] = FromWireTypeQuality(report.pyramids());
  quality.histogram.assign(report.histogram().begin(), report.histogram().end());
  return quality;
}

v1::PhaseSummary ToWirePhaseSummary(const PhaseSummary& summary) {
  v1::PhaseSummary wire;
  wire.set_phase(ToWirePhase(summary.phase));
  wire.set_iterations(summary.iterations);
  wire.set_seconds(summary.seconds);
  wire.set_q_min(summary.q_min);
  wire.set_q_mean(summary.q_mean);
  wire.set_reverted_nodes(summary.reverted_nodes);
  return wire;
}

v1::SmoothResult ToWireSmoothResult(const SmoothingResult& result, const MeshQuality& before,
                                    const MeshQuality& after, const WireMeshIds& ids) {
  v1::SmoothResult summary;
  *summary.mutable_before() = ToWireReport(before, ids);
  *summary.mutable_after() = ToWireReport(after, ids);
  for (const PhaseSummary& phase : result.phases) *summary.add_phases() = ToWirePhaseSummary(phase);
  summary.set_iterations_untangle(result.iterations_untangle);
  summary.set_iterations_simultaneous(result.iterations_simultaneous);
  summary.set_iterations_sequential(result.iterations_sequential);
  summary.set_iterations_laplace(result.iterations_laplace);
  summary.set_iterations_polish(result.iterations_polish);
  summary.set_iterations_layers(result.iterations_layers);
  if (result.boundary_slide) {
    v1::BoundarySlideReport& slide = *summary.mutable_boundary_slide();
    slide.set_sliding_nodes(result.boundary_slide->sliding_nodes);
    slide.set_slid_nodes(result.boundary_slide->slid_nodes);
    slide.set_max_distance(result.boundary_slide->max_distance);
    slide.set_layer_nodes(result.boundary_slide->layer_nodes);
  }
  summary.set_seconds(result.seconds);
  summary.set_threads(result.threads);
  return summary;
}

SmoothingResult FromWireResult(const v1::SmoothResult& result) {
  SmoothingResult converted;
  converted.before = FromWireQuality(result.before());
  converted.after = FromWireQuality(result.after());
  for (const v1::PhaseSummary& phase : result.phases()) {
    PhaseSummary summary;
    summary.phase = PhaseOrSimultaneous(phase.phase());
    summary.iterations = phase.iterations();
    summary.seconds = phase.seconds();
    summary.q_min = phase.q_min();
    summary.q_mean = phase.q_mean();
    summary.reverted_nodes = phase.reverted_nodes();
    converted.phases.push_back(summary);
  }
  converted.iterations_untangle = result.iterations_untangle();
  converted.iterations_simultaneous = result.iterations_simultaneous();
  converted.iterations_sequential = result.iterations_sequential();
  converted.iterations_laplace = result.iterations_laplace();
  converted.iterations_polish = result.iterations_polish();
  converted.iterations_layers = result.iterations_layers();
  if (result.has_boundary_slide()) {
    const v1::BoundarySlideReport& slide = result.boundary_slide();
    converted.boundary_slide = BoundarySlideSummary{slide.sliding_nodes(), slide.slid_nodes(),
                                                    slide.max_distance(), slide.layer_nodes()};
  }
  converted.seconds = result.seconds();
  converted.threads = result.threads();
  return converted;
}

}  // namespace getme::wire
