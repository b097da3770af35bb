// SmoothingContext::RefreshQualityAndSummarize computes the qualities and their summary in one
// pass; it must give exactly what RefreshQuality() followed by Summarize() gives, for any thread
// count, including invalid elements and summary chunks that span element type blocks.

#include <gtest/gtest.h>

#include "getme/chunked_summary.h"
#include "getme/meshgen/hybrid_block.h"
#include "getme/smoothing_context.h"

namespace getme {
namespace {

TEST(FusedQualityPassTest, SameQualitiesAndSummaryBitsAsRefreshThenSummarize) {
  auto mesh = meshgen::HybridBlock(15, 15, 15, 0.3, 3);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  // Several reduction chunks, crossing from one type block into the next.
  ASSERT_GT(mesh->element_count(), 2 * kReductionChunk);
  ASSERT_GT(mesh->element_count(ElementType::kHexahedron), 0);
  ASSERT_GT(mesh->element_count(ElementType::kPrism), 0);
  // Invert the elements around a few interior nodes by throwing the nodes far away.
  for (NodeId node : {400, 900, 1500}) mesh->x()[node] += 50.0;

  for (int threads : {1, 3}) {
    SmoothingParams params;
    ThreadPool pool(threads);
    const ProgressCallback no_progress;
    SmoothingContext separate(*mesh, params, pool, no_progress, nullptr);
    SmoothingContext fused(*mesh, params, pool, no_progress, nullptr);
    separate.RefreshQuality();
    const SmoothingContext::Summary expected = separate.Summarize();
    fused.quality.assign(fused.quality.size(), 0.5);  // stale values must all be replaced
    const SmoothingContext::Summary summary = fused.RefreshQualityAndSummarize();

    EXPECT_GT(expected.invalid, 0);
    EXPECT_EQ(summary.invalid, expected.invalid) << threads << " threads";
    EXPECT_EQ(summary.q_min, expected.q_min) << threads << " threads";
    EXPECT_EQ(summary.q_mean, expected.q_mean) << threads << " threads";
    EXPECT_EQ(fused.quality, separate.quality) << threads << " threads";
  }
}

}  // namespace
}  // namespace getme
