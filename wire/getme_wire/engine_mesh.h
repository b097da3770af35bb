#pragma once

#include <span>

#include "absl/status/status.h"
#include "getme/mesh/mesh.h"
#include "getme/v1/mesh.pb.h"

namespace getme::wire {

// A whole engine mesh as one wire mesh and back, for programs that hold an engine mesh (the
// benchmarks, tests, a generator's output) rather than a file.

// Fixed nodes are listed from the mesh's flags, no ids. Element numbering changes to the wire's
// (by type) unless the mesh already was in that order.
v1::Mesh ToWireMesh(const Mesh& mesh);

// The coordinates of a wire mesh as a span (x0, y0, z0, x1, …).
inline std::span<const double> CoordinatesOf(const v1::Mesh& mesh) {
  return {mesh.coordinates().data(), static_cast<std::size_t>(mesh.coordinates().size())};
}

// Writes smoothed coordinates (x0, y0, z0, x1, …, as on the wire) into the mesh. InvalidArgument
// if the count does not match its nodes.
absl::Status ApplyCoordinates(std::span<const double> coordinates, Mesh& mesh);
// The same check alone, for targets of other kinds (a file's grid).
absl::Status CheckCoordinateCount(std::span<const double> coordinates, std::int64_t nodes);

}  // namespace getme::wire
