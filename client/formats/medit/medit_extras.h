#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace getme::formats {

// One keyword section of a MEDIT file that carries no mesh elements (Corners, Ridges,
// RequiredEdges, Normals, NormalAtVertices, Tangents, BoundingBox, …), kept token for token so a
// MEDIT → MEDIT round trip writes it back unchanged. Its indices (vertices, edges, normals, …)
// are 1-based, as in the file.
struct MeditSection {
  std::string keyword;               // in libMeshb's spelling ("Corners"), whatever the file's case
  std::vector<std::string> entries;  // one per data line: its tokens joined by single spaces

  bool operator==(const MeditSection&) const = default;
};

// What only a MEDIT file carries beyond MeshDocument::grid (owned by the MEDIT reader/writer).
struct MeditExtras {
  // MeshVersionFormatted: 1 = single-precision reals, 2 = double, 3 and 4 differ from 2 only in
  // the binary .meshb. Coordinates are kept as the parsed doubles whatever the version.
  int version = 2;
  // RequiredVertices as listed in the file (1-based), so that they are written back in the same
  // order while the grid's `fixed` array still marks exactly these vertices.
  std::optional<std::vector<std::int64_t>> required_vertices;
  // The sections above, in file order.
  std::vector<MeditSection> sections;

  bool operator==(const MeditExtras&) const = default;
};

}  // namespace getme::formats
