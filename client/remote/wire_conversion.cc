#include "remote/wire_conversion.h"

namespace getme::remote {
namespace {

// Sets `wire` to `value` when it differs from the engine default `fallback`.
template <typename T, typename Setter>
void SetIfChanged(T value, T fallback, Setter set) {
  if (value != fallback) set(value);
}

void SetPerTypeIfChanged(const PerType& value, const PerType& fallback, v1::PerType& wire,
                         bool& any) {
  for (const ElementType type : kAllElementTypes) {
    const int i = TypeIndex(type);
    if (value[i] == fallback[i]) continue;
    any = true;
    switch (type) {
      case ElementType::kTetrahedron:
        wire.set_tetrahedron(value[i]);
        break;
      case ElementType::kHexahedron:
        wire.set_hexahedron(value[i]);
        break;
      case ElementType::kPyramid:
        wire.set_pyramid(value[i]);
        break;
      case ElementType::kPrism:
        wire.set_prism(value[i]);
        break;
    }
  }
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

v1::SmoothingParameters ToWireParameters(const SmoothingParams& params) {
  const SmoothingParams defaults;
  v1::SmoothingParameters wire;
  wire.set_method(wire::ToWireMethod(params.method));
  bool any = false;
  SetPerTypeIfChanged(params.simultaneous_sigma_min, defaults.simultaneous_sigma_min,
                      *wire.mutable_simultaneous_sigma_min(), any);
  if (!any) wire.clear_simultaneous_sigma_min();
  any = false;
  SetPerTypeIfChanged(params.simultaneous_sigma_max, defaults.simultaneous_sigma_max,
                      *wire.mutable_simultaneous_sigma_max(), any);
  if (!any) wire.clear_simultaneous_sigma_max();
  any = false;
  SetPerTypeIfChanged(params.sequential_sigma, defaults.sequential_sigma,
                      *wire.mutable_sequential_sigma(), any);
  if (!any) wire.clear_sequential_sigma();

  // clang-format off
  SetIfChanged(params.simultaneous_rho, defaults.simultaneous_rho, [&](double v) { wire.set_simultaneous_rho(v); });
  SetIfChanged(params.simultaneous_eta, defaults.simultaneous_eta, [&](double v) { wire.set_simultaneous_eta(v); });
  SetIfChanged(params.simultaneous_tolerance, defaults.simultaneous_tolerance, [&](double v) { wire.set_simultaneous_tolerance(v); });
  SetIfChanged(params.simultaneous_max_iterations, defaults.simultaneous_max_iterations, [&](std::int64_t v) { wire.set_simultaneous_max_iterations(v); });
  SetIfChanged(params.simultaneous_backtracking_steps, defaults.simultaneous_backtracking_steps, [&](int v) { wire.set_simultaneous_backtracking_steps(v); });
  SetIfChanged(params.sequential_rho, defaults.sequential_rho, [&](double v) { wire.set_sequential_rho(v); });
  SetIfChanged(params.penalty_invalid, defaults.penalty_invalid, [&](double v) { wire.set_penalty_invalid(v); });
  SetIfChanged(params.penalty_repeat, defaults.penalty_repeat, [&](double v) { wire.set_penalty_repeat(v); });
  SetIfChanged(params.penalty_success, defaults.penalty_success, [&](double v) { wire.set_penalty_success(v); });
  SetIfChanged(params.sequential_stall_iterations, defaults.sequential_stall_iterations, [&](std::int64_t v) { wire.set_sequential_stall_iterations(v); });
  SetIfChanged(params.sequential_max_iterations, defaults.sequential_max_iterations, [&](std::int64_t v) { wire.set_sequential_max_iterations(v); });
  SetIfChanged(params.sequential_improvement_tolerance, defaults.sequential_improvement_tolerance, [&](double v) { wire.set_sequential_improvement_tolerance(v); });
  SetIfChanged(params.sequential_backtracking_steps, defaults.sequential_backtracking_steps, [&](int v) { wire.set_sequential_backtracking_steps(v); });
  SetIfChanged(params.sequential_transform_blockers, defaults.sequential_transform_blockers, [&](bool v) { wire.set_sequential_transform_blockers(v); });
  SetIfChanged(params.sequential_cycle, defaults.sequential_cycle, [&](std::int64_t v) { wire.set_sequential_cycle(v); });
  SetIfChanged(params.gamma, defaults.gamma, [&](double v) { wire.set_gamma(v); });
  SetIfChanged(params.laplace_tolerance, defaults.laplace_tolerance, [&](double v) { wire.set_laplace_tolerance(v); });
  SetIfChanged(params.laplace_max_iterations, defaults.laplace_max_iterations, [&](std::int64_t v) { wire.set_laplace_max_iterations(v); });
  SetIfChanged(params.untangle, defaults.untangle, [&](bool v) { wire.set_untangle(v); });
  SetIfChanged(params.untangle_max_iterations, defaults.untangle_max_iterations, [&](std::int64_t v) { wire.set_untangle_max_iterations(v); });
  SetIfChanged(params.fix_boundary, defaults.fix_boundary, [&](bool v) { wire.set_free_boundary(!v); });
  SetIfChanged(params.threads, defaults.threads, [&](int v) { wire.set_threads(v); });
  // clang-format on
  return wire;
}

ProgressEvent FromWireProgress(const v1::ProgressEvent& event) {
  ProgressEvent result;
  result.phase = FromWirePhase(event.phase());
  result.iteration = event.iteration();
  result.q_min = event.q_min();
  result.q_mean = event.q_mean();
  result.invalid = event.invalid_elements();
  result.reverted_nodes = event.reverted_nodes();
  result.elapsed_seconds = event.elapsed_seconds();
  result.phase_done = event.phase_done();
  return result;
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

SmoothingResult FromWireResult(const v1::SmoothResult& result) {
  SmoothingResult converted;
  converted.before = FromWireQuality(result.before());
  converted.after = FromWireQuality(result.after());
  for (const v1::PhaseSummary& phase : result.phases()) {
    PhaseSummary summary;
    summary.phase = FromWirePhase(phase.phase());
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
  converted.seconds = result.seconds();
  converted.threads = result.threads();
  return converted;
}

}  // namespace getme::remote
