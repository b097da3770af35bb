#include "getme_wire/params.h"

#include <optional>
#include <string>

#include "absl/strings/str_cat.h"
#include "getme_wire/enums.h"

namespace getme::wire {
namespace {
absl::StatusOr<Method> ToEngineMethod(int method) {
  if (std::optional<Method> known = FromWireMethod(method)) return *known;
  return absl::InvalidArgumentError(
      absl::StrCat("parameters.method = ", method, " is not a known getme.v1.Method"));
}

// boundary, its older spelling free_boundary, and what only some boundaries allow: checked here
// rather than by SmoothingParams::Validate, whose fix_boundary and slide_boundary are no wire
// fields, so that the message names the fields the caller set.
absl::Status ApplyBoundary(const v1::SmoothingParameters& wire, SmoothingParams& params) {
  const int boundary = wire.boundary();
  if (!v1::Boundary_IsValid(boundary)) {
    return absl::InvalidArgumentError(
        absl::StrCat("parameters.boundary = ", boundary, " is not a known getme.v1.Boundary"));
  }
  if (wire.has_free_boundary() && boundary != v1::BOUNDARY_UNSPECIFIED &&
      wire.free_boundary() != (boundary == v1::BOUNDARY_FREE)) {
    return absl::InvalidArgumentError(
        absl::StrCat("parameters.free_boundary = ", wire.free_boundary() ? "true" : "false",
                     " contradicts parameters.boundary = ", v1::Boundary_Name(boundary),
                     ": free_boundary is the older spelling of BOUNDARY_FREE; set one of the two"));
  }
  v1::Boundary mode = static_cast<v1::Boundary>(boundary);
  if (mode == v1::BOUNDARY_UNSPECIFIED) {
    mode = wire.free_boundary() ? v1::BOUNDARY_FREE : v1::BOUNDARY_FIXED;
  }
  params.fix_boundary = mode != v1::BOUNDARY_FREE;
  params.slide_boundary = mode == v1::BOUNDARY_SLIDE;
  if (wire.has_feature_angle_degrees()) {
    // As the CLI refuses --feature-angle without --boundary slide: a caller who sets it expects
    // a sliding boundary.
    if (mode != v1::BOUNDARY_SLIDE) {
      return absl::InvalidArgumentError(
          absl::StrCat("parameters.feature_angle_degrees only shapes a sliding boundary: it needs "
                       "parameters.boundary = BOUNDARY_SLIDE, not ",
                       v1::Boundary_Name(mode)));
    }
    params.feature_angle_degrees = wire.feature_angle_degrees();
  }
  if (wire.has_keep_layers()) params.keep_layers = wire.keep_layers();
  if (params.keep_layers && mode == v1::BOUNDARY_FREE) {
    return absl::InvalidArgumentError(
        absl::StrCat("parameters.keep_layers = true needs the boundary fixed or sliding, but ",
                     boundary == v1::BOUNDARY_FREE ? "parameters.boundary = BOUNDARY_FREE"
                                                   : "parameters.free_boundary = true",
                     " moves the walls the layer heights are measured from"));
  }
  return absl::OkStatus();
}

void ApplyPerType(const v1::PerType& wire, PerType& values) {
  if (wire.has_tetrahedron()) values[TypeIndex(ElementType::kTetrahedron)] = wire.tetrahedron();
  if (wire.has_hexahedron()) values[TypeIndex(ElementType::kHexahedron)] = wire.hexahedron();
  if (wire.has_pyramid()) values[TypeIndex(ElementType::kPyramid)] = wire.pyramid();
  if (wire.has_prism()) values[TypeIndex(ElementType::kPrism)] = wire.prism();
}

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

}  // namespace

absl::StatusOr<SmoothingParams> ToEngineParams(const v1::SmoothingParameters& wire,
                                               int default_threads) {
  SmoothingParams params;
  absl::StatusOr<Method> method = ToEngineMethod(wire.method());
  if (!method.ok()) return method.status();
  params.method = *method;
  if (wire.literal()) params.UseLiteralPaperAlgorithm();

  ApplyPerType(wire.simultaneous_sigma_min(), params.simultaneous_sigma_min);
  ApplyPerType(wire.simultaneous_sigma_max(), params.simultaneous_sigma_max);
  if (wire.has_simultaneous_rho()) params.simultaneous_rho = wire.simultaneous_rho();
  if (wire.has_simultaneous_eta()) params.simultaneous_eta = wire.simultaneous_eta();
  if (wire.has_simultaneous_tolerance()) {
    params.simultaneous_tolerance = wire.simultaneous_tolerance();
  }
  if (wire.has_simultaneous_max_iterations()) {
    params.simultaneous_max_iterations = wire.simultaneous_max_iterations();
  }
  if (wire.has_simultaneous_backtracking_steps()) {
    params.simultaneous_backtracking_steps = wire.simultaneous_backtracking_steps();
  }
  ApplyPerType(wire.sequential_sigma(), params.sequential_sigma);
  if (wire.has_sequential_rho()) params.sequential_rho = wire.sequential_rho();
  if (wire.has_penalty_invalid()) params.penalty_invalid = wire.penalty_invalid();
  if (wire.has_penalty_repeat()) params.penalty_repeat = wire.penalty_repeat();
  if (wire.has_penalty_success()) params.penalty_success = wire.penalty_success();
  if (wire.has_sequential_stall_iterations()) {
    params.sequential_stall_iterations = wire.sequential_stall_iterations();
  }
  if (wire.has_sequential_max_iterations()) {
    params.sequential_max_iterations = wire.sequential_max_iterations();
  }
  if (wire.has_sequential_improvement_tolerance()) {
    params.sequential_improvement_tolerance = wire.sequential_improvement_tolerance();
  }
  if (wire.has_sequential_backtracking_steps()) {
    params.sequential_backtracking_steps = wire.sequential_backtracking_steps();
  }
  if (wire.has_sequential_transform_blockers()) {
    params.sequential_transform_blockers = wire.sequential_transform_blockers();
  }
  if (wire.has_sequential_cycle()) params.sequential_cycle = wire.sequential_cycle();
  if (wire.has_sequential_batch()) params.sequential_batch = wire.sequential_batch();
  if (wire.has_sequential_batch_elements()) {
    params.sequential_batch_elements = wire.sequential_batch_elements();
  }
  if (wire.has_sequential_batch_band()) {
    params.sequential_batch_band = wire.sequential_batch_band();
  }
  if (wire.has_gamma()) params.gamma = wire.gamma();
  if (wire.has_laplace_tolerance()) params.laplace_tolerance = wire.laplace_tolerance();
  if (wire.has_laplace_max_iterations()) {
    params.laplace_max_iterations = wire.laplace_max_iterations();
  }
  if (wire.has_untangle()) params.untangle = wire.untangle();
  if (wire.has_untangle_max_iterations()) {
    params.untangle_max_iterations = wire.untangle_max_iterations();
  }
  if (absl::Status boundary = ApplyBoundary(wire, params); !boundary.ok()) return boundary;
  if (wire.has_untangle_free_boundary()) {
    params.untangle_free_boundary = wire.untangle_free_boundary();
  }
  if (wire.has_sequential_handoff_window()) {
    params.sequential_handoff_window = wire.sequential_handoff_window();
  }
  if (wire.has_polish_over_relaxation()) {
    params.polish_over_relaxation = wire.polish_over_relaxation();
  }
  if (wire.has_polish_worst_exponent()) params.polish_worst_exponent = wire.polish_worst_exponent();
  if (wire.has_polish_worst_tolerance()) {
    params.polish_worst_tolerance = wire.polish_worst_tolerance();
  }
  if (wire.has_polish_worst_max_sweeps()) {
    params.polish_worst_max_sweeps = wire.polish_worst_max_sweeps();
  }
  if (wire.has_polish_cluster_trigger()) {
    params.polish_cluster_trigger = wire.polish_cluster_trigger();
  }
  if (wire.has_polish_cluster_band()) params.polish_cluster_band = wire.polish_cluster_band();
  if (wire.has_polish_cluster_exponent()) {
    params.polish_cluster_exponent = wire.polish_cluster_exponent();
  }
  if (wire.has_polish_cluster_tolerance()) {
    params.polish_cluster_tolerance = wire.polish_cluster_tolerance();
  }
  if (wire.has_polish_cluster_max_rounds()) {
    params.polish_cluster_max_rounds = wire.polish_cluster_max_rounds();
  }
  if (wire.has_polish_cluster_iterations()) {
    params.polish_cluster_iterations = wire.polish_cluster_iterations();
  }
  if (wire.has_polish_cluster_ascent_iterations()) {
    params.polish_cluster_ascent_iterations = wire.polish_cluster_ascent_iterations();
  }
  if (wire.has_polish()) params.polish = wire.polish();
  if (wire.has_polish_tolerance()) params.polish_tolerance = wire.polish_tolerance();
  if (wire.has_polish_final_tolerance()) {
    params.polish_final_tolerance = wire.polish_final_tolerance();
  }
  if (wire.has_polish_max_sweeps()) params.polish_max_sweeps = wire.polish_max_sweeps();
  if (wire.has_polish_node_tolerance()) {
    params.polish_node_tolerance = wire.polish_node_tolerance();
  }
  if (wire.has_polish_backtracking_steps()) {
    params.polish_backtracking_steps = wire.polish_backtracking_steps();
  }
  if (wire.has_simultaneous_handoff_window()) {
    params.simultaneous_handoff_window = wire.simultaneous_handoff_window();
  }
  if (wire.has_simultaneous_handoff_gain()) {
    params.simultaneous_handoff_gain = wire.simultaneous_handoff_gain();
  }
  params.threads = wire.threads() > 0 ? wire.threads() : default_threads;
  if (wire.threads() < 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("parameters.threads = ", wire.threads(), " is out of range: must be >= 0"));
  }

