// Topology of a 2×2×2 block of unit hexahedra (27 nodes): boundary, node→element adjacency,
// element neighbours.

#include <gtest/gtest.h>

#include <vector>

#include "getme/mesh/mesh.h"
#include "mesh_spec.h"
#include "topology_checks.h"

namespace getme::mesh_test {
namespace {

constexpr int kCells = 2;

class HexBlockTopology : public ::testing::Test {
 protected:
  void SetUp() override {
    absl::StatusOr<Mesh> built = BuildMesh(spec_);
    ASSERT_TRUE(built.ok()) << built.status();
    mesh_ = std::move(*built);
  }
  const MeshSpec spec_ = HexBlock(kCells);
  Mesh mesh_;
  const NodeId centre_ = HexBlockNodeId(kCells, 1, 1, 1);
};

TEST_F(HexBlockTopology, AllNodesButTheCentreAreBoundary) {
  ASSERT_EQ(mesh_.node_count(), 27);
  ASSERT_EQ(centre_, 13);
  int boundary = 0;
  for (NodeId node = 0; node < 27; ++node) boundary += mesh_.is_boundary(node) ? 1 : 0;
  EXPECT_EQ(boundary, 26);
  EXPECT_FALSE(mesh_.is_boundary(centre_));
}

TEST_F(HexBlockTopology, TwentyFourBoundaryFaces) {
  // Four unit squares on each of the block's six sides.
  EXPECT_EQ(mesh_.boundary_face_count(), 24);
}

TEST_F(HexBlockTopology, CentreBelongsToAllEightElementsAscending) {
  const std::span<const ElementId> elements = mesh_.node_elements(centre_);
  EXPECT_EQ(std::vector<ElementId>(elements.begin(), elements.end()),
            (std::vector<ElementId>{0, 1, 2, 3, 4, 5, 6, 7}));
}

TEST_F(HexBlockTopology, NodeElementCountsMatchTheirPositionInTheBlock) {
  // A node touches 2 cells per axis on which it is interior (coordinate 1), else 1.
  for (int k = 0; k <= kCells; ++k) {
    for (int j = 0; j <= kCells; ++j) {
      for (int i = 0; i <= kCells; ++i) {
        const std::size_t expected = (i == 1 ? 2 : 1) * (j == 1 ? 2 : 1) * (k == 1 ? 2 : 1);
        EXPECT_EQ(mesh_.node_elements(HexBlockNodeId(kCells, i, j, k)).size(), expected)
            << "node (" << i << ", " << j << ", " << k << ")";
      }
    }
  }
}

TEST_F(HexBlockTopology, EveryElementNeighboursTheOtherSeven) {
  for (ElementId e = 0; e < 8; ++e) {
    std::vector<ElementId> others;
    for (ElementId other = 0; other < 8; ++other) {
      if (other != e) others.push_back(other);
    }
    const std::span<const ElementId> neighbours = mesh_.element_neighbours(e);
    EXPECT_EQ(std::vector<ElementId>(neighbours.begin(), neighbours.end()), others)
        << "element " << e;
  }
}

TEST_F(HexBlockTopology, MatchesBruteForceReference) {
  ExpectTopologyMatchesReference(mesh_, spec_);
}

TEST(HexBlockTopologyLarger, ThreeCubedBlockHasEightInteriorNodesAndFiftyFourBoundaryFaces) {
  const MeshSpec spec = HexBlock(3);
  const absl::StatusOr<Mesh> mesh = BuildMesh(spec);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  int interior = 0;
  for (NodeId node = 0; node < mesh->node_count(); ++node)
    interior += mesh->is_boundary(node) ? 0 : 1;
  EXPECT_EQ(interior, 8);
  EXPECT_EQ(mesh->boundary_face_count(), 6 * 9);
  ExpectTopologyMatchesReference(*mesh, spec);
}

}  // namespace
}  // namespace getme::mesh_test
