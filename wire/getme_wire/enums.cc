#include "getme_wire/enums.h"

#include <array>
#include <utility>

namespace getme::wire {
namespace {

constexpr std::array<std::pair<Method, v1::Method>, 6> kMethods = {{
    {Method::kGetme, v1::METHOD_GETME},
    {Method::kSimultaneous, v1::METHOD_SIMULTANEOUS},
    {Method::kSequential, v1::METHOD_SEQUENTIAL},
    {Method::kWarpage, v1::METHOD_WARPAGE},
    {Method::kSmartLaplace, v1::METHOD_SMART_LAPLACE},
    {Method::kLaplace, v1::METHOD_LAPLACE},
}};

constexpr std::array<std::pair<Phase, v1::Phase>, 8> kPhases = {{
    {Phase::kUntangle, v1::PHASE_UNTANGLE},
    {Phase::kSimultaneous, v1::PHASE_SIMULTANEOUS},
    {Phase::kSequential, v1::PHASE_SEQUENTIAL},
    {Phase::kWarpage, v1::PHASE_WARPAGE},
    {Phase::kSmartLaplace, v1::PHASE_SMART_LAPLACE},
    {Phase::kLaplace, v1::PHASE_LAPLACE},
    {Phase::kPolish, v1::PHASE_POLISH},
    {Phase::kLayers, v1::PHASE_LAYERS},
}};

template <typename Engine, typename Wire, std::size_t kSize>
Wire ToWire(const std::array<std::pair<Engine, Wire>, kSize>& table, Engine value) {
  for (const auto& [engine, wire] : table) {
    if (engine == value) return wire;
  }
  return Wire{};
}

template <typename Engine, typename Wire, std::size_t kSize>
std::optional<Engine> FromWire(const std::array<std::pair<Engine, Wire>, kSize>& table, int value) {
  for (const auto& [engine, wire] : table) {
    if (static_cast<int>(wire) == value) return engine;
  }
  return std::nullopt;
}

}  // namespace

v1::Method ToWireMethod(Method method) { return ToWire(kMethods, method); }

std::optional<Method> FromWireMethod(int method) {
  if (method == v1::METHOD_UNSPECIFIED) return Method::kGetme;
  return FromWire(kMethods, method);
}

v1::Phase ToWirePhase(Phase phase) { return ToWire(kPhases, phase); }

std::optional<Phase> FromWirePhase(int phase) { return FromWire(kPhases, phase); }

v1::Boundary ToWireBoundary(const SmoothingParams& params) {
  if (!params.fix_boundary) return v1::BOUNDARY_FREE;
  return params.slide_boundary ? v1::BOUNDARY_SLIDE : v1::BOUNDARY_FIXED;
}

const char* BoundaryName(v1::Boundary boundary) {
  switch (boundary) {
    case v1::BOUNDARY_FIXED:
      return "fixed";
    case v1::BOUNDARY_SLIDE:
      return "slide";
    case v1::BOUNDARY_FREE:
      return "free";
    default:
      return "unspecified";
  }
}

Method MethodOrGetme(v1::Method method) { return FromWireMethod(method).value_or(Method::kGetme); }

Phase PhaseOrSimultaneous(v1::Phase phase) {
  return FromWirePhase(phase).value_or(Phase::kSimultaneous);
}

}  // namespace getme::wire
