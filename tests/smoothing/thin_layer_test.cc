// The hard case of the paper's Table 3: a tetrahedral vessel wrapped in 6 layers of prisms only
// 1% of the wall edge length thick (docs/thin-layers.md). The engine must reach the paper's level,
// q_min ≥ 0.4 and q_mean ≥ 0.8 (paper's aorta: 0.5522 / 0.8231).

#include <gtest/gtest.h>

#include <cmath>

#include "getme/meshgen/thin_prism_vessel.h"
#include "getme/smoothing/smoother.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

// The outer surface of the prism layers (the vessel wall) is fixed; the inflow and outflow caps
// (planes z = 0 and z = length) are not. Pinned caps would pin the cap prisms at their initial 1%
// height, whose mean ratio is ~0.07 whatever the method (docs/thin-layers.md).
Mesh VesselWithFixedWall(meshgen::ThinPrismVesselOptions options) {
  options.fix_outer_wall = true;
  auto mesh = meshgen::ThinPrismVessel(options);
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  // Independently: every boundary node off the two cap planes is fixed, every fixed node is on
  // the boundary, and the caps' interior (inside the wall radius) is free.
  const double tolerance = 1e-9 * options.length;
  for (NodeId node = 0; node < mesh->node_count(); ++node) {
    const double z = mesh->z()[node];
    const bool on_cap = z < tolerance || z > options.length - tolerance;
    const double r = std::hypot(mesh->x()[node], mesh->y()[node]);
    if (mesh->is_boundary(node) && !on_cap) {
      EXPECT_TRUE(mesh->is_fixed(node)) << node;
    }
    if (mesh->is_fixed(node)) {
      EXPECT_TRUE(mesh->is_boundary(node)) << node;
    }
    if (on_cap && r < options.radius * (1.0 + 1e-9)) {
      EXPECT_FALSE(mesh->is_fixed(node)) << node;
    }
  }
  return std::move(*mesh);
}

meshgen::ThinPrismVesselOptions TestVessel() {
  meshgen::ThinPrismVesselOptions options;
  options.radius = 1.0;
  options.length = 3.0;
  options.mesh_size = 0.2;
  options.layers = 6;
  options.layer_height_ratio = 0.01;
  return options;
}

TEST(ThinLayerTest, GetmeReachesThePapersQualityOnThinPrismLayers) {
  Mesh mesh = VesselWithFixedWall(TestVessel());
  ASSERT_GT(mesh.element_count(ElementType::kPrism), 0);
  ASSERT_GT(mesh.element_count(ElementType::kTetrahedron), 0);
  SmoothingParams params;
  params.fix_boundary = false;
  const std::vector<NodeId> fixed = testing::ImmovableNodes(mesh, params);
  const testing::CoordinateSnapshot before(mesh);

  auto result = Smooth(mesh, params);
  ASSERT_TRUE(result.ok()) << result.status();

  // A thin-layer mesh as in the paper: initial quality dominated by flat prisms.
  EXPECT_LT(result->before.q_min, 0.1);
  EXPECT_LT(result->before.q_mean, 0.45);
  EXPECT_LT(result->before.by_type[TypeIndex(ElementType::kPrism)].q_mean, 0.1);

  EXPECT_GE(result->after.q_min, 0.4);
  EXPECT_GE(result->after.q_mean, 0.8);
  EXPECT_EQ(result->after.invalid, 0);
  EXPECT_EQ(testing::CountInvalid(mesh), 0);
  const testing::CoordinateSnapshot after(mesh);
  for (NodeId node : fixed) {
    ASSERT_EQ(after.x[node], before.x[node]);
    ASSERT_EQ(after.y[node], before.y[node]);
    ASSERT_EQ(after.z[node], before.z[node]);
  }
}

TEST(ThinLayerTest, SmartLaplaceStaysFarBelow) {
  // The baseline of Sec. 4 cannot widen the layers (paper Table 3: 0.0211 / 0.5737).
  Mesh mesh = VesselWithFixedWall(TestVessel());
  SmoothingParams params;
  params.fix_boundary = false;
  params.method = Method::kSmartLaplace;
  auto result = Smooth(mesh, params);
  ASSERT_TRUE(result.ok()) << result.status();
  EXPECT_LT(result->after.q_min, 0.3);
  EXPECT_LT(result->after.q_mean, 0.75);
}

}  // namespace
}  // namespace getme
