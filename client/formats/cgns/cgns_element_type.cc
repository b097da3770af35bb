#include "formats/cgns/cgns_element_type.h"

#include <cgnslib.h>

#include <array>

#include "absl/strings/str_cat.h"
#include "formats/cgns/cgns_functions.h"
#include "formats/vtk_cell_type.h"
#include "getme/elements/node_orders.h"

namespace getme::formats::cgns {
namespace {

constexpr std::array<ElementKind, 8> kKinds = {{
    {NODE, 1, 1},
    {BAR_2, 3, 2},
    {TRI_3, kVtkTriangle, 3},
    {QUAD_4, kVtkQuad, 4},
    {TETRA_4, kVtkTetra, 4},
    {PYRA_5, kVtkPyramid, 5},
    {PENTA_6, kVtkWedge, 6},
    {HEXA_8, kVtkHexahedron, 8},
}};

}  // namespace

std::optional<ElementKind> KindOfCgnsType(int cgns_type) {
  for (const ElementKind& kind : kKinds) {
    if (kind.cgns_type == cgns_type) return kind;
  }
  return std::nullopt;
}

std::optional<ElementKind> KindOfVtkType(int vtk_type) {
  for (const ElementKind& kind : kKinds) {
    if (kind.vtk_type == vtk_type) return kind;
  }
  return std::nullopt;
}

int CgnsPosition(int vtk_type, int vtk_position) {
  return vtk_type == kVtkWedge ? kVtkWedgeToPaperPrism[vtk_position] : vtk_position;
}

std::string CgnsTypeName(int cgns_type) {
  if (cgns_type >= 0 && cgns_type < NofValidElementTypes) {
    return Cgns().cg_ElementTypeName(static_cast<CGNS_ENUMT(ElementType_t)>(cgns_type));
  }
  return absl::StrCat("element type ", cgns_type);
}

}  // namespace getme::formats::cgns
