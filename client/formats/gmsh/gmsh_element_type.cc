#include "formats/gmsh/gmsh_element_type.h"

#include "getme/elements/node_orders.h"

namespace getme::formats {
namespace {

// Gmsh's element types (GmshDefines.h, "MSH_*"). Only the linear ones map to VTK cells: getme
// smooths linear elements, and second-order files are rejected by name rather than guessed at.
// The higher-order entries are here so that a message names them and a binary 2.2 block of them
// can be measured.
constexpr std::array<GmshElementTypeInfo, 31> kTypes = {{
    {1, "2-node line", 2, 1, 3},
    {2, "3-node triangle", 3, 2, 5},
    {3, "4-node quadrangle", 4, 2, 9},
    {4, "4-node tetrahedron", 4, 3, 10},
    {5, "8-node hexahedron", 8, 3, 12},
    {6, "6-node prism", 6, 3, 13},
    {7, "5-node pyramid", 5, 3, 14},
    {8, "3-node second-order line", 3, 1, 0},
    {9, "6-node second-order triangle", 6, 2, 0},
    {10, "9-node second-order quadrangle", 9, 2, 0},
    {11, "10-node second-order tetrahedron", 10, 3, 0},
    {12, "27-node second-order hexahedron", 27, 3, 0},
    {13, "18-node second-order prism", 18, 3, 0},
    {14, "14-node second-order pyramid", 14, 3, 0},
    {15, "1-node point", 1, 0, 1},
    {16, "8-node second-order quadrangle", 8, 2, 0},
    {17, "20-node second-order hexahedron", 20, 3, 0},
    {18, "15-node second-order prism", 15, 3, 0},
    {19, "13-node second-order pyramid", 13, 3, 0},
    {20, "9-node third-order incomplete triangle", 9, 2, 0},
    {21, "10-node third-order triangle", 10, 2, 0},
    {22, "12-node fourth-order incomplete triangle", 12, 2, 0},
    {23, "15-node fourth-order triangle", 15, 2, 0},
    {24, "15-node fifth-order incomplete triangle", 15, 2, 0},
    {25, "21-node fifth-order complete triangle", 21, 2, 0},
    {26, "4-node third-order edge", 4, 1, 0},
    {27, "5-node fourth-order edge", 5, 1, 0},
    {28, "6-node fifth-order edge", 6, 1, 0},
    {29, "20-node third-order tetrahedron", 20, 3, 0},
    {30, "35-node fourth-order tetrahedron", 35, 3, 0},
    {31, "56-node fifth-order tetrahedron", 56, 3, 0},
}};

}  // namespace

std::optional<GmshElementTypeInfo> GmshElementType(int code) {
  if (code < 1 || code > static_cast<int>(kTypes.size())) return std::nullopt;
  return kTypes[code - 1];
}

std::optional<GmshElementTypeInfo> GmshElementTypeOfVtk(int vtk_code) {
  if (vtk_code == 0) return std::nullopt;
  for (const GmshElementTypeInfo& info : kTypes) {
    if (info.vtk_code == vtk_code) return info;
  }
  return std::nullopt;
}

int GmshNodeOfVtkNode(int gmsh_code, int vtk_node) {
  // Gmsh's 6-node prism is the paper's; VTK's wedge lists each triangle the other way round.
  return gmsh_code == 6 ? kVtkWedgeToPaperPrism[vtk_node] : vtk_node;
}

}  // namespace getme::formats
