// What a successful MeshBuilder::Build keeps: coordinates, global element ids in insertion order
// across types with per-type blocks, element node lists, and caller-fixed flags.

#include <gtest/gtest.h>

#include <vector>

#include "getme/mesh/mesh.h"
#include "mesh_spec.h"

namespace getme::mesh_test {
namespace {

TEST(MeshBuilder, ElementIdsFollowInsertionOrderAcrossTypes) {
  const MeshSpec spec = PrismCubeWithPyramidAndTet();
  const absl::StatusOr<Mesh> mesh = BuildMesh(spec);
  ASSERT_TRUE(mesh.ok()) << mesh.status();

  // Insertion order: prism, tetrahedron, prism, pyramid.
  ASSERT_EQ(mesh->element_count(), 4);
  const ElementType expected_types[] = {ElementType::kPrism, ElementType::kTetrahedron,
                                        ElementType::kPrism, ElementType::kPyramid};
  const int expected_block_index[] = {0, 0, 1, 0};
  for (ElementId e = 0; e < 4; ++e) {
    EXPECT_EQ(mesh->type(e), expected_types[e]) << "element " << e;
    EXPECT_EQ(mesh->block_index(e), expected_block_index[e]) << "element " << e;
    const std::span<const NodeId> nodes = mesh->element_nodes(e);
    EXPECT_EQ(std::vector<std::int64_t>(nodes.begin(), nodes.end()), spec.elements[e].nodes)
        << "element " << e;
  }
  EXPECT_EQ(mesh->element_count(ElementType::kTetrahedron), 1);
  EXPECT_EQ(mesh->element_count(ElementType::kHexahedron), 0);
  EXPECT_EQ(mesh->element_count(ElementType::kPyramid), 1);
  EXPECT_EQ(mesh->element_count(ElementType::kPrism), 2);
  EXPECT_EQ(mesh->block(ElementType::kPrism).elements, (std::vector<ElementId>{0, 2}));
  EXPECT_EQ(mesh->block(ElementType::kPrism).nodes,
            (std::vector<NodeId>{0, 1, 2, 4, 5, 6, 0, 2, 3, 4, 6, 7}));
  EXPECT_EQ(mesh->block(ElementType::kTetrahedron).elements, (std::vector<ElementId>{1}));
  EXPECT_EQ(mesh->block(ElementType::kPyramid).elements, (std::vector<ElementId>{3}));
  EXPECT_TRUE(mesh->block(ElementType::kHexahedron).elements.empty());
}

TEST(MeshBuilder, KeepsCoordinatesExactly) {
  MeshBuilder builder;
  // Extreme but accepted: tiny coordinates near 0, large ones up to the 1e40 bound.
  builder.AddNode(0.1, -2.5e-300, 7e39);
  builder.AddNode(1, 0, 0);
  builder.AddNode(0, 1, 0);
  builder.AddNode(0, 0, 1);
  builder.AddElement(ElementType::kTetrahedron, std::vector<std::int64_t>{0, 1, 2, 3});
  const absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  ASSERT_EQ(mesh->node_count(), 4);
  EXPECT_EQ(mesh->x()[0], 0.1);
  EXPECT_EQ(mesh->y()[0], -2.5e-300);
  EXPECT_EQ(mesh->z()[0], 7e39);
  EXPECT_EQ(mesh->x()[1], 1.0);
  EXPECT_EQ(mesh->z()[3], 1.0);
}

TEST(MeshBuilder, CornerOffsetsFollowTypeOrderAndBlockSizes) {
  const absl::StatusOr<Mesh> mesh = BuildMesh(PrismCubeWithPyramidAndTet());
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  // Blocks in type order tet, hex, pyramid, prism: 1·4, 0·8, 1·5, 2·6 corners.
  EXPECT_EQ(mesh->corner_offset(ElementType::kTetrahedron), 0);
  EXPECT_EQ(mesh->corner_offset(ElementType::kHexahedron), 4);
  EXPECT_EQ(mesh->corner_offset(ElementType::kPyramid), 4);
  EXPECT_EQ(mesh->corner_offset(ElementType::kPrism), 9);
  EXPECT_EQ(mesh->corner_count(), 21);
}

TEST(MeshBuilder, FixedFlagsAreThoseSetAndNoOthers) {
  MeshSpec spec = HexBlock(1);
  MeshBuilder builder;
  for (const auto& p : spec.nodes) builder.AddNode(p.x(), p.y(), p.z());
  builder.AddElement(ElementType::kHexahedron, spec.elements[0].nodes);
  builder.SetFixed(2);
  builder.SetFixed(5, true);
  builder.SetFixed(2);  // twice is harmless
  builder.SetFixed(6, false);
  const absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  for (NodeId node = 0; node < 8; ++node) {
    EXPECT_EQ(mesh->is_fixed(node), node == 2 || node == 5) << "node " << node;
    EXPECT_EQ(mesh->fixed_flags()[node] != 0, node == 2 || node == 5) << "node " << node;
  }
}

// SetFixed(node, fixed) states the node's flag; the last call for a node wins, as it would for
// a caller copying a per-node flag array that it corrects later.
TEST(MeshBuilder, SetFixedFalseAfterTrueLeavesTheNodeFree) {
  MeshSpec spec = HexBlock(1);
  MeshBuilder builder;
  for (const auto& p : spec.nodes) builder.AddNode(p.x(), p.y(), p.z());
  builder.AddElement(ElementType::kHexahedron, spec.elements[0].nodes);
  builder.SetFixed(4, true);
  builder.SetFixed(4, false);
  const absl::StatusOr<Mesh> mesh = std::move(builder).Build();
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EXPECT_FALSE(mesh->is_fixed(4));
}

TEST(MeshBuilder, SetFixedOnTheBuiltMeshChangesOnlyThatNode) {
  absl::StatusOr<Mesh> mesh = BuildMesh(HexBlock(1));
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  mesh->set_fixed(3, true);
  for (NodeId node = 0; node < 8; ++node) EXPECT_EQ(mesh->is_fixed(node), node == 3);
  mesh->set_fixed(3, false);
  EXPECT_FALSE(mesh->is_fixed(3));
}

}  // namespace
}  // namespace getme::mesh_test
