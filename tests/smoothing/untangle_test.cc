#include <gtest/gtest.h>

#include <array>

#include "absl/strings/str_cat.h"
#include "getme/smoothing/smoother.h"
#include "gmock/gmock.h"
#include "mesh_spec.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

class UntangleTest : public ::testing::TestWithParam<const char*> {};

TEST_P(UntangleTest, TangledMeshEndsValidAndSmoothed) {
  Mesh mesh = testing::LoadSharedMesh(GetParam());
  const std::int64_t invalid_before = testing::CountInvalid(mesh);
  ASSERT_GT(invalid_before, 0);
  SmoothingParams params;
  const std::vector<NodeId> immovable = testing::ImmovableNodes(mesh, params);
  const testing::CoordinateSnapshot before(mesh);
  std::vector<std::int64_t> untangle_invalid;
  auto result = Smooth(mesh, params, [&](const ProgressEvent& event) {
    if (event.phase == Phase::kUntangle) untangle_invalid.push_back(event.invalid);
  });
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_EQ(result->before.invalid, invalid_before);
  EXPECT_EQ(result->after.invalid, 0);
  EXPECT_EQ(testing::CountInvalid(mesh), 0);
  EXPECT_GT(result->iterations_untangle, 0);
  ASSERT_FALSE(untangle_invalid.empty());
  EXPECT_EQ(untangle_invalid.back(), 0);
  EXPECT_EQ(result->phases.front().phase, Phase::kUntangle);
  EXPECT_GT(result->after.q_min, 0.0);
  const testing::CoordinateSnapshot after(mesh);
  for (NodeId node : immovable) {
    ASSERT_EQ(after.x[node], before.x[node]);
    ASSERT_EQ(after.y[node], before.y[node]);
    ASSERT_EQ(after.z[node], before.z[node]);
  }
}

