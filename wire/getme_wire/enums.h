#pragma once

#include <optional>

#include "getme/smoothing/progress.h"
#include "getme/smoothing/smoothing_params.h"
#include "getme/v1/params.pb.h"
#include "getme/v1/smoother.pb.h"

// The one mapping between the engine's enums and the wire's, shared by server and client.
namespace getme::wire {

v1::Method ToWireMethod(Method method);
// METHOD_UNSPECIFIED is GETMe (the proto's documented default); nullopt for values this build
// does not know (a newer peer).
std::optional<Method> FromWireMethod(int method);

v1::Phase ToWirePhase(Phase phase);
std::optional<Phase> FromWirePhase(int phase);  // nullopt for unspecified or unknown values

// The engine has no boundary enum: fix_boundary and slide_boundary say it (smoothing_params.h).
// BOUNDARY_FIXED, BOUNDARY_SLIDE or BOUNDARY_FREE; never BOUNDARY_UNSPECIFIED.
v1::Boundary ToWireBoundary(const SmoothingParams& params);
// "fixed", "slide" or "free", as the CLI's --boundary, the Python keyword and the dashboard name
// them; "unspecified" for BOUNDARY_UNSPECIFIED (a server that predates the field) and values
// this build does not know.
const char* BoundaryName(v1::Boundary boundary);

// For display, where any value must read as something: values a newer peer may send fall back to
// GETMe / the simultaneous phase.
Method MethodOrGetme(v1::Method method);
Phase PhaseOrSimultaneous(v1::Phase phase);

}  // namespace getme::wire
