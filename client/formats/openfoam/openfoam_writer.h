#pragma once

#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// The files of the polyMesh of `document`. Read from a polyMesh (MeshDocument::openfoam): faces,
// owner, neighbour, boundary and the zone files exactly as read, and the points file with only
// its list replaced by the grid's points, in the points file's own encoding (ASCII: shortest
// decimals that read back bit-identical; binary: raw little-endian doubles, or floats for
// scalar=32) and compression. From another format: faces, owners and patches built from the
// cells first (BuildPolyMesh, polymesh_builder.h), in `options.encoding`.
//
// InvalidArgument when the cells cannot make a polyMesh (BuildPolyMesh says which), when the
// point count differs from the polyMesh's, or when `options.encoding` asks for another encoding
// than the points file's of a polyMesh read back.
absl::StatusOr<std::vector<PolyMeshFile>> SerializeOpenFoam(const MeshDocument& document,
                                                            const WriteOptions& options);

// The polyMesh directory that writing to `path` fills: `path` itself when its last component is
// "polyMesh", else path/constant/polyMesh (a case directory, as OpenFOAM's utilities expect).
std::string PolyMeshDirectoryFor(const std::string& path);

// Writes SerializeOpenFoam's files into PolyMeshDirectoryFor(path), creating the directories,
// each file atomically. InvalidArgument when a file of the other compression is already there
// (faces beside a faces.gz to be written): OpenFOAM would read either.
absl::Status WriteOpenFoam(const std::string& path, const MeshDocument& document,
                           const WriteOptions& options);

}  // namespace getme::formats
