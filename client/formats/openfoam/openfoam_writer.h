#pragma once

#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// The files of the polyMesh of `document`, which must have been read from a polyMesh
// (MeshDocument::openfoam): faces, owner, neighbour, boundary and the zone files exactly as read,
// and the points file with only its list replaced by the grid's points, in the points file's
// own encoding (ASCII: shortest decimals that read back bit-identical; binary: raw little-endian
// doubles, or floats for scalar=32) and compression.
//
// InvalidArgument when the document has no OpenFOAM extras (building faces, owners and patches
// from cells of another format is not implemented), when its point count differs from the
// polyMesh's, or when `options.encoding` asks for another encoding than the points file's.
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
