// SmoothingContext: which nodes may move (caller-fixed and, with fix_boundary, boundary nodes do
// not), and the q_min / q_mean / invalid summary with invalid elements counted as q = 0.

#include "getme/smoothing/smoothing_context.h"

#include <gtest/gtest.h>

#include <random>

#include "getme/mesh/mesh_quality.h"
#include "mesh_spec.h"

namespace getme::mesh_test {
namespace {

TEST(SmoothingContext, MovableExcludesFixedAndOptionallyBoundaryNodes) {
  absl::StatusOr<Mesh> mesh = BuildMesh(HexBlock(3));
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const NodeId interior_fixed = HexBlockNodeId(3, 1, 2, 1);
  const NodeId boundary_fixed = HexBlockNodeId(3, 0, 0, 0);
  mesh->set_fixed(interior_fixed, true);
  mesh->set_fixed(boundary_fixed, true);
  ThreadPool pool(2);
  const ProgressCallback no_progress;
  for (bool fix_boundary : {true, false}) {
    SmoothingParams params;
    params.fix_boundary = fix_boundary;
    const SmoothingContext context(*mesh, params, pool, no_progress, nullptr);
    ASSERT_EQ(context.movable.size(), 64u);
    for (int k = 0; k <= 3; ++k) {
      for (int j = 0; j <= 3; ++j) {
        for (int i = 0; i <= 3; ++i) {
          const NodeId node = HexBlockNodeId(3, i, j, k);
          const bool on_boundary = i % 3 == 0 || j % 3 == 0 || k % 3 == 0;
          const bool fixed = node == interior_fixed || node == boundary_fixed;
          EXPECT_EQ(context.movable[node] != 0, !fixed && !(fix_boundary && on_boundary))
              << "node " << node << ", fix_boundary " << fix_boundary;
        }
      }
    }
  }
}

TEST(SmoothingContext, SummaryAgreesWithEvaluateMeshQuality) {
  MeshSpec spec = HexBlock(6);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> jitter(-0.4, 0.4);
  for (Eigen::Vector3d& p : spec.nodes)
    p += Eigen::Vector3d(jitter(random), jitter(random), jitter(random));
  absl::StatusOr<Mesh> mesh = BuildMesh(spec);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  ThreadPool pool(3);
  const SmoothingParams params;
  const ProgressCallback no_progress;
  const SmoothingContext context(*mesh, params, pool, no_progress, nullptr);
  const MeshQuality quality = EvaluateMeshQuality(*mesh, pool);
  ASSERT_GT(quality.invalid, 0) << "the jitter should invert some elements";
  const SmoothingContext::Summary summary = context.Summarize();
  EXPECT_EQ(summary.invalid, quality.invalid);
  EXPECT_EQ(summary.q_min, 0.0);
  EXPECT_NEAR(summary.q_mean, quality.q_mean, 1e-14);
  // Invalid elements are marked, valid ones hold the mean ratio.
  const std::vector<double> mean_ratio = ComputeElementQualities(*mesh, pool);
  const std::vector<std::uint8_t> valid = ComputeElementValidity(*mesh, pool);
  for (ElementId e = 0; e < mesh->element_count(); ++e) {
    if (valid[e]) {
      EXPECT_EQ(context.quality[e], mean_ratio[e]) << "element " << e;
      EXPECT_EQ(ElementQualityOrInvalid(*mesh, e), mean_ratio[e]) << "element " << e;
    } else {
      EXPECT_LT(context.quality[e], 0.0) << "element " << e;
      EXPECT_LT(ElementQualityOrInvalid(*mesh, e), 0.0) << "element " << e;
    }
  }
}

}  // namespace
}  // namespace getme::mesh_test
