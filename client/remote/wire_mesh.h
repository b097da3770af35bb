#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "formats/vtk_file.h"
#include "getme/mesh/mesh.h"
#include "getme/v1/mesh.pb.h"

namespace getme::remote {

// A VTK file's volume cells as a wire mesh, and where each wire element came from.
struct VtkWireMesh {
  v1::Mesh mesh;
  // Wire element index (tetrahedra first, then hexahedra, wedges, pyramids; mesh.proto) → the
  // file's cell index, so the server's element numbers can be told as cell numbers.
  std::vector<std::int64_t> element_cells;
};

// Converts without validating beyond what the wire cannot represent: the server checks the mesh
// and names what is wrong (so a malformed file gets the server's INVALID_ARGUMENT message). Points
// become nodes with the same index; tetra (10), hexahedron (12), wedge (13) and pyramid (14) cells
// become elements in VTK node order; lines, triangles, quads… are passthrough and not sent; a
// nonzero `fixed` point-data value marks a fixed node. InvalidArgument for cells of any other
// type, a node id that does not fit uint32, or a `fixed` array of the wrong length.
absl::StatusOr<VtkWireMesh> ToWireMesh(const formats::VtkFile& file);

// An engine mesh as a wire mesh (paper prisms mirrored back to VTK wedges, fixed nodes listed).
// Element numbering changes to the wire's (by type) unless the mesh already was in that order.
v1::Mesh ToWireMesh(const Mesh& mesh);

// The coordinates of a wire mesh as a span (x0, y0, z0, x1, …).
inline std::span<const double> CoordinatesOf(const v1::Mesh& mesh) {
  return {mesh.coordinates().data(), static_cast<std::size_t>(mesh.coordinates().size())};
}

// Writes smoothed coordinates (x0, y0, z0, x1, …, as on the wire) into the file's POINTS as
// doubles. InvalidArgument if the count does not match the file's points.
absl::Status ApplyCoordinates(std::span<const double> coordinates, formats::VtkFile& file);
// The same into an engine mesh.
absl::Status ApplyCoordinates(std::span<const double> coordinates, Mesh& mesh);

}  // namespace getme::remote
