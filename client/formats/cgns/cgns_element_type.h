#pragma once

#include <optional>
#include <string>

namespace getme::formats::cgns {

// A CGNS ElementType_t that getme reads, with its VTK cell code and node count.
struct ElementKind {
  int cgns_type;  // ElementType_t value (TETRA_4 = 10, …)
  int vtk_type;
  int node_count;
};

// The linear types: NODE, BAR_2, TRI_3, QUAD_4, TETRA_4, PYRA_5, PENTA_6, HEXA_8. Every other
// type (quadratic and higher, NGON_n, NFACE_n, MIXED itself) has none.
std::optional<ElementKind> KindOfCgnsType(int cgns_type);
std::optional<ElementKind> KindOfVtkType(int vtk_type);

// Node k of a VTK cell is node CgnsPosition(vtk_type, k) of the CGNS element, and the other way
// round (the permutation is its own inverse).
//
// SIDS §3.3 (Unstructured Grid Element Numbering Conventions) numbers TETRA_4, PYRA_5 and
// HEXA_8 as VTK does, and PENTA_6 with the bottom triangle 1, 2, 3 counter-clockwise seen from
// the top face 4, 5, 6 (its face 1-3-2 points out of the bottom): Gmsh's prism and the paper's,
// mirrored against VTK's wedge (docs/node-orders.md). The mapping is the engine's one prism
// table (kVtkWedgeToPaperPrism). Evidence: tests/formats/cgns (regular elements written by
// meshio's UGRID writer and the CGNS project's own aflr3_to_cgns read back with mean ratio 1).
int CgnsPosition(int vtk_type, int vtk_position);

// "TETRA_10", "MIXED", … (cg_ElementTypeName), or the number for values the library names not.
std::string CgnsTypeName(int cgns_type);

// What the reader accepts, for messages.
inline constexpr char kSupportedElementTypes[] =
    "TETRA_4, PYRA_5, PENTA_6, HEXA_8, TRI_3, QUAD_4, BAR_2, NODE and MIXED sections of these";

}  // namespace getme::formats::cgns