INSTANTIATE_TEST_SUITE_P(SharedMeshes, UntangleTest,
                         ::testing::Values("tet_4_tangled.vtk", "hex_5_tangled.vtk",
                                           "mixed-hex-pyr-tet.vtk", "pave3.vtk", "pave_cyl.vtk"),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

TEST(UntangleOffTest, InvalidInputIsRefusedNamingTheFirstInvalidElements) {
  Mesh mesh = testing::LoadSharedMesh("mixed-hex-pyr-tet.vtk");
  std::vector<ElementId> invalid;
  ThreadPool pool(1);
  const std::vector<std::uint8_t> valid = ComputeElementValidity(mesh, pool);
  for (ElementId e = 0; e < mesh.element_count(); ++e) {
    if (!valid[e]) invalid.push_back(e);
  }
  ASSERT_EQ(invalid.size(), 3u);
  SmoothingParams params;
  params.untangle = false;
  const testing::CoordinateSnapshot before(mesh);
  auto result = Smooth(mesh, params);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.status().code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_NE(result.status().message().find(
                absl::StrCat("first: ", invalid[0], ", ", invalid[1], ", ", invalid[2])),
            std::string::npos)
      << result.status();
  EXPECT_TRUE(testing::CoordinateSnapshot(mesh) == before);
}

TEST(UntangleTest, ElementWithOnlyFixedNodesIsReportedAsUnrepairable) {
  // Two tetrahedra sharing a face; the second is inverted and all its nodes are on the boundary.
  MeshBuilder builder;
  builder.AddNode(0, 0, 0);
  builder.AddNode(1, 0, 0);
  builder.AddNode(0, 1, 0);
  builder.AddNode(0, 0, 1);
  builder.AddNode(0.2, 0.2, 0.2);  // inside the first tetrahedron: the second one is inverted
  const std::array<std::int64_t, 4> first = {0, 1, 2, 3};
  const std::array<std::int64_t, 4> second = {1, 2, 3, 4};
  builder.AddElement(ElementType::kTetrahedron, first);
  builder.AddElement(ElementType::kTetrahedron, second);
  auto mesh = std::move(builder).Build();
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  ASSERT_EQ(testing::CountInvalid(*mesh), 1);
  const testing::CoordinateSnapshot before(*mesh);
  auto result = Smooth(*mesh, SmoothingParams{});
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.status().code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_THAT(std::string(result.status().message()),
              HasSubstr("element 1 (tetrahedron), corner of node 1: det "))
      << result.status();
  EXPECT_THAT(std::string(result.status().message()),
              HasSubstr("with nodes 1 boundary, 2 boundary, 3 boundary, 4 boundary"));
  EXPECT_THAT(std::string(result.status().message()), HasSubstr("untangle_free_boundary"));
  // The proof is given before anything moves.
  EXPECT_TRUE(testing::CoordinateSnapshot(*mesh) == before);

  // With the boundary of invalid elements released, the same mesh untangles: node 4 is pushed
  // back out through the shared face.
  SmoothingParams params;
  params.untangle_free_boundary = true;
  auto untangled = Smooth(*mesh, params);
  ASSERT_TRUE(untangled.ok()) << untangled.status();
  EXPECT_EQ(untangled->after.invalid, 0);
  EXPECT_EQ(testing::CountInvalid(*mesh), 0);
}

// A corner hexahedron of a 3×3×3 block whose block-corner node is pushed inside: the node
// tetrahedron of that corner (the node and its three edge neighbours, all on the boundary) is
// inverted, so with the boundary fixed no untangler can repair it.
absl::StatusOr<Mesh> BlockWithInvertedBoundaryCorner() {
  mesh_test::MeshSpec spec = mesh_test::HexBlock(3);
  spec.nodes[mesh_test::HexBlockNodeId(3, 0, 0, 0)] = Eigen::Vector3d(0.6, 0.6, 0.6);
  return mesh_test::BuildMesh(spec);
}

TEST(UntangleImpossibleTest, PinnedInvertedCornerIsProvedAndFreeBoundaryRepairsIt) {
  absl::StatusOr<Mesh> mesh = BlockWithInvertedBoundaryCorner();
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  ASSERT_EQ(testing::CountInvalid(*mesh), 1);
  auto result = Smooth(*mesh, SmoothingParams{});
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.status().code(), absl::StatusCode::kFailedPrecondition);
  const std::string message(result.status().message());
  EXPECT_THAT(message, HasSubstr("cannot untangle: 1 invalid element has a corner with det <= 0"));
  // Node tetrahedron 0 of a hexahedron is (0, 3, 4, 1): node (0,0,0) and its neighbours along y,
  // z and x, ids 0, 4, 16 and 1 in the block.
  EXPECT_THAT(message, HasSubstr("element 0 (hexahedron), corner of node 0: det -"));
  EXPECT_THAT(message, HasSubstr("with nodes 0 boundary, 4 boundary, 16 boundary, 1 boundary"));
  EXPECT_THAT(message, HasSubstr("untangle_free_boundary"));

  SmoothingParams params;
  params.untangle_free_boundary = true;
  mesh = BlockWithInvertedBoundaryCorner();
  ASSERT_TRUE(mesh.ok());
  const testing::CoordinateSnapshot before(*mesh);
  std::vector<std::int64_t> untangle_invalid;
  auto untangled = Smooth(*mesh, params, [&](const ProgressEvent& event) {
    if (event.phase == Phase::kUntangle) untangle_invalid.push_back(event.invalid);
  });
  ASSERT_TRUE(untangled.ok()) << untangled.status();
  EXPECT_EQ(untangled->after.invalid, 0);
  EXPECT_EQ(testing::CountInvalid(*mesh), 0);
  ASSERT_FALSE(untangle_invalid.empty());
  EXPECT_EQ(untangle_invalid.back(), 0);
  // Only nodes of the invalid element (cell 0: ids i + 4j + 16k, i, j, k in {0, 1}) may have
  // moved, and of them the boundary ones only during untangling; every other boundary node is
  // where it was.
  const testing::CoordinateSnapshot after(*mesh);
  EXPECT_NE(after.x[0], before.x[0]);
  for (NodeId node = 0; node < mesh->node_count(); ++node) {
    const bool in_cell0 = node % 4 <= 1 && (node / 4) % 4 <= 1 && node / 16 <= 1;
    if (in_cell0 || !mesh->is_boundary(node)) continue;
    ASSERT_EQ(after.x[node], before.x[node]) << node;
    ASSERT_EQ(after.y[node], before.y[node]) << node;
    ASSERT_EQ(after.z[node], before.z[node]) << node;
  }
}

TEST(UntangleImpossibleTest, InputFixedNodesStayPinnedEvenWithTheFreeBoundaryOption) {
  absl::StatusOr<Mesh> mesh = BlockWithInvertedBoundaryCorner();
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  for (NodeId node : {0, 4, 16, 1}) mesh->set_fixed(node, true);
  SmoothingParams params;
  params.untangle_free_boundary = true;
  const testing::CoordinateSnapshot before(*mesh);
  auto result = Smooth(*mesh, params);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.status().code(), absl::StatusCode::kFailedPrecondition);
  const std::string message(result.status().message());
  EXPECT_THAT(message, HasSubstr("with nodes 0 fixed, 4 fixed, 16 fixed, 1 fixed"));
  // Nothing more an option could free: no hint.
  EXPECT_THAT(message, Not(HasSubstr("untangle_free_boundary")));
  EXPECT_TRUE(testing::CoordinateSnapshot(*mesh) == before);
}

}  // namespace
}  // namespace getme
