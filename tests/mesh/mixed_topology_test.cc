// Topology of mixed meshes: faces match only between elements that share the same node set, a
// triangle never matches a quad, and all adjacency agrees with a brute-force reference.

#include <gtest/gtest.h>

#include <vector>

#include "getme/mesh/mesh.h"
#include "mesh_spec.h"
#include "reference_quality.h"
#include "reference_topology.h"
#include "topology_checks.h"

namespace getme::mesh_test {
namespace {

Mesh BuildMixedOrDie(const MeshSpec& spec) {
  absl::StatusOr<Mesh> mesh = BuildMesh(spec);
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  return std::move(mesh).value();
}

void ExpectAllElementsValid(const MeshSpec& spec) {
  for (std::size_t e = 0; e < spec.elements.size(); ++e) {
    EXPECT_TRUE(ReferenceIsValid(spec.elements[e].type, spec.ElementPoints(e)))
        << "test mesh element " << e << " is not valid: fix the fixture";
  }
}

TEST(MixedTopology, PrismCubeWithPyramidAndTetHasThirteenBoundaryFaces) {
  const MeshSpec spec = PrismCubeWithPyramidAndTet();
  ExpectAllElementsValid(spec);
  const Mesh mesh = BuildMixedOrDie(spec);
  // 5 + 4 + 5 + 5 faces; the prisms share the diagonal quad, prism 0 and the pyramid the x = 1
  // quad, the pyramid and the tetrahedron one triangle: 19 − 2·3.
  EXPECT_EQ(mesh.boundary_face_count(), 13);
  EXPECT_EQ(ComputeReferenceTopology(spec).boundary_face_count, 13);
  ExpectTopologyMatchesReference(mesh, spec);
}

TEST(MixedTopology, PrismCubeNeighboursAndNodeElements) {
  const Mesh mesh = BuildMixedOrDie(PrismCubeWithPyramidAndTet());
  // Ids: 0 prism, 1 tet, 2 prism, 3 pyramid. Node 2 = (1,1,0) is in all four. Rows follow the
  // canonical order (tet, hex, pyramid, prism; then id): 1, 3, 0, 2.
  EXPECT_EQ(std::vector<ElementId>(mesh.canonical_order().begin(), mesh.canonical_order().end()),
            (std::vector<ElementId>{1, 3, 0, 2}));
  EXPECT_EQ(mesh.canonical_rank(0), 2);
  EXPECT_EQ(mesh.canonical_rank(3), 1);
  EXPECT_FALSE(mesh.ids_in_canonical_order());
  for (std::int32_t rank = 0; rank < 4; ++rank) {
    EXPECT_EQ(mesh.canonical_rank(mesh.canonical_order()[rank]), rank);
  }
  const auto node_elements = mesh.node_elements(2);
  EXPECT_EQ(std::vector<ElementId>(node_elements.begin(), node_elements.end()),
            (std::vector<ElementId>{1, 3, 0, 2}));
  // Node 9 (tet apex) is only in the tetrahedron; node 8 (pyramid apex) in tet and pyramid.
  EXPECT_EQ(mesh.node_elements(9).size(), 1u);
  EXPECT_EQ(mesh.node_elements(8)[0], 1);
  EXPECT_EQ(mesh.node_elements(8)[1], 3);
  const auto tet_neighbours = mesh.element_neighbours(1);
  EXPECT_EQ(std::vector<ElementId>(tet_neighbours.begin(), tet_neighbours.end()),
            (std::vector<ElementId>{3, 0, 2}));
}

// Ids added type by type in the canonical order are their own ranks, and the mesh says so (the
// neighbour finder then reads no rank table).
TEST(MixedTopology, IdsAddedInCanonicalOrderAreTheirRanks) {
  const MeshSpec interleaved = PrismCubeWithPyramidAndTet();
  MeshSpec grouped;
  for (std::size_t n = 0; n < interleaved.nodes.size(); ++n) grouped.AddNode(interleaved.nodes[n]);
  for (ElementId e : {1, 3, 0, 2}) {
    grouped.AddElement(interleaved.elements[e].type, interleaved.elements[e].nodes);
  }
  const Mesh mesh = BuildMixedOrDie(grouped);
  EXPECT_TRUE(mesh.ids_in_canonical_order());
  for (ElementId e = 0; e < 4; ++e) {
    EXPECT_EQ(mesh.canonical_order()[e], e);
    EXPECT_EQ(mesh.canonical_rank(e), e);
  }
  ExpectTopologyMatchesReference(mesh, grouped);
}

// A tetrahedron resting on three of the four nodes of prism 0's y = 0 quad face: its triangle
// (0, 1, 5) must not be taken for the quad (0, 1, 5, 4), so neither face is shared.
TEST(MixedTopology, TriangleOnThreeNodesOfAQuadDoesNotMatchIt) {
  MeshSpec spec = PrismCubeWithPyramidAndTet();
  const std::int64_t apex = spec.AddNode(Eigen::Vector3d(0.5, -0.5, 0.5));
  spec.AddElement(ElementType::kTetrahedron, {0, 1, 5, apex});
  ExpectAllElementsValid(spec);
  const Mesh mesh = BuildMixedOrDie(spec);
  EXPECT_EQ(mesh.boundary_face_count(), 13 + 4);
  ExpectTopologyMatchesReference(mesh, spec);
}

// Two tetrahedra on opposite sides of one triangle share exactly that face.
TEST(MixedTopology, TwoTetsShareOneFaceWhateverTheNodeOrder) {
  MeshSpec spec;
  spec.AddNode({0, 0, 0});
  spec.AddNode({1, 0, 0});
  spec.AddNode({0, 1, 0});
  spec.AddNode({0, 0, 1});
  spec.AddNode({0, 0, -1});
  spec.AddElement(ElementType::kTetrahedron, {0, 1, 2, 3});
  spec.AddElement(ElementType::kTetrahedron, {2, 1, 0, 4});
  ExpectAllElementsValid(spec);
  const Mesh mesh = BuildMixedOrDie(spec);
  EXPECT_EQ(mesh.boundary_face_count(), 6);
  ExpectTopologyMatchesReference(mesh, spec);
}

TEST(MixedTopology, PyramidCellInHexBlockIsConforming) {
  const MeshSpec spec = HexBlockWithPyramidCell();
  ExpectAllElementsValid(spec);
  const Mesh mesh = BuildMixedOrDie(spec);
  ASSERT_EQ(mesh.node_count(), 28);
  EXPECT_EQ(mesh.boundary_face_count(), 24);
  // The block centre and the pyramids' common apex are the interior nodes.
  for (NodeId node = 0; node < 28; ++node) {
    EXPECT_EQ(mesh.is_boundary(node), node != 13 && node != 27) << "node " << node;
  }
  EXPECT_EQ(mesh.node_elements(27).size(), 6u);
  // (1,1,1) is a corner of 7 hexes and of the 3 bases at that corner of the split cell.
  EXPECT_EQ(mesh.node_elements(13).size(), 7u + 3u);
  ExpectTopologyMatchesReference(mesh, spec);
}

TEST(MixedTopology, PrismCellAgainstHexQuadIsANonConformingBoundary) {
  const MeshSpec spec = HexBlockWithPrismCell();
  ExpectAllElementsValid(spec);
  const Mesh mesh = BuildMixedOrDie(spec);
  // Outside: 23 quads and the two triangles of the split bottom square. Inside: the two top
  // triangles of the prisms and the bottom quad of the hex above them match nothing.
  EXPECT_EQ(mesh.boundary_face_count(), 25 + 3);
  EXPECT_TRUE(mesh.is_boundary(13));
  ExpectTopologyMatchesReference(mesh, spec);
}

}  // namespace
}  // namespace getme::mesh_test
