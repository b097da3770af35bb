// Boundary-layer columns found by topology (surface/getme_surface/layer_columns.h, issue 15): on
// meshes whose layers are known by construction, the column count, the layer count, every node's
// level and the node below it, and why each column stops; an isotropic block has none.

#include "getme_surface/layer_columns.h"

#include <gtest/gtest.h>

#include "getme/meshgen/distorted_hex_block.h"
#include "getme/meshgen/layered_hex_block.h"
#include "getme_surface/kept_columns.h"
#include "getme_surface/layer_heights.h"
#include "surface_test_meshes.h"

namespace getme::surface {
namespace {

constexpr int kColumnCells = 6;
constexpr int kColumnLayers = 10;

Mesh ColumnLayerBlock() {
  absl::StatusOr<Mesh> mesh =
      meshgen::LayeredHexBlock(kColumnCells, kColumnCells, kColumnLayers, 0.01, 1.3, 0.3, 7);
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  return std::move(*mesh);
}

TEST(LayerColumnsTest, AHexahedralLayerBlockIsOneColumnPerWallFaceThroughItsHeight) {
  const Mesh mesh = ColumnLayerBlock();
  const LayerColumns columns = FindLayerColumns(mesh);
  EXPECT_EQ(columns.column_count(), kColumnCells * kColumnCells);
  EXPECT_EQ(columns.column_elements(), mesh.element_count());
  EXPECT_EQ(columns.layers, kColumnLayers);
  EXPECT_EQ(columns.ends.boundary, kColumnCells * kColumnCells);
  EXPECT_EQ(columns.conflicting_nodes, 0);
  // Grid node (i, j, k) is node i + (n + 1)(j + (n + 1) k) (structured_grid.h): its level is k and
  // the node below it is the same (i, j) one level down.
  constexpr NodeId kPerLevel = (kColumnCells + 1) * (kColumnCells + 1);
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    const int k = node / kPerLevel;
    EXPECT_EQ(columns.level[node], k) << "node " << node;
    if (k > 0) {
      EXPECT_EQ(columns.below[node], node - kPerLevel) << "node " << node;
    }
  }
  // The wall is z = 0, where every wall face lies.
  for (const auto& face : columns.wall_faces) {
    for (int k = 0; k < 4; ++k) EXPECT_EQ(mesh.z()[face[k]], 0.0);
  }
}

TEST(LayerColumnsTest, AnIsotropicBlockHasNoColumns) {
  absl::StatusOr<Mesh> mesh = meshgen::DistortedHexBlock(4, 4, 4, 0.3, 3);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const LayerColumns columns = FindLayerColumns(*mesh);
  EXPECT_EQ(columns.column_count(), 0);
  EXPECT_EQ(columns.layers, 0);
  for (NodeId node = 0; node < mesh->node_count(); ++node) EXPECT_EQ(columns.level[node], -1);
}

TEST(LayerColumnsTest, AThinPrismStackGrowsFromOneSideOnly) {
  // 16 triangles extruded 0.1 high in 4 layers: both end faces could start a column; the stack is
  // one column per triangle from whichever end comes first, spanning the mesh.
  const Mesh mesh = test::PolygonPrism(16, 4, 0.1);
  const LayerColumns columns = FindLayerColumns(mesh);
  EXPECT_EQ(columns.column_count(), 16);
  EXPECT_EQ(columns.layers, 4);
  EXPECT_EQ(columns.ends.boundary, 16);
  EXPECT_EQ(columns.conflicting_nodes, 0);
  EXPECT_EQ(columns.column_elements(), mesh.element_count());
}

TEST(LayerColumnsTest, HeightsAreWallDistancesAndTheDescriptionKeepsThem) {
  const Mesh mesh = ColumnLayerBlock();
  const LayerColumns columns = FindLayerColumns(mesh);
  const WallDistance walls(mesh, columns);
  const KeptLayers kept = DescribeKeptLayers(mesh, columns, walls);
  // One kept column per wall node, each with every level above it.
  EXPECT_EQ(kept.column_count(), (kColumnCells + 1) * (kColumnCells + 1));
  for (std::int64_t c = 0; c < kept.column_count(); ++c) {
    ASSERT_EQ(kept.Nodes(c).size(), static_cast<std::size_t>(kColumnLayers));
    // The wall is the plane z = 0: its normal is z, and a node's distance from it is its z.
    EXPECT_NEAR(kept.direction[c][2], 1.0, 1e-12);
    for (std::size_t k = 0; k < kept.Nodes(c).size(); ++k) {
      EXPECT_NEAR(kept.Distances(c)[k], mesh.z()[kept.Nodes(c)[k]], 1e-12);
    }
  }
  const std::vector<double> quality(mesh.element_count(), 0.5);
  const LayerHeights heights = MeasureLayerHeights(mesh, columns, walls, kept, quality);
  EXPECT_EQ(heights.columns, (kColumnCells + 1) * (kColumnCells + 1));
  EXPECT_EQ(heights.layers, kColumnLayers);
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    if (columns.level[node] < 1) continue;
    EXPECT_NEAR(heights.height[node], mesh.z()[node] - mesh.z()[columns.below[node]], 1e-12);
  }
  // First layer: 0.01 thick, the interior nodes moved by up to 0.3 of it.
  EXPECT_GE(heights.first_min, 0.007 - 1e-12);
  EXPECT_LE(heights.first_max, 0.013 + 1e-12);
  EXPECT_DOUBLE_EQ(heights.q_mean, 0.5);
  EXPECT_GT(heights.mean_lean_degrees, 1.0);  // the jitter leans the columns
}

}  // namespace
}  // namespace getme::surface
