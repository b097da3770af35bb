#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace getme::formats {

// One SU2 boundary marker (MARKER_TAG / MARKER_ELEMS): its name as the file spells it and the
// value its boundary cells carry in the grid's cell array "su2:tag".
struct Su2Marker {
  std::string name;
  std::int64_t tag = 0;

  bool operator==(const Su2Marker&) const = default;
};

// What only an SU2 native mesh file carries beyond MeshDocument::grid (owned by the SU2
// reader/writer).
struct Su2Extras {
  // The markers in file order, so that an SU2 → SU2 round trip writes them back in that order
  // and `--fix-group NAME` finds a marker by its name.
  std::vector<Su2Marker> markers;
  // Whether the element rows and the point rows end with their running index, as SU2's own
  // writer numbers them (meshio's writer does not).
  bool element_indices = true;
  bool point_indices = true;
  // The grid cells (ascending) whose node order the reader mirrored: each came with every corner
  // Jacobian negative in VTK's convention (su2_mirrored_elements.h). The writer mirrors them
  // back, so SU2 output has the file's own node order.
  std::vector<std::int64_t> mirrored_cells;
  // The text after the last mesh section (SU2's NPERIODIC / PERIODIC_INDEX and FFD_* sections of
  // a deformed mesh), kept verbatim: it refers to points by index, which nothing renumbers.
  std::string tail;

  bool operator==(const Su2Extras&) const = default;
};

}  // namespace getme::formats
