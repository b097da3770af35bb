#include "mesh_spec.h"

#include <Eigen/Geometry>  // cross products
#include <utility>

namespace getme::mesh_test {
namespace {

// Paper order of the hex cell with lower corner (a, b, c): bottom counter-clockwise seen from the
// top, then the top nodes above the bottom ones.
std::vector<std::int64_t> HexCellNodes(int cells, int a, int b, int c) {
  return {HexBlockNodeId(cells, a, b, c),
          HexBlockNodeId(cells, a + 1, b, c),
          HexBlockNodeId(cells, a + 1, b + 1, c),
          HexBlockNodeId(cells, a, b + 1, c),
          HexBlockNodeId(cells, a, b, c + 1),
          HexBlockNodeId(cells, a + 1, b, c + 1),
          HexBlockNodeId(cells, a + 1, b + 1, c + 1),
          HexBlockNodeId(cells, a, b + 1, c + 1)};
}

// The block with one cell left out, so a test can fill that cell with other element types.
MeshSpec HexBlockWithoutCell(int cells, int skipped_cell) {
  MeshSpec spec;
  for (int k = 0; k <= cells; ++k) {
    for (int j = 0; j <= cells; ++j) {
      for (int i = 0; i <= cells; ++i) spec.AddNode(Eigen::Vector3d(i, j, k));
    }
  }
  for (int c = 0; c < cells; ++c) {
    for (int b = 0; b < cells; ++b) {
      for (int a = 0; a < cells; ++a) {
        if (HexBlockCellId(cells, a, b, c) == skipped_cell) continue;
        spec.AddElement(ElementType::kHexahedron, HexCellNodes(cells, a, b, c));
      }
    }
  }
  return spec;
}

}  // namespace

std::int64_t MeshSpec::AddNode(const Eigen::Vector3d& p) {
  nodes.push_back(p);
  return static_cast<std::int64_t>(nodes.size()) - 1;
}

std::int64_t MeshSpec::AddElement(ElementType type, std::vector<std::int64_t> element_nodes) {
  elements.push_back({type, std::move(element_nodes)});
  return static_cast<std::int64_t>(elements.size()) - 1;
}

std::vector<Eigen::Vector3d> MeshSpec::ElementPoints(std::int64_t element) const {
  std::vector<Eigen::Vector3d> points;
  for (std::int64_t node : elements[element].nodes) points.push_back(nodes[node]);
  return points;
}

absl::StatusOr<Mesh> BuildMesh(const MeshSpec& spec) {
  MeshBuilder builder;
  for (const Eigen::Vector3d& p : spec.nodes) builder.AddNode(p.x(), p.y(), p.z());
  for (const ElementSpec& element : spec.elements) builder.AddElement(element.type, element.nodes);
  return std::move(builder).Build();
}

int HexBlockNodeId(int cells, int i, int j, int k) {
  return i + (cells + 1) * (j + (cells + 1) * k);
}

int HexBlockCellId(int cells, int a, int b, int c) { return a + cells * (b + cells * c); }

MeshSpec HexBlock(int cells) { return HexBlockWithoutCell(cells, -1); }

MeshSpec PrismCubeWithPyramidAndTet() {
  MeshSpec spec;
  // 0..7: the unit cube in hex order; 8: pyramid apex beyond x = 1; 9: tetrahedron apex.
  for (const Eigen::Vector3d& p :
       {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 1, 0),
        Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 1),
        Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(0, 1, 1), Eigen::Vector3d(1.5, 0.5, 0.5),
        Eigen::Vector3d(1.5, 1.2, 0.5)}) {
    spec.AddNode(p);
  }
  spec.AddElement(ElementType::kPrism, {0, 1, 2, 4, 5, 6});  // below the diagonal plane x = y
  spec.AddElement(ElementType::kTetrahedron, {2, 6, 8, 9});  // on the pyramid's face (2, 6, 8)
  spec.AddElement(ElementType::kPrism, {0, 2, 3, 4, 6, 7});  // above it
  spec.AddElement(ElementType::kPyramid, {1, 2, 6, 5, 8});   // base = the cube's x = 1 face
  return spec;
}

MeshSpec HexBlockWithPyramidCell() {
  constexpr int kCells = 2;
  MeshSpec spec = HexBlockWithoutCell(kCells, HexBlockCellId(kCells, 1, 1, 1));
  const std::vector<std::int64_t> cell = HexCellNodes(kCells, 1, 1, 1);
  const std::int64_t apex = spec.AddNode(Eigen::Vector3d(1.5, 1.5, 1.5));
  // The cell's six faces as bases (the paper's F of the hexahedron, Sec. 2.1), each turned
  // counter-clockwise as seen from the apex, which is what makes the pyramid valid
  // (docs/node-orders.md).
  const int faces[6][4] = {{0, 1, 2, 3}, {0, 1, 5, 4}, {1, 2, 6, 5},
                           {2, 3, 7, 6}, {3, 0, 4, 7}, {4, 7, 6, 5}};
  for (const auto& face : faces) {
    std::vector<std::int64_t> nodes = {cell[face[0]], cell[face[1]], cell[face[2]], cell[face[3]]};
    const Eigen::Vector3d& p0 = spec.nodes[nodes[0]];
    const Eigen::Vector3d normal = (spec.nodes[nodes[1]] - p0).cross(spec.nodes[nodes[3]] - p0);
    if (normal.dot(spec.nodes[apex] - p0) < 0.0) std::swap(nodes[1], nodes[3]);
    nodes.push_back(apex);
    spec.AddElement(ElementType::kPyramid, nodes);
  }
  return spec;
}

MeshSpec HexBlockWithPrismCell() {
  constexpr int kCells = 2;
  MeshSpec spec = HexBlockWithoutCell(kCells, HexBlockCellId(kCells, 0, 0, 0));
  const std::vector<std::int64_t> c = HexCellNodes(kCells, 0, 0, 0);
  spec.AddElement(ElementType::kPrism, {c[0], c[1], c[2], c[4], c[5], c[6]});
  spec.AddElement(ElementType::kPrism, {c[0], c[2], c[3], c[4], c[6], c[7]});
  return spec;
}

}  // namespace getme::mesh_test
