// BuildEdgeNeighbours: on a single element of each type, the node→node rows are the element's
// geometric edges (tet 6, hex 12, pyramid 8, prism 9), symmetric and ascending. The expected
// edges are derived from geometry: in a regular element with unit edges exactly the edge pairs
// are at distance 1 (face and body diagonals are longer).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "getme/mesh/node_neighbours.h"
#include "mesh_spec.h"

namespace getme::mesh_test {
namespace {

struct UnitElement {
  ElementType type;
  std::vector<Eigen::Vector3d> points;  // paper order, every edge of length 1
  int edges;
};

std::vector<UnitElement> UnitElements() {
  const double h = std::sqrt(3.0) / 2;
  return {
      {ElementType::kTetrahedron,
       {{0, 0, 0}, {1, 0, 0}, {0.5, h, 0}, {0.5, std::sqrt(3.0) / 6, std::sqrt(2.0 / 3)}},
       6},
      {ElementType::kHexahedron,
       {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
       12},
      {ElementType::kPyramid,
       {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, std::sqrt(2.0) / 2}},
       8},
      {ElementType::kPrism,
       {{0, 0, 0}, {1, 0, 0}, {0.5, h, 0}, {0, 0, 1}, {1, 0, 1}, {0.5, h, 1}},
       9},
  };
}

using EdgeSet = std::set<std::pair<std::int64_t, std::int64_t>>;

// Ordered pairs (a, b) and (b, a) of spec nodes at distance 1 within one element.
EdgeSet UnitDistancePairs(const MeshSpec& spec, const ElementSpec& element) {
  EdgeSet pairs;
  for (std::int64_t a : element.nodes) {
    for (std::int64_t b : element.nodes) {
      if (a != b && std::abs((spec.nodes[a] - spec.nodes[b]).norm() - 1.0) < 1e-9) {
        pairs.emplace(a, b);
      }
    }
  }
  return pairs;
}

EdgeSet RowsAsPairs(const CompressedRows& rows) {
  EdgeSet pairs;
  for (std::int64_t node = 0; node < rows.RowCount(); ++node) {
    for (std::int32_t other : rows.Row(node)) pairs.emplace(node, other);
  }
  return pairs;
}

void ExpectRowsAscendingWithoutSelf(const CompressedRows& rows) {
  for (std::int64_t node = 0; node < rows.RowCount(); ++node) {
    const auto row = rows.Row(node);
    EXPECT_TRUE(std::adjacent_find(row.begin(), row.end(), std::greater_equal<>()) == row.end())
        << "row of node " << node << " is not strictly ascending";
    EXPECT_TRUE(std::find(row.begin(), row.end(), node) == row.end()) << "node " << node;
  }
}

TEST(EdgeNeighbours, SingleElementOfEachTypeGivesItsGeometricEdges) {
  for (const UnitElement& unit : UnitElements()) {
    // Insert the nodes in reverse so the element's node ids are not its local indices.
    MeshSpec spec;
    const auto n = static_cast<std::int64_t>(unit.points.size());
    for (std::int64_t k = n - 1; k >= 0; --k) spec.AddNode(unit.points[k]);
    std::vector<std::int64_t> ids;
    for (std::int64_t k = 0; k < n; ++k) ids.push_back(n - 1 - k);
    spec.AddElement(unit.type, ids);
    const absl::StatusOr<Mesh> mesh = BuildMesh(spec);
    ASSERT_TRUE(mesh.ok()) << mesh.status();

    const CompressedRows rows = BuildEdgeNeighbours(*mesh);
    ASSERT_EQ(rows.RowCount(), n) << TypeName(unit.type);
    const EdgeSet expected = UnitDistancePairs(spec, spec.elements[0]);
    ASSERT_EQ(expected.size(), 2u * unit.edges) << "fixture of " << TypeName(unit.type);
    EXPECT_EQ(RowsAsPairs(rows), expected) << TypeName(unit.type);
    EXPECT_EQ(rows.items.size(), 2u * unit.edges) << TypeName(unit.type);
    ExpectRowsAscendingWithoutSelf(rows);
  }
}

TEST(EdgeNeighbours, RowsAreSymmetric) {
  const MeshSpec spec = PrismCubeWithPyramidAndTet();
  const absl::StatusOr<Mesh> mesh = BuildMesh(spec);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const EdgeSet pairs = RowsAsPairs(BuildEdgeNeighbours(*mesh));
  for (const auto& [a, b] : pairs) EXPECT_TRUE(pairs.count({b, a})) << a << " → " << b;
}

TEST(EdgeNeighbours, SharedEdgesAppearOnceAndFaceDiagonalsNever) {
  // 2×2×2 unit hexes: the edges are the unit grid segments, each shared by up to 4 hexes.
  const MeshSpec spec = HexBlock(2);
  const absl::StatusOr<Mesh> mesh = BuildMesh(spec);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const CompressedRows rows = BuildEdgeNeighbours(*mesh);
  EdgeSet expected;
  for (const ElementSpec& element : spec.elements) {
    const EdgeSet element_pairs = UnitDistancePairs(spec, element);
    expected.insert(element_pairs.begin(), element_pairs.end());
  }
  // Grid segments along each axis: 3·3 lines of 2 segments, times 3 axes = 54 edges.
  EXPECT_EQ(expected.size(), 2u * 54u);
  EXPECT_EQ(RowsAsPairs(rows), expected);
  EXPECT_EQ(rows.items.size(), 2u * 54u);
  EXPECT_EQ(rows.Row(HexBlockNodeId(2, 1, 1, 1)).size(), 6u);  // the centre
  EXPECT_EQ(rows.Row(HexBlockNodeId(2, 0, 0, 0)).size(), 3u);  // a corner
  ExpectRowsAscendingWithoutSelf(rows);
}

TEST(EdgeNeighbours, MixedMeshMatchesTheUnionOfElementEdges) {
  // In the prism cube the pyramid's and tet's edges are not unit length, so use the node pairs
  // each element type connects by its geometric edges (docs/node-orders.md, the tables section).
  const MeshSpec spec = PrismCubeWithPyramidAndTet();
  const absl::StatusOr<Mesh> mesh = BuildMesh(spec);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EdgeSet expected;
  auto add = [&](std::int64_t a, std::int64_t b) {
    expected.emplace(a, b);
    expected.emplace(b, a);
  };
  // Prisms (0,1,2,4,5,6) and (0,2,3,4,6,7): triangles and vertical edges.
  for (const auto& [a, b] : std::vector<std::pair<int, int>>{{0, 1},
                                                             {1, 2},
                                                             {2, 0},
                                                             {4, 5},
                                                             {5, 6},
                                                             {6, 4},
                                                             {0, 4},
                                                             {1, 5},
                                                             {2, 6},
                                                             {2, 3},
                                                             {3, 0},
                                                             {6, 7},
                                                             {7, 4},
                                                             {3, 7}}) {
    add(a, b);
  }
  // Tetrahedron (2, 6, 8, 9): all six pairs.
  for (const auto& [a, b] :
       std::vector<std::pair<int, int>>{{2, 6}, {2, 8}, {2, 9}, {6, 8}, {6, 9}, {8, 9}}) {
    add(a, b);
  }
  // Pyramid (1, 2, 6, 5; apex 8): base ring and apex edges, no base diagonals.
  for (const auto& [a, b] : std::vector<std::pair<int, int>>{
           {1, 2}, {2, 6}, {6, 5}, {5, 1}, {1, 8}, {2, 8}, {6, 8}, {5, 8}}) {
    add(a, b);
  }
  EXPECT_EQ(RowsAsPairs(BuildEdgeNeighbours(*mesh)), expected);
}

}  // namespace
}  // namespace getme::mesh_test
