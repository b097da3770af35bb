#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace getme::formats {

// A file of a polyMesh directory kept byte for byte (as read, gzip compressed if it was).
struct PolyMeshFile {
  std::string name;  // "faces", "owner.gz", "cellZones", …
  std::string bytes;

  bool operator==(const PolyMeshFile&) const = default;
};

// One boundary patch (the boundary file's entries, in file order).
struct OpenFoamPatch {
  std::string name;
  std::string type;  // patch, wall, empty, symmetryPlane, …
  std::int64_t start_face = 0;
  std::int64_t face_count = 0;

  bool operator==(const OpenFoamPatch&) const = default;
};

// What only an OpenFOAM polyMesh carries beyond MeshDocument::grid (owned by the OpenFOAM
// reader/writer). The grid holds the points and the cells getme understands; everything else is
// here so that writing the directory back changes nothing but the points.
struct OpenFoamExtras {
  // The patches; boundary face cells of the grid carry their 1-based position in the cell array
  // "openfoam:patch" (0 for volume cells).
  std::vector<OpenFoamPatch> patches;
  // faces, owner, neighbour, boundary and the zone files present (cellZones, faceZones,
  // pointZones), byte for byte, under the names they were read from.
  std::vector<PolyMeshFile> files;
  // The points file: its name, the bytes before its list (banner, FoamFile header, comments) and
  // after it, decompressed, so only the list is rewritten; its encoding.
  std::string points_name = "points";
  bool points_gzipped = false;
  std::string points_before;
  std::string points_after;
  bool points_binary = false;
  int scalar_bytes = 8;  // binary points: 8 (scalar=64) or 4 (scalar=32)
  // Counts of the mesh read, for the writer's checks and the read summary.
  std::int64_t point_count = 0;
  std::int64_t cell_count = 0;
  std::int64_t polyhedron_count = 0;

  bool operator==(const OpenFoamExtras&) const = default;
};

}  // namespace getme::formats
