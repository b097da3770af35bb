#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"

namespace getme::formats {

// What an Exodus element block holds, in getme's terms.
struct ExodusTopology {
  int vtk_type = 0;    // VTK cell code of its elements (10, 12, 13, 14; 5, 9, 3, 1 pass through)
  int node_count = 0;  // linear elements only
  absl::string_view written_name;  // the type name getme writes for such cells
};

// The topology of a block whose element type is `type_name` with `nodes_per_element` nodes.
// Exodus writers spell types freely: the name is matched ignoring case and trailing blanks, by
// its letters ("TETRA", "TET", "HEX", "HEXAHEDRON", "WEDGE", "PYRAMID", "PYRA"; passed through:
// "TRI", "TRIANGLE", "TRISHELL", "SHELL", "QUAD", "BAR", "BEAM", "TRUSS", "EDGE", "SPHERE",
// "CIRCLE"), a trailing node count ("TET4", "HEX8") must match the block's. SHELL with 3 nodes
// is a triangle. InvalidArgument (text without the block, which the caller adds) for unknown
// types, for higher-order elements (HEX20, TETRA10: getme smooths linear elements) and for a node
// count the type does not have.
absl::StatusOr<ExodusTopology> TopologyOfBlock(absl::string_view type_name,
                                               std::int64_t nodes_per_element);

// The topology getme writes for cells of VTK type `vtk_type`, or nullopt if Exodus cannot hold
// them here (voxels, quadratic cells, polyhedra, …).
std::optional<ExodusTopology> TopologyOfVtkCell(int vtk_type);

// Exodus numbers tetrahedra, pyramids, hexahedra and wedges as the paper does (the manual's
// element figures, "Element Types"), so only the wedge differs from VTK's order: Exodus
// (e0..e5) = VTK (v0, v2, v1, v3, v5, v4) (core/getme/elements/node_orders.h). Converts one
// element's nodes in place, either direction.
void ConvertExodusVtkOrder(int vtk_type, std::span<std::int64_t> nodes);

// The number of sides of a volume element (tetra 4, pyramid 5, wedge 5, hexahedron 6); 0 for
// other cells, whose sides getme does not keep.
int SideCount(int vtk_type);

// The local nodes (0-based, Exodus order) of side `side` (1-based) of a volume element, as the
// Exodus II manual's "Side Set Node Ordering" table lists them: each side counter-clockwise seen
// from outside. Used to find a face's side when writing; the reader gets the faces from the
// library itself (ex_get_side_set_node_list), and the tests check that both agree.
struct ExodusSide {
  std::array<int, 4> nodes{};
  int size = 0;
};
ExodusSide SideNodes(int vtk_type, int side);

}  // namespace getme::formats
