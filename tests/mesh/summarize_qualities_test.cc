// SummarizeQualities: exact minimum and a mean whose bits do not depend on the thread count.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

#include "getme/mesh/mesh_quality.h"
#include "getme/parallel/thread_pool.h"

namespace getme {
namespace {

std::vector<double> RandomQualities(std::size_t count, unsigned seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<double> quality(count);
  for (double& q : quality) q = uniform(random);
  return quality;
}

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(SummarizeQualities, BitIdenticalForOneTwoThreeAndEightThreads) {
  for (std::size_t count : {100000u, 100003u, 8192u, 8193u, 17u}) {
    const std::vector<double> quality = RandomQualities(count, 7 + static_cast<unsigned>(count));
    ThreadPool single(1);
    const QualitySummary expected = SummarizeQualities(quality, single);
    for (int threads : {2, 3, 8}) {
      ThreadPool pool(threads);
      for (int repeat = 0; repeat < 3; ++repeat) {
        const QualitySummary summary = SummarizeQualities(quality, pool);
        EXPECT_TRUE(SameBits(summary.q_min, expected.q_min)) << count << " values, " << threads;
        EXPECT_TRUE(SameBits(summary.q_mean, expected.q_mean)) << count << " values, " << threads;
      }
    }
  }
}

TEST(SummarizeQualities, MinimumIsExactAndMeanMatchesLongDoubleSum) {
  std::vector<double> quality = RandomQualities(100000, 99);
  quality[76543] = 1e-7;  // a unique minimum far from the first chunk
  ThreadPool pool(3);
  const QualitySummary summary = SummarizeQualities(quality, pool);
  long double sum = 0.0L;
  for (double q : quality) sum += q;
  EXPECT_EQ(summary.q_min, 1e-7);
  EXPECT_EQ(summary.q_min, *std::min_element(quality.begin(), quality.end()));
  EXPECT_NEAR(summary.q_mean, static_cast<double>(sum / quality.size()), 1e-13);
}

TEST(SummarizeQualities, SingleValue) {
  const std::vector<double> quality = {0.375};
  ThreadPool pool(2);
  const QualitySummary summary = SummarizeQualities(quality, pool);
  EXPECT_EQ(summary.q_min, 0.375);
  EXPECT_EQ(summary.q_mean, 0.375);
}

}  // namespace
}  // namespace getme
