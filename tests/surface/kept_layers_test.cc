// Kept boundary layers (SmoothingParams::keep_layers; core/getme/smoothing/layer_phase.h with
// surface/'s columns, issue 15): on a hexahedral layer block on the wall z = 0 (layers 1 % thick
// at the wall, growing 1.3 ×, columns leaning), every layer's height, read from the coordinates
// (the wall is z = 0, so a node's wall distance is its z), stays within 1 % while the layers'
// mean quality rises and their lean falls; without the option the same run changes the heights
// (the option does something); on a block whose columns were shifted sideways, a sliding wall
// keeps its nodes on z = 0 and the corners in place while it regularises its grid with the
// columns, for a better q_mean than with the wall held; every thread count gives the same bits;
// and the option's preconditions are refused by name.

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "getme/meshgen/layered_hex_block.h"
#include "getme/smoothing/smoother.h"
#include "getme_surface/surface_slide.h"

namespace getme::surface {
namespace {

constexpr int kCells = 6;
constexpr int kLayers = 10;
constexpr NodeId kPerLevel = (kCells + 1) * (kCells + 1);

Mesh LayerBlock() {
  absl::StatusOr<Mesh> mesh = meshgen::LayeredHexBlock(kCells, kCells, kLayers, 0.01, 1.3, 0.3, 7);
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  return std::move(*mesh);
}

// LayerBlock with each interior column (i, j), from the wall to the top, moved sideways by up to
// a quarter of the cell width: the wall's grid is irregular, the columns as straight as before.
Mesh ShiftedColumnBlock() {
  Mesh mesh = LayerBlock();
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> offset(-0.25, 0.25);
  for (int j = 1; j < kCells; ++j) {
    for (int i = 1; i < kCells; ++i) {
      const double dx = offset(random);
      const double dy = offset(random);
      for (int k = 0; k <= kLayers; ++k) {
        const NodeId node = i + (kCells + 1) * j + kPerLevel * k;
        mesh.x()[node] += dx;
        mesh.y()[node] += dy;
      }
    }
  }
  return mesh;
}

// The largest |h_after / h_before − 1| of a layer height, h = z(node) − z(node below).
double MaxHeightChange(const Mesh& before, const Mesh& after) {
  double change = 0.0;
  for (NodeId node = kPerLevel; node < before.node_count(); ++node) {
    const double h_before = before.z()[node] - before.z()[node - kPerLevel];
    const double h_after = after.z()[node] - after.z()[node - kPerLevel];
    change = std::max(change, std::abs(h_after / h_before - 1.0));
  }
  return change;
}

// The mean angle (degrees) of the column edges from the wall normal z.
double MeanLean(const Mesh& mesh) {
  double sum = 0.0;
  std::int64_t edges = 0;
  for (NodeId node = kPerLevel; node < mesh.node_count(); ++node) {
    const NodeId below = node - kPerLevel;
    const double dx = mesh.x()[node] - mesh.x()[below];
    const double dy = mesh.y()[node] - mesh.y()[below];
    const double dz = mesh.z()[node] - mesh.z()[below];
    sum += std::atan2(std::hypot(dx, dy), dz) * 180.0 / M_PI;
    ++edges;
  }
  return sum / static_cast<double>(edges);
}

struct SmoothedBlock {
  Mesh mesh;
  SmoothingResult result;
};

SmoothedBlock SmoothBlock(const Mesh& input, bool keep_layers, bool slide_boundary,
                          int threads = 2) {
  SmoothedBlock run{input, {}};
  SmoothingParams params;
  params.threads = threads;
  params.keep_layers = keep_layers;
  params.slide_boundary = slide_boundary;
  SlideOptions options;
  options.keep_layers = keep_layers;
  options.slide_boundary = slide_boundary;
  absl::StatusOr<std::unique_ptr<SurfaceSlide>> slide = SurfaceSlide::Build(run.mesh, options);
  EXPECT_TRUE(slide.ok()) << slide.status();
  absl::StatusOr<SmoothingResult> result = Smooth(run.mesh, params, {}, nullptr, slide->get());
  EXPECT_TRUE(result.ok()) << result.status();
  if (result.ok()) run.result = *std::move(result);
  return run;
}

TEST(KeptLayersTest, HeightsStayWhileTheLayersStraightenAndImprove) {
  const Mesh input = LayerBlock();
  const SmoothedBlock kept = SmoothBlock(input, true, false);
  EXPECT_EQ(kept.result.after.invalid, 0);
  EXPECT_LE(MaxHeightChange(input, kept.mesh), 0.01);
  // Every element is in a column here, so the layers' quality is the mesh's.
  EXPECT_GT(kept.result.after.q_mean, kept.result.before.q_mean);
  EXPECT_GE(kept.result.after.q_min, kept.result.before.q_min);
  EXPECT_LT(MeanLean(kept.mesh), 0.8 * MeanLean(input));
  ASSERT_FALSE(kept.result.phases.empty());
  EXPECT_EQ(kept.result.phases.front().phase, Phase::kLayers);
  // The held boundary did not move.
  for (NodeId node = 0; node < input.node_count(); ++node) {
    if (!input.is_boundary(node)) continue;
    EXPECT_EQ(kept.mesh.x()[node], input.x()[node]);
    EXPECT_EQ(kept.mesh.y()[node], input.y()[node]);
    EXPECT_EQ(kept.mesh.z()[node], input.z()[node]);
  }
}

TEST(KeptLayersTest, WithoutTheOptionTheSameRunChangesTheHeights) {
  const Mesh input = LayerBlock();
  const SmoothedBlock free_layers = SmoothBlock(input, false, false);
  EXPECT_GT(MaxHeightChange(input, free_layers.mesh), 0.05);
}

TEST(KeptLayersTest, ASlidingWallKeepsItsPlaneAndTheColumnsTheirHeights) {
  const Mesh input = ShiftedColumnBlock();
  const SmoothedBlock held = SmoothBlock(input, true, false);
  const SmoothedBlock slid = SmoothBlock(input, true, true);
  EXPECT_EQ(slid.result.after.invalid, 0);
  EXPECT_LE(MaxHeightChange(input, slid.mesh), 0.01);
  // The wall's grid becomes more regular, with its columns: better than with the wall held.
  EXPECT_GT(slid.result.after.q_mean, held.result.after.q_mean);
  EXPECT_GE(slid.result.after.q_min, held.result.after.q_min);
  ASSERT_TRUE(slid.result.boundary_slide.has_value());
  EXPECT_EQ(slid.result.boundary_slide->layer_nodes, kLayers * kPerLevel);
  EXPECT_GT(slid.result.boundary_slide->slid_nodes, 0);
  const double top = input.z()[input.node_count() - 1];
  for (NodeId node = 0; node < input.node_count(); ++node) {
    if (!input.is_boundary(node)) continue;
    // Wall and top nodes stay in their planes, side nodes on theirs; the block's 8 corners stay.
    const int level = node / kPerLevel;
    if (level == 0) {
      EXPECT_NEAR(slid.mesh.z()[node], 0.0, 1e-12) << "node " << node;
    }
    if (level == kLayers) {
      EXPECT_NEAR(slid.mesh.z()[node], top, 1e-12) << "node " << node;
    }
    const int i = node % (kCells + 1);
    const int j = (node / (kCells + 1)) % (kCells + 1);
    if (i == 0 || i == kCells) {
      EXPECT_NEAR(slid.mesh.x()[node], input.x()[node], 1e-12);
    }
    if (j == 0 || j == kCells) {
      EXPECT_NEAR(slid.mesh.y()[node], input.y()[node], 1e-12);
    }
    const bool corner =
        (i == 0 || i == kCells) && (j == 0 || j == kCells) && (level == 0 || level == kLayers);
    if (corner) {
      EXPECT_EQ(slid.mesh.x()[node], input.x()[node]);
      EXPECT_EQ(slid.mesh.y()[node], input.y()[node]);
      EXPECT_EQ(slid.mesh.z()[node], input.z()[node]);
    }
  }
}

TEST(KeptLayersTest, SameBitsForEveryThreadCount) {
  const Mesh input = ShiftedColumnBlock();
  const SmoothedBlock one = SmoothBlock(input, true, true, 1);
  const SmoothedBlock three = SmoothBlock(input, true, true, 3);
  for (NodeId node = 0; node < one.mesh.node_count(); ++node) {
    ASSERT_EQ(one.mesh.x()[node], three.mesh.x()[node]) << "node " << node;
    ASSERT_EQ(one.mesh.y()[node], three.mesh.y()[node]) << "node " << node;
    ASSERT_EQ(one.mesh.z()[node], three.mesh.z()[node]) << "node " << node;
  }
}

TEST(KeptLayersTest, PreconditionsAreRefusedByName) {
  Mesh mesh = LayerBlock();
  SmoothingParams params;
  params.keep_layers = true;
  params.fix_boundary = false;
  absl::Status status = params.Validate();
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(status.message().find("keep_layers"), std::string::npos) << status;

  params.fix_boundary = true;
  absl::StatusOr<SmoothingResult> without_slide = Smooth(mesh, params);
  EXPECT_EQ(without_slide.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(without_slide.status().message().find("keep_layers"), std::string::npos);

  // A slide built without kept layers describes none.
  absl::StatusOr<std::unique_ptr<SurfaceSlide>> slide = SurfaceSlide::Build(mesh);
  ASSERT_TRUE(slide.ok());
  absl::StatusOr<SmoothingResult> undescribed = Smooth(mesh, params, {}, nullptr, slide->get());
  EXPECT_EQ(undescribed.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(undescribed.status().message().find("describes no layers"), std::string::npos)
      << undescribed.status();
}

}  // namespace
}  // namespace getme::surface
