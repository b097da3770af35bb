// Regularization speed (paper Sec. 2.2, Fig. 4 (b)): random valid elements (nodes uniform in the
// unit cube, invalid ones discarded) regularize under repeated transform + mean-edge-length
// scaling with ρ = 1 in a type-typical number of steps, and the share of valid random elements is
// the paper's.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "element_type_tags.h"
#include "getme/elements/element_quality.h"
#include "getme/elements/transform.h"
#include "random_elements.h"

namespace getme::test {
namespace {

constexpr int kElementsPerType = 1000;
constexpr double kRegularQuality = 1.0 - 1e-6;  // "deviated less than 10⁻⁶ from one"
constexpr int kIterationCap = 1000;

// Reference values of our own measurement (2,000 elements per type): the paper's Fig. 4 (b) gives
// curves only, its Sec. 2.2 the valid shares (docs/paper-notes.md#regularization-speed). Indexed
// by TypeIndex.
constexpr double kValidShare[kElementTypeCount] = {0.502, 0.0037, 0.093, 0.053};
constexpr double kMeanIterationsSigmaOne[kElementTypeCount] = {14.3, 6.9, 13.0, 13.6};
constexpr double kMeanIterationsSigmaHalf[kElementTypeCount] = {7.1, 3.8, 6.7, 6.6};
constexpr double kMeanIterationsSigmaOneAndHalf[kElementTypeCount] = {21.4, 10.5, 19.4, 20.8};

template <ElementType kType>
struct Sample {
  std::vector<ElementNodes<kType>> elements;
  std::int64_t draws = 0;
};

template <ElementType kType>
Sample<kType> DrawValidElements(std::uint64_t seed) {
  UnitRandom random(seed);
  Sample<kType> sample;
  sample.elements.reserve(kElementsPerType);
  for (int i = 0; i < kElementsPerType; ++i) {
    sample.elements.push_back(random.ValidElementInUnitCube<kType>(&sample.draws));
  }
  return sample;
}

// Steps of RegularizingStep(σ, ρ = 1) until q > 1 − 10⁻⁶, or kIterationCap + 1 if never.
template <ElementType kType>
int IterationsToRegular(ElementNodes<kType> nodes, double sigma) {
  for (int iteration = 1; iteration <= kIterationCap; ++iteration) {
    nodes = RegularizingStep<kType>(nodes, sigma, 1.0);
    if (MeanRatio<kType>(nodes) > kRegularQuality) return iteration;
  }
  return kIterationCap + 1;
}

struct IterationStatistics {
  double mean = 0.0;
  double standard_deviation = 0.0;
  int capped = 0;
};

template <ElementType kType>
IterationStatistics Regularize(const std::vector<ElementNodes<kType>>& elements, double sigma) {
  IterationStatistics statistics;
  double sum = 0.0;
  double sum_of_squares = 0.0;
  for (const ElementNodes<kType>& element : elements) {
    const int iterations = IterationsToRegular<kType>(element, sigma);
    if (iterations > kIterationCap) ++statistics.capped;
    sum += iterations;
    sum_of_squares += static_cast<double>(iterations) * iterations;
  }
  const double n = static_cast<double>(elements.size());
  statistics.mean = sum / n;
  statistics.standard_deviation =
      std::sqrt(std::max(0.0, sum_of_squares / n - statistics.mean * statistics.mean));
  return statistics;
}

// One sample per type, drawn once and shared by the tests of that type (the hexahedron needs
// ~270,000 draws for 1,000 valid elements).
template <ElementType kType>
const Sample<kType>& SharedSample() {
  static const Sample<kType> sample = DrawValidElements<kType>(0x6e7e4d65 + TypeIndex(kType));
  return sample;
}

template <typename Tag>
class RegularizationSpeedTest : public ::testing::Test {};
TYPED_TEST_SUITE(RegularizationSpeedTest, AllElementTypes, ElementTypeName);

TYPED_TEST(RegularizationSpeedTest, ValidShareMatchesReference) {
  constexpr ElementType kType = TypeParam::kType;
  const auto& sample = SharedSample<kType>();
  const double draws = static_cast<double>(sample.draws);
  const double share = kElementsPerType / draws;
  const double expected = kValidShare[TypeIndex(kType)];
  // Four binomial standard deviations of the share estimated from this many draws.
  const double tolerance = 4.0 * std::sqrt(expected * (1.0 - expected) / draws);
  EXPECT_NEAR(share, expected, tolerance) << sample.draws << " draws for " << kElementsPerType
                                          << " valid " << TypeName(kType) << " elements";
  ::testing::Test::RecordProperty("valid_share", std::to_string(share));
}

// Every element reaches q > 1 − 10⁻⁶, and the mean step count is the reference's within `margin`
// (the standard error of a 1,000-element mean is below 0.1 steps for every type and σ here).
template <ElementType kType>
void ExpectReferenceSpeed(double sigma, double expected_mean, double margin) {
  const IterationStatistics statistics = Regularize<kType>(SharedSample<kType>().elements, sigma);
  EXPECT_EQ(statistics.capped, 0) << statistics.capped << " " << TypeName(kType)
                                  << " elements not regularized within " << kIterationCap
                                  << " steps at sigma " << sigma;
  EXPECT_NEAR(statistics.mean, expected_mean, margin)
      << TypeName(kType) << " at sigma " << sigma << ": standard deviation "
      << statistics.standard_deviation;
  ::testing::Test::RecordProperty("mean_iterations", std::to_string(statistics.mean));
  ::testing::Test::RecordProperty("std_iterations", std::to_string(statistics.standard_deviation));
}

TYPED_TEST(RegularizationSpeedTest, SigmaHalfMatchesReferenceMean) {
  constexpr ElementType kType = TypeParam::kType;
  ExpectReferenceSpeed<kType>(0.5, kMeanIterationsSigmaHalf[TypeIndex(kType)], 1.0);
}

TYPED_TEST(RegularizationSpeedTest, SigmaOneMatchesReferenceMean) {
  constexpr ElementType kType = TypeParam::kType;
  ExpectReferenceSpeed<kType>(1.0, kMeanIterationsSigmaOne[TypeIndex(kType)], 1.5);
}

// Beyond σ ≈ 1/2 the step count grows about linearly with σ (paper, Section 2.2).
TYPED_TEST(RegularizationSpeedTest, SigmaOneAndHalfMatchesReferenceMean) {
  constexpr ElementType kType = TypeParam::kType;
  ExpectReferenceSpeed<kType>(1.5, kMeanIterationsSigmaOneAndHalf[TypeIndex(kType)], 1.5);
}

}  // namespace
}  // namespace getme::test
