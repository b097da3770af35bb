#pragma once

#include <array>
#include <optional>

#include "absl/strings/string_view.h"

namespace getme::formats {

// A Gmsh element type code (the MSH "elm-type") and how it maps to a VTK cell.
struct GmshElementTypeInfo {
  int code;
  absl::string_view name;  // Gmsh's own wording, for messages ("4-node tetrahedron")
  int node_count;
  int dim;
  // The VTK cell type code, or 0 for the types getme does not read (second and higher order).
  int vtk_code;
};

// nullopt for codes Gmsh does not define (or this table does not know).
std::optional<GmshElementTypeInfo> GmshElementType(int code);

// The Gmsh type of a VTK cell type code; nullopt for cells MSH cannot hold here.
std::optional<GmshElementTypeInfo> GmshElementTypeOfVtk(int vtk_code);

// The Gmsh node index of VTK node `vtk_node` of a cell of Gmsh type `gmsh_code`: the identity for
// every type but the prism: Gmsh's prism (6) is the paper's order, VTK's wedge is mirrored against
// it (docs/node-orders.md): VTK (v0..v5) = Gmsh (g0, g2, g1, g3, g5, g4). That permutation is its
// own inverse, so it maps both ways.
int GmshNodeOfVtkNode(int gmsh_code, int vtk_node);

}  // namespace getme::formats
