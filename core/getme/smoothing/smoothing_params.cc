#include "getme/smoothing/smoothing_params.h"

#include <array>
#include <cmath>
#include <utility>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"

namespace getme {
namespace {

constexpr std::array<std::pair<const char*, Method>, 6> kMethodNames = {{
    {"getme", Method::kGetme},
    {"simultaneous", Method::kSimultaneous},
    {"sequential", Method::kSequential},
    {"warpage", Method::kWarpage},
    {"smart-laplace", Method::kSmartLaplace},
    {"laplace", Method::kLaplace},
}};

absl::Status OutOfRange(absl::string_view field, double value, absl::string_view allowed) {
  return absl::InvalidArgumentError(
      absl::StrCat("parameter ", field, " = ", value, " is out of range: must be ", allowed));
}

bool Finite(double v) { return std::isfinite(v); }

absl::Status CheckPositive(absl::string_view field, double value) {
  if (!Finite(value) || !(value > 0.0)) return OutOfRange(field, value, "> 0");
  return absl::OkStatus();
}

absl::Status CheckUnitInterval(absl::string_view field, double value, bool allow_zero) {
  const bool ok = Finite(value) && value <= 1.0 && (allow_zero ? value >= 0.0 : value > 0.0);
  if (!ok) return OutOfRange(field, value, allow_zero ? "in [0, 1]" : "in (0, 1]");
  return absl::OkStatus();
}

absl::Status CheckNonNegative(absl::string_view field, double value) {
  if (!Finite(value) || value < 0.0) return OutOfRange(field, value, ">= 0");
  return absl::OkStatus();
}

}  // namespace

const char* MethodName(Method method) {
  for (const auto& [name, value] : kMethodNames) {
    if (value == method) return name;
  }
  return "unknown";
}

absl::StatusOr<Method> ParseMethod(std::string_view name) {
  for (const auto& [method_name, value] : kMethodNames) {
    if (method_name == name) return value;
  }
  std::vector<std::string> names;
  for (const auto& entry : kMethodNames) names.push_back(entry.first);
  return absl::InvalidArgumentError(absl::StrCat(
      "unknown method '", std::string(name), "': expected one of ", absl::StrJoin(names, ", ")));
}

absl::Status SmoothingParams::Validate() const {
  for (ElementType type : kAllElementTypes) {
    const int t = TypeIndex(type);
    const std::string suffix = absl::StrCat("[", TypeName(type), "]");
    if (auto s = CheckPositive("simultaneous_sigma_min" + suffix, simultaneous_sigma_min[t]);
        !s.ok()) {
      return s;
    }
    if (auto s = CheckPositive("simultaneous_sigma_max" + suffix, simultaneous_sigma_max[t]);
        !s.ok()) {
      return s;
    }
    if (simultaneous_sigma_max[t] < simultaneous_sigma_min[t]) {
      return OutOfRange(
          "simultaneous_sigma_max" + suffix, simultaneous_sigma_max[t],
          absl::StrCat(">= simultaneous_sigma_min", suffix, " = ", simultaneous_sigma_min[t]));
    }
    if (auto s = CheckPositive("sequential_sigma" + suffix, sequential_sigma[t]); !s.ok()) return s;
  }
  struct UnitField {
    absl::string_view name;
    double value;
    bool allow_zero;
  };
  for (const UnitField& field :
       {UnitField{"simultaneous_rho", simultaneous_rho, false},
        UnitField{"sequential_rho", sequential_rho, false}, UnitField{"gamma", gamma, false}}) {
    if (auto s = CheckUnitInterval(field.name, field.value, field.allow_zero); !s.ok()) return s;
  }
  for (const auto& [name, value] :
       {std::pair<absl::string_view, double>{"simultaneous_eta", simultaneous_eta},
        {"simultaneous_tolerance", simultaneous_tolerance},
        {"penalty_invalid", penalty_invalid},
        {"penalty_repeat", penalty_repeat},
        {"penalty_success", penalty_success},
        {"laplace_tolerance", laplace_tolerance},
        {"sequential_improvement_tolerance", sequential_improvement_tolerance},
        {"sequential_batch_band", sequential_batch_band},
        {"polish_tolerance", polish_tolerance},
        {"polish_final_tolerance", polish_final_tolerance},
        {"polish_node_tolerance", polish_node_tolerance},
        {"simultaneous_handoff_gain", simultaneous_handoff_gain},
        {"polish_worst_tolerance", polish_worst_tolerance},
        {"polish_worst_exponent", polish_worst_exponent},
        {"polish_cluster_trigger", polish_cluster_trigger},
        {"polish_cluster_band", polish_cluster_band},
        {"polish_cluster_tolerance", polish_cluster_tolerance}}) {
    if (auto s = CheckNonNegative(name, value); !s.ok()) return s;
  }
  if (!(penalty_invalid > 0.0)) return OutOfRange("penalty_invalid", penalty_invalid, "> 0");
  for (const auto& [name, value] :
       {std::pair<absl::string_view, std::int64_t>{"simultaneous_max_iterations",
                                                   simultaneous_max_iterations},
        {"sequential_max_iterations", sequential_max_iterations},
        {"sequential_stall_iterations", sequential_stall_iterations},
        {"laplace_max_iterations", laplace_max_iterations},
        {"untangle_max_iterations", untangle_max_iterations},
        {"polish_max_sweeps", polish_max_sweeps},
        {"simultaneous_handoff_window", simultaneous_handoff_window},
        {"sequential_handoff_window", sequential_handoff_window},
        {"polish_worst_max_sweeps", polish_worst_max_sweeps},
        {"polish_cluster_max_rounds", polish_cluster_max_rounds},
        {"polish_cluster_iterations", polish_cluster_iterations},
        {"polish_cluster_ascent_iterations", polish_cluster_ascent_iterations}}) {
    if (value < 0) return OutOfRange(name, static_cast<double>(value), ">= 0");
  }
  if (sequential_cycle < 1) {
    return OutOfRange("sequential_cycle", static_cast<double>(sequential_cycle), ">= 1");
  }
  // A batch's picks keep their work buffers between batches (sequential_smoother.cc).
  if (sequential_batch < 1 || sequential_batch > 65536) {
    return OutOfRange("sequential_batch", static_cast<double>(sequential_batch), "in [1, 65536]");
  }
  if (sequential_batch_elements < 1) {
    return OutOfRange("sequential_batch_elements", static_cast<double>(sequential_batch_elements),
                      ">= 1");
  }
  if (simultaneous_backtracking_steps < 0 || simultaneous_backtracking_steps > 30) {
    return OutOfRange("simultaneous_backtracking_steps", simultaneous_backtracking_steps,
                      "in [0, 30]");
  }
  if (sequential_backtracking_steps < 0 || sequential_backtracking_steps > 30) {
    return OutOfRange("sequential_backtracking_steps", sequential_backtracking_steps, "in [0, 30]");
  }
  // c(E)^p must stay finite: c reaches 10⁶ on nearly flat elements, and (10⁶)^32 = 10^192 fits.
  if (!(polish_worst_exponent <= 32.0)) {
    return OutOfRange("polish_worst_exponent", polish_worst_exponent, "in [0, 32]");
  }
  // (q_min / q)^p over a cluster's elements must stay finite while its elements are at most a
  // few thousand times worse than q_min: 1e3^100 would overflow, 1e3^64 does not.
  if (!(polish_cluster_exponent >= 1.0 && polish_cluster_exponent <= 64.0)) {
    return OutOfRange("polish_cluster_exponent", polish_cluster_exponent, "in [1, 64]");
  }
  if (!(feature_angle_degrees >= 0.0 && feature_angle_degrees <= 180.0)) {
    return OutOfRange("feature_angle_degrees", feature_angle_degrees, "in [0, 180]");
  }
  if (slide_boundary && !fix_boundary) {
    return absl::InvalidArgumentError(
        "slide_boundary needs the boundary held (fix_boundary): a free boundary has no surface to "
        "slide on; choose one of the two");
  }
  if (keep_layers && !fix_boundary) {
    return absl::InvalidArgumentError(
        "keep_layers needs the boundary held or sliding (fix_boundary): a free boundary moves the "
        "walls the layer heights are measured from");
  }
  if (!(polish_over_relaxation >= 1.0 && polish_over_relaxation < 2.0)) {
    return OutOfRange("polish_over_relaxation", polish_over_relaxation, "in [1, 2)");
  }
  if (polish_backtracking_steps < 0 || polish_backtracking_steps > 30) {
    return OutOfRange("polish_backtracking_steps", polish_backtracking_steps, "in [0, 30]");
  }
  if (threads < 0 || threads > 1024) return OutOfRange("threads", threads, "in [0, 1024]");
  // Whether this machine runs the width is Smooth()'s FailedPrecondition (element_passes_dispatch).
  if (kernel_lanes != 0 && kernel_lanes != 2 && kernel_lanes != 4 && kernel_lanes != 8) {
    return OutOfRange("kernel_lanes", kernel_lanes, "0, 2, 4 or 8");
  }
  if (untangle_free_boundary && !untangle) {
    // Asking to free the boundary for a phase that does not run is a caller mistake, not a no-op.
    return absl::InvalidArgumentError(
        "untangle_free_boundary = true requires untangle = true (it only affects untangling)");
  }
  return absl::OkStatus();
}

}  // namespace getme