  // The engine names the field (its names are the wire's); say where it sits in the request.
  if (absl::Status valid = params.Validate(); !valid.ok()) {
    return absl::InvalidArgumentError(absl::StrCat("parameters: ", valid.message()));
  }
  return params;
}

v1::SmoothingParameters ToWireParameters(const SmoothingParams& params) {
  const SmoothingParams defaults;
  v1::SmoothingParameters wire;
  wire.set_method(ToWireMethod(params.method));
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
  SetIfChanged(params.sequential_batch, defaults.sequential_batch, [&](std::int64_t v) { wire.set_sequential_batch(v); });
  SetIfChanged(params.sequential_batch_elements, defaults.sequential_batch_elements, [&](std::int64_t v) { wire.set_sequential_batch_elements(v); });
  SetIfChanged(params.sequential_batch_band, defaults.sequential_batch_band, [&](double v) { wire.set_sequential_batch_band(v); });
  SetIfChanged(params.gamma, defaults.gamma, [&](double v) { wire.set_gamma(v); });
  SetIfChanged(params.laplace_tolerance, defaults.laplace_tolerance, [&](double v) { wire.set_laplace_tolerance(v); });
  SetIfChanged(params.laplace_max_iterations, defaults.laplace_max_iterations, [&](std::int64_t v) { wire.set_laplace_max_iterations(v); });
  SetIfChanged(params.untangle, defaults.untangle, [&](bool v) { wire.set_untangle(v); });
  SetIfChanged(params.untangle_max_iterations, defaults.untangle_max_iterations, [&](std::int64_t v) { wire.set_untangle_max_iterations(v); });
  SetIfChanged(params.fix_boundary, defaults.fix_boundary, [&](bool v) { wire.set_free_boundary(!v); });
  // A sliding boundary goes as the enum; a free one keeps its older spelling, which servers that
  // predate the enum understand too.
  SetIfChanged(params.slide_boundary, defaults.slide_boundary, [&](bool) { wire.set_boundary(v1::BOUNDARY_SLIDE); });
  SetIfChanged(params.feature_angle_degrees, defaults.feature_angle_degrees, [&](double v) { wire.set_feature_angle_degrees(v); });
  SetIfChanged(params.keep_layers, defaults.keep_layers, [&](bool v) { wire.set_keep_layers(v); });
  SetIfChanged(params.threads, defaults.threads, [&](int v) { wire.set_threads(v); });
  SetIfChanged(params.untangle_free_boundary, defaults.untangle_free_boundary, [&](bool v) { wire.set_untangle_free_boundary(v); });
  SetIfChanged(params.polish, defaults.polish, [&](bool v) { wire.set_polish(v); });
  SetIfChanged(params.sequential_handoff_window, defaults.sequential_handoff_window, [&](std::int64_t v) { wire.set_sequential_handoff_window(v); });
  SetIfChanged(params.polish_over_relaxation, defaults.polish_over_relaxation, [&](double v) { wire.set_polish_over_relaxation(v); });
  SetIfChanged(params.polish_worst_exponent, defaults.polish_worst_exponent, [&](double v) { wire.set_polish_worst_exponent(v); });
  SetIfChanged(params.polish_worst_tolerance, defaults.polish_worst_tolerance, [&](double v) { wire.set_polish_worst_tolerance(v); });
  SetIfChanged(params.polish_worst_max_sweeps, defaults.polish_worst_max_sweeps, [&](std::int64_t v) { wire.set_polish_worst_max_sweeps(v); });
  SetIfChanged(params.polish_cluster_trigger, defaults.polish_cluster_trigger, [&](double v) { wire.set_polish_cluster_trigger(v); });
  SetIfChanged(params.polish_cluster_band, defaults.polish_cluster_band, [&](double v) { wire.set_polish_cluster_band(v); });
  SetIfChanged(params.polish_cluster_exponent, defaults.polish_cluster_exponent, [&](double v) { wire.set_polish_cluster_exponent(v); });
  SetIfChanged(params.polish_cluster_tolerance, defaults.polish_cluster_tolerance, [&](double v) { wire.set_polish_cluster_tolerance(v); });
  SetIfChanged(params.polish_cluster_max_rounds, defaults.polish_cluster_max_rounds, [&](std::int64_t v) { wire.set_polish_cluster_max_rounds(v); });
  SetIfChanged(params.polish_cluster_iterations, defaults.polish_cluster_iterations, [&](std::int64_t v) { wire.set_polish_cluster_iterations(v); });
  SetIfChanged(params.polish_cluster_ascent_iterations, defaults.polish_cluster_ascent_iterations, [&](std::int64_t v) { wire.set_polish_cluster_ascent_iterations(v); });
  SetIfChanged(params.polish_tolerance, defaults.polish_tolerance, [&](double v) { wire.set_polish_tolerance(v); });
  SetIfChanged(params.polish_final_tolerance, defaults.polish_final_tolerance, [&](double v) { wire.set_polish_final_tolerance(v); });
  SetIfChanged(params.polish_max_sweeps, defaults.polish_max_sweeps, [&](std::int64_t v) { wire.set_polish_max_sweeps(v); });
  SetIfChanged(params.polish_node_tolerance, defaults.polish_node_tolerance, [&](double v) { wire.set_polish_node_tolerance(v); });
  SetIfChanged(params.polish_backtracking_steps, defaults.polish_backtracking_steps, [&](int v) { wire.set_polish_backtracking_steps(v); });
  SetIfChanged(params.simultaneous_handoff_window, defaults.simultaneous_handoff_window, [&](std::int64_t v) { wire.set_simultaneous_handoff_window(v); });
  SetIfChanged(params.simultaneous_handoff_gain, defaults.simultaneous_handoff_gain, [&](double v) { wire.set_simultaneous_handoff_gain(v); });
  // clang-format on
  return wire;
}

}  // namespace getme::wire
