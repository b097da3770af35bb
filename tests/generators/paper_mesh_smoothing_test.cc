// GETMe smoothing improves the generated paper meshes, as it does the paper's (Tables 1 and 2):
// evidence that the distortions leave the smoother real work. Labelled slow: whole smoothing
// runs, which the sanitizer stages cover through the smoothing tests' smaller meshes.

#include <gtest/gtest.h>

#include "getme/meshgen/plate_with_holes.h"
#include "getme/meshgen/ring_in_block.h"
#include "getme/smoothing/smoother.h"

namespace getme::meshgen {
namespace {

SmoothingResult SmoothWithGetme(Mesh& mesh) {
  SmoothingParams params;
  params.threads = 2;
  absl::StatusOr<SmoothingResult> result = Smooth(mesh, params);
  EXPECT_TRUE(result.ok()) << result.status();
  return result.ok() ? *result : SmoothingResult{};
}

// Paper Table 1 (plate): q_min 0.1625 → 0.4476, q_mean 0.7302 → 0.8300.
TEST(PaperMeshSmoothingTest, GetmeRaisesThePlatesMinimumAndMeanQuality) {
  absl::StatusOr<Mesh> mesh = PlateWithHoles({.target_elements = 10'000});
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const SmoothingResult result = SmoothWithGetme(*mesh);
  EXPECT_EQ(result.after.invalid, 0);
  EXPECT_GT(result.after.q_min, result.before.q_min + 0.05);
  EXPECT_GT(result.after.q_mean, result.before.q_mean);
}

// Paper Table 2 (ring): q_min 0.0005 → 0.2324, q_mean 0.4499 → 0.7437.
TEST(PaperMeshSmoothingTest, GetmeRaisesTheRingsMinimumAndMeanQuality) {
  absl::StatusOr<Mesh> mesh = RingInBlock({.target_elements = 10'000});
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const SmoothingResult result = SmoothWithGetme(*mesh);
  EXPECT_EQ(result.after.invalid, 0);
  EXPECT_GT(result.after.q_min, result.before.q_min + 0.1);
  EXPECT_GT(result.after.q_mean, result.before.q_mean + 0.1);
}

}  // namespace
}  // namespace getme::meshgen
