#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "formats/mesh_file.h"
#include "formats/unstructured_grid.h"
#include "getme/v1/mesh.pb.h"

namespace getme::remote {

// A file's grid as a wire mesh for upload, and the smoothed coordinates back into the grid. This
// is the client's side of the wire (a file's grid is not an engine mesh); every engine <-> wire
// mapping lives in wire/ (docs/design.md).

// A grid's volume cells as a wire mesh, and where each wire element came from.
struct GridWireMesh {
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
absl::StatusOr<GridWireMesh> ToWireMesh(const formats::UnstructuredGrid& file);

// Adds a file's tagged triangles and quads (formats::TaggedSurfaceFaces) to the wire mesh as its
// surface groups (mesh.proto: group_triangles, ...), for a sliding boundary. Faces tagged 0 carry
// no group and are not sent, so the server puts them with the untagged boundary, as `getme smooth`
// does. InvalidArgument naming the face (its cell index among the tagged faces) for a tag that
// does not fit uint32.
absl::Status AddSurfaceGroups(std::span<const formats::TaggedFace> faces, v1::Mesh& mesh);

// Writes smoothed coordinates (x0, y0, z0, x1, …, as on the wire) into the file's POINTS as
// doubles. InvalidArgument if the count does not match the file's points.
absl::Status ApplyCoordinates(std::span<const double> coordinates, formats::UnstructuredGrid& file);
}  // namespace getme::remote
