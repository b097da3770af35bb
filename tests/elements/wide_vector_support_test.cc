// The engine's own check of what wide code this machine runs, against Highway's
// (hwy::SupportedTargets, which the engine no longer links: wide_vector_support.h says why).
#include "getme/smoothing/wide_vector_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "getme/smoothing/element_passes_dispatch.h"
#include "hwy/targets.h"

namespace getme {
namespace {

TEST(WideVectorSupportTest, AgreesWithHighwaysOwnCheck) {
  const WideVectorSupport ours = DetectWideVectorSupport();
  const std::int64_t highway = hwy::SupportedTargets();
  EXPECT_EQ(ours.avx2, (highway & HWY_AVX2) != 0);
  EXPECT_EQ(ours.avx512, (highway & HWY_AVX3) != 0);
}

TEST(WideVectorSupportTest, TheWidthsOnOfferAreTheOnesHighwayWouldRun) {
  const std::int64_t highway = hwy::SupportedTargets();
  std::vector<int> expected = {2};
  if (highway & HWY_AVX2) expected.push_back(4);
  if (highway & HWY_AVX3) expected.push_back(8);
  EXPECT_EQ(SupportedLaneWidths(), expected);
}

}  // namespace
}  // namespace getme
