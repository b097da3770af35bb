#include "getme_server/report_conversion.h"

#include "getme_server/mesh_conversion.h"
#include "getme_wire/enums.h"

namespace getme::server {
namespace {

void ToWireTypeQuality(const TypeQuality& quality, v1::TypeQuality& wire) {
  wire.set_count(quality.count);
  wire.set_q_min(quality.q_min);
  wire.set_q_mean(quality.q_mean);
  wire.set_invalid_elements(quality.invalid);
}

}  // namespace

v1::QualityReport ToWireReport(const MeshQuality& quality, const v1::Mesh& wire) {
  v1::QualityReport report;
  report.set_elements(quality.elements);
  report.set_q_min(quality.q_min);
  report.set_q_mean(quality.q_mean);
  report.set_invalid_elements(quality.invalid);
  for (ElementId element : quality.first_invalid) {
    report.add_first_invalid_elements(WireElementId(wire, element));
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

v1::ProgressEvent ToWireEvent(const ProgressEvent& event) {
  v1::ProgressEvent wire;
  wire.set_phase(wire::ToWirePhase(event.phase));
  wire.set_iteration(event.iteration);
  wire.set_q_min(event.q_min);
  wire.set_q_mean(event.q_mean);
  wire.set_invalid_elements(event.invalid);
  wire.set_reverted_nodes(event.reverted_nodes);
  wire.set_elapsed_seconds(event.elapsed_seconds);
  wire.set_phase_done(event.phase_done);
  return wire;
}

v1::PhaseSummary ToWirePhaseSummary(const PhaseSummary& summary) {
  v1::PhaseSummary wire;
  wire.set_phase(wire::ToWirePhase(summary.phase));
  wire.set_iterations(summary.iterations);
  wire.set_seconds(summary.seconds);
  wire.set_q_min(summary.q_min);
  wire.set_q_mean(summary.q_mean);
  wire.set_reverted_nodes(summary.reverted_nodes);
  return wire;
}

}  // namespace getme::server
