#pragma once

#include <cstdint>
#include <optional>

#include "absl/strings/string_view.h"
#include "getme/elements/element_type.h"

namespace getme::formats {

// VTK cell type codes (vtkCellType.h) that matter to getme by name.
inline constexpr int kVtkTriangle = 5;
inline constexpr int kVtkQuad = 9;
inline constexpr int kVtkTetra = 10;
inline constexpr int kVtkHexahedron = 12;
inline constexpr int kVtkWedge = 13;
inline constexpr int kVtkPyramid = 14;
inline constexpr int kVtkPolyhedron = 42;

// What getme does with a cell of a given VTK type.
enum class VtkCellRole : std::uint8_t {
  kVolumeElement,  // tetra, hexahedron, wedge, pyramid: becomes an engine element
  kPassthrough,    // linear cells of dimension 0–2 (vertex … quad): kept, moved with its nodes
  kUnsupported,    // anything else (voxel, quadratic, higher-order, polyhedron, …)
};

struct VtkCellTypeInfo {
  int code;
  absl::string_view name;  // VTK's name without the "VTK_" prefix, lower case ("quad", "wedge")
  int node_count;          // -1 for cells with a variable node count
  VtkCellRole role;
};

// nullopt for codes that are not VTK cell types.
std::optional<VtkCellTypeInfo> CellTypeInfo(int code);

// The engine type of a volume cell code (10, 12, 13, 14).
std::optional<ElementType> ElementTypeOfCell(int code);

}  // namespace getme::formats
