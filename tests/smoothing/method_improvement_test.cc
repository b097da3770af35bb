// Every smoothing method on the three generated kinds of mesh: quality improves, no element is
// left invalid, fixed and boundary nodes stay bit-identical.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>

#include "absl/strings/str_cat.h"
#include "getme/meshgen/distorted_hex_block.h"
#include "getme/meshgen/hybrid_block.h"
#include "getme/meshgen/jittered_tet_block.h"
#include "getme/smoothing/smoother.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

struct Case {
  const char* mesh_name;
  std::function<absl::StatusOr<Mesh>()> make;
  Method method;
};

class MethodImprovementTest : public ::testing::TestWithParam<Case> {};

TEST_P(MethodImprovementTest, ImprovesWithoutInvalidElementsOrMovingFixedNodes) {
  auto mesh = GetParam().make();
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  // Also fix every 7th interior node explicitly: it must not move either.
  for (NodeId node = 0; node < mesh->node_count(); node += 7) mesh->set_fixed(node, true);
  SmoothingParams params;
  params.method = GetParam().method;
  params.threads = 2;
  const std::vector<NodeId> immovable = testing::ImmovableNodes(*mesh, params);
  const testing::CoordinateSnapshot before(*mesh);

  auto result = Smooth(*mesh, params);
  ASSERT_TRUE(result.ok()) << result.status();

  EXPECT_EQ(result->before.invalid, 0);
  EXPECT_EQ(result->after.invalid, 0);
  EXPECT_EQ(testing::CountInvalid(*mesh), 0);
  EXPECT_GT(result->after.q_mean, result->before.q_mean + 0.01);
  if (params.method != Method::kSmartLaplace && params.method != Method::kSimultaneous) {
    // The sequential substep is what lifts q_min; the simultaneous one alone may lower it.
    EXPECT_GT(result->after.q_min, result->before.q_min);
  }
  const testing::CoordinateSnapshot after(*mesh);
  for (NodeId node : immovable) {
    ASSERT_EQ(after.x[node], before.x[node]) << "node " << node;
    ASSERT_EQ(after.y[node], before.y[node]) << "node " << node;
    ASSERT_EQ(after.z[node], before.z[node]) << "node " << node;
  }
  EXPECT_FALSE(after == before);
}

std::vector<Case> AllCases() {
  const std::vector<std::pair<const char*, std::function<absl::StatusOr<Mesh>()>>> meshes = {
      {"distorted_hex", [] { return meshgen::DistortedHexBlock(8, 8, 8, 0.35, 11); }},
      {"jittered_tet", [] { return meshgen::JitteredTetBlock(6, 6, 6, 0.3, 12); }},
      {"hybrid", [] { return meshgen::HybridBlock(8, 8, 8, 0.3, 13); }},
  };
  std::vector<Case> cases;
  for (const auto& [name, make] : meshes) {
    for (Method method : {Method::kGetme, Method::kSimultaneous, Method::kSequential,
                          Method::kWarpage, Method::kSmartLaplace}) {
      cases.push_back({name, make, method});
    }
  }
  return cases;
}

INSTANTIATE_TEST_SUITE_P(GeneratedMeshes, MethodImprovementTest, ::testing::ValuesIn(AllCases()),
                         [](const auto& info) {
                           std::string name = std::string(info.param.mesh_name) + "_" +
                                              MethodName(info.param.method);
                           for (char& c : name) {
                             if (c == '-') c = '_';
                           }
                           return name;
                         });

TEST(WarpageVariantTest, LowersWarpageAgainstGetme) {
  auto getme_mesh = meshgen::HybridBlock(8, 8, 8, 0.3, 13);
  auto warpage_mesh = meshgen::HybridBlock(8, 8, 8, 0.3, 13);
  ASSERT_TRUE(getme_mesh.ok() && warpage_mesh.ok());
  SmoothingParams params;
  auto getme_result = Smooth(*getme_mesh, params);
  params.method = Method::kWarpage;
  auto warpage_result = Smooth(*warpage_mesh, params);
  ASSERT_TRUE(getme_result.ok() && warpage_result.ok());
  // Sec. 4.4 / Table 4: q_γ smoothing trades a little mean ratio for flatter quad faces.
  EXPECT_LT(warpage_result->after.warpage_max, getme_result->after.warpage_max);
  EXPECT_GT(warpage_result->after.q_mean, getme_result->after.q_mean - 0.01);
  EXPECT_EQ(warpage_result->phases.back().phase, Phase::kWarpage);
}

TEST(PlainLaplaceTest, RefusesToHandOutTheElementsItInverts) {
  // Its concave clipped corner pulls nodes across their neighbours' faces (0 → 35 inverted).
  Mesh mesh = testing::LoadSharedMesh("cube-clip-5.vtk");
  SmoothingParams params;
  params.method = Method::kLaplace;
  std::int64_t last_event_invalid = -1;
  auto result =
      Smooth(mesh, params, [&](const ProgressEvent& event) { last_event_invalid = event.invalid; });
  const std::int64_t recount = testing::CountInvalid(mesh);
  ASSERT_GT(recount, 0) << "plain Laplace no longer inverts cube-clip-5: pick a mesh where it does";
  EXPECT_EQ(result.status().code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_THAT(result.status().message(),
              ::testing::HasSubstr(absl::StrCat("plain Laplace smoothing inverted ", recount,
                                                " elements, first: ")));
  // The progress events showed them as they appeared.
  EXPECT_EQ(last_event_invalid, recount);
}

}  // namespace
}  // namespace getme
