#pragma once

#include <array>
#include <span>

#include "getme/elements/element_type.h"

namespace getme {

// The one node-order table between the paper's elements (Fig. 1) and the VTK cell order that the
// wire (proto/getme/v1/mesh.proto) and the neutral grid of the file formats use.
//
// Tetrahedra, hexahedra and pyramids are numbered alike in both. Prisms are not: the paper's
// prism has its first triangle (p0, p1, p2) counter-clockwise seen from the opposite triangle,
// VTK_WEDGE clockwise, so paper (p0..p5) = VTK (v0, v2, v1, v3, v5, v4). Gmsh, MEDIT and meshio
// number prisms as the paper does. Mirroring twice is the identity: the same table converts in
// both directions (docs/node-orders.md).
inline constexpr std::array<int, 6> kVtkWedgeToPaperPrism = {0, 2, 1, 3, 5, 4};

// Position k of an element in VTK order holds the node at this position of the paper's order (and
// the other way round: the permutation is its own inverse).
constexpr int VtkToPaperPosition(ElementType type, int position) {
  return type == ElementType::kPrism ? kVtkWedgeToPaperPrism[position] : position;
}

// Copies one element's node ids between VTK and paper order (either direction); `to` holds at
// least as many entries as `from`.
template <typename From, typename To>
constexpr void MirrorVtkPaperOrder(ElementType type, std::span<const From> from, std::span<To> to) {
  for (std::size_t k = 0; k < from.size(); ++k) {
    to[k] = static_cast<To>(from[VtkToPaperPosition(type, static_cast<int>(k))]);
  }
}

}  // namespace getme
