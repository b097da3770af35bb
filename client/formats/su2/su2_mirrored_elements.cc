#include "formats/su2/su2_mirrored_elements.h"

#include <algorithm>
#include <array>
#include <optional>

#include "formats/vtk_cell_type.h"
#include "getme/elements/element_quality.h"
#include "getme/elements/node_orders.h"
#include "getme/elements/vec3.h"

namespace getme::formats {
namespace {

// The orientation-reversing renumbering of each element type, in VTK order (header).
constexpr std::array<int, 4> kMirroredTetra = {0, 2, 1, 3};
constexpr std::array<int, 8> kMirroredHexahedron = {0, 3, 2, 1, 4, 7, 6, 5};
constexpr std::array<int, 6> kMirroredWedge = {0, 2, 1, 3, 5, 4};
constexpr std::array<int, 5> kMirroredPyramid = {0, 3, 2, 1, 4};

template <std::size_t kSize>
void Permute(std::int64_t* nodes, const std::array<int, kSize>& order) {
  std::array<std::int64_t, kSize> original;
  std::copy_n(nodes, kSize, original.begin());
  for (std::size_t k = 0; k < kSize; ++k) nodes[k] = original[order[k]];
}

template <ElementType kType>
bool AllCornersNegative(const DataArray& points, const std::int64_t* vtk_nodes) {
  const std::int64_t point_count = points.tuple_count();
  ElementNodes<kType> paper;
  for (int k = 0; k < ElementTable<kType>::kNodes; ++k) {
    // Position k of the paper's order holds this position of VTK's (node_orders.h).
    const std::int64_t id = vtk_nodes[VtkToPaperPosition(kType, k)];
    if (id < 0 || id >= point_count) return false;
    paper[k] =
        Vec3(points.AsDouble(3 * id), points.AsDouble(3 * id + 1), points.AsDouble(3 * id + 2));
  }
  for (int k = 0; k < static_cast<int>(ElementTable<kType>::kNodeTets.size()); ++k) {
    if (!(NodeTetDeterminant<kType>(paper, k) < 0.0)) return false;
  }
  return true;
}

}  // namespace

bool IsMirroredCell(const UnstructuredGrid& grid, std::int64_t cell) {
  const std::optional<ElementType> type = ElementTypeOfCell(grid.cells.types[cell]);
  if (!type.has_value() || grid.cells.node_count(cell) != NodeCount(*type) ||
      grid.points.components != 3) {
    return false;
  }
  const std::int64_t* nodes = grid.cells.nodes(cell);
  return DispatchElementType(
      *type, [&]<ElementType kType>() { return AllCornersNegative<kType>(grid.points, nodes); });
}

void MirrorCellNodeOrder(GridCells& cells, std::int64_t cell) {
  std::int64_t* nodes = cells.connectivity.data() + cells.offsets[cell];
  const std::int64_t count = cells.node_count(cell);
  switch (cells.types[cell]) {
    case kVtkTetra:
      if (count == 4) Permute(nodes, kMirroredTetra);
      break;
    case kVtkHexahedron:
      if (count == 8) Permute(nodes, kMirroredHexahedron);
      break;
    case kVtkWedge:
      if (count == 6) Permute(nodes, kMirroredWedge);
      break;
    case kVtkPyramid:
      if (count == 5) Permute(nodes, kMirroredPyramid);
      break;
    default:
      break;
  }
}

std::vector<std::int64_t> RenumberMirroredCells(UnstructuredGrid& grid) {
  std::vector<std::int64_t> mirrored;
  for (std::int64_t cell = 0; cell < grid.cells.size(); ++cell) {
    if (!IsMirroredCell(grid, cell)) continue;
    MirrorCellNodeOrder(grid.cells, cell);
    mirrored.push_back(cell);
  }
  return mirrored;
}

}  // namespace getme::formats
