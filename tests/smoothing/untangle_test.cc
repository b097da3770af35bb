#include <gtest/gtest.h>

#include <array>

#include "absl/strings/str_cat.h"
#include "getme/smoothing/smoother.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

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
                                           "mixed-hex-pyr-tet.vtk"),
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
  auto result = Smooth(*mesh, SmoothingParams{});
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.status().code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_NE(result.status().message().find("1 (tetrahedron)"), std::string::npos)
      << result.status();
  EXPECT_NE(result.status().message().find("fixed"), std::string::npos) << result.status();
}

}  // namespace
}  // namespace getme
