#include "formats/vtk_cell_type.h"

#include <array>

namespace getme::formats {
namespace {

using enum VtkCellRole;

// From vtkCellType.h (VTK 9.3). Node counts of the fixed-size cells let the reader refuse a
// CELLS entry with the wrong number of ids.
constexpr std::array<VtkCellTypeInfo, 50> kCellTypes = {{
    {0, "empty_cell", 0, kPassthrough},
    {1, "vertex", 1, kPassthrough},
    {2, "poly_vertex", -1, kPassthrough},
    {3, "line", 2, kPassthrough},
    {4, "poly_line", -1, kPassthrough},
    {5, "triangle", 3, kPassthrough},
    {6, "triangle_strip", -1, kPassthrough},
    {7, "polygon", -1, kPassthrough},
    {8, "pixel", 4, kPassthrough},
    {9, "quad", 4, kPassthrough},
    {10, "tetra", 4, kVolumeElement},
    {11, "voxel", 8, kUnsupported},
    {12, "hexahedron", 8, kVolumeElement},
    {13, "wedge", 6, kVolumeElement},
    {14, "pyramid", 5, kVolumeElement},
    {15, "pentagonal_prism", 10, kUnsupported},
    {16, "hexagonal_prism", 12, kUnsupported},
    {21, "quadratic_edge", 3, kUnsupported},
    {22, "quadratic_triangle", 6, kUnsupported},
    {23, "quadratic_quad", 8, kUnsupported},
    {24, "quadratic_tetra", 10, kUnsupported},
    {25, "quadratic_hexahedron", 20, kUnsupported},
    {26, "quadratic_wedge", 15, kUnsupported},
    {27, "quadratic_pyramid", 13, kUnsupported},
    {28, "biquadratic_quad", 9, kUnsupported},
    {29, "triquadratic_hexahedron", 27, kUnsupported},
    {30, "quadratic_linear_quad", 6, kUnsupported},
    {31, "quadratic_linear_wedge", 12, kUnsupported},
    {32, "biquadratic_quadratic_wedge", 18, kUnsupported},
    {33, "biquadratic_quadratic_hexahedron", 24, kUnsupported},
    {34, "biquadratic_triangle", 7, kUnsupported},
    {35, "cubic_line", 4, kUnsupported},
    {36, "quadratic_polygon", -1, kUnsupported},
    {37, "triquadratic_pyramid", 19, kUnsupported},
    {41, "convex_point_set", -1, kUnsupported},
    // The polyhedron's CELLS entry is a face stream (face count, then per face its size and
    // ids), so its entries are not all point ids.
    {42, "polyhedron", -1, kUnsupported},
    {51, "parametric_curve", -1, kUnsupported},
    {52, "parametric_surface", -1, kUnsupported},
    {53, "parametric_tri_surface", -1, kUnsupported},
    {54, "parametric_quad_surface", -1, kUnsupported},
    {55, "parametric_tetra_region", -1, kUnsupported},
    {56, "parametric_hex_region", -1, kUnsupported},
    {60, "higher_order_edge", -1, kUnsupported},
    {61, "higher_order_triangle", -1, kUnsupported},
    {62, "higher_order_quad", -1, kUnsupported},
    {63, "higher_order_polygon", -1, kUnsupported},
    {64, "higher_order_tetrahedron", -1, kUnsupported},
    {65, "higher_order_wedge", -1, kUnsupported},
    {66, "higher_order_pyramid", -1, kUnsupported},
    {67, "higher_order_hexahedron", -1, kUnsupported},
}};

// Lagrange (68–74) and Bézier (75–81) cells: all of variable order, all unsupported.
constexpr std::array<absl::string_view, 14> kHighOrderNames = {
    "lagrange_curve",      "lagrange_triangle",    "lagrange_quadrilateral", "lagrange_tetrahedron",
    "lagrange_hexahedron", "lagrange_wedge",       "lagrange_pyramid",       "bezier_curve",
    "bezier_triangle",     "bezier_quadrilateral", "bezier_tetrahedron",     "bezier_hexahedron",
    "bezier_wedge",        "bezier_pyramid"};

}  // namespace

std::optional<VtkCellTypeInfo> CellTypeInfo(int code) {
  if (code >= 68 && code <= 81) {
    return VtkCellTypeInfo{code, kHighOrderNames[code - 68], -1, kUnsupported};
  }
  for (const VtkCellTypeInfo& info : kCellTypes) {
    if (info.code == code) return info;
  }
  return std::nullopt;
}

std::optional<ElementType> ElementTypeOfCell(int code) {
  switch (code) {
    case kVtkTetra:
      return ElementType::kTetrahedron;
    case kVtkHexahedron:
      return ElementType::kHexahedron;
    case kVtkWedge:
      return ElementType::kPrism;
    case kVtkPyramid:
      return ElementType::kPyramid;
    default:
      return std::nullopt;
  }
}

}  // namespace getme::formats
