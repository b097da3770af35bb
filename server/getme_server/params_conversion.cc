#include "getme_server/params_conversion.h"

#include <optional>
#include <string>

#include "absl/strings/str_cat.h"
#include "getme_wire/enums.h"

namespace getme::server {
namespace {

absl::StatusOr<Method> ToEngineMethod(int method) {
  if (std::optional<Method> known = wire::FromWireMethod(method)) return *known;
  return absl::InvalidArgumentError(
      absl::StrCat("parameters.method = ", method, " is not a known getme.v1.Method"));
}

void ApplyPerType(const v1::PerType& wire, PerType& values) {
  if (wire.has_tetrahedron()) values[TypeIndex(ElementType::kTetrahedron)] = wire.tetrahedron();
  if (wire.has_hexahedron()) values[TypeIndex(ElementType::kHexahedron)] = wire.hexahedron();
  if (wire.has_pyramid()) values[TypeIndex(ElementType::kPyramid)] = wire.pyramid();
  if (wire.has_prism()) values[TypeIndex(ElementType::kPrism)] = wire.prism();
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
  if (wire.has_gamma()) params.gamma = wire.gamma();
  if (wire.has_laplace_tolerance()) params.laplace_tolerance = wire.laplace_tolerance();
  if (wire.has_laplace_max_iterations()) {
    params.laplace_max_iterations = wire.laplace_max_iterations();
  }
  if (wire.has_untangle()) params.untangle = wire.untangle();
  if (wire.has_untangle_max_iterations()) {
    params.untangle_max_iterations = wire.untangle_max_iterations();
  }
  if (wire.has_free_boundary()) params.fix_boundary = !wire.free_boundary();
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

}  // namespace getme::server
