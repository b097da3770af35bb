// The simultaneous substep evaluates kLanes elements at once (lanes.h). Each lane must hold exactly
// the bits the one-element kernels give for its element, or results would depend on which
// elements happen to share a lane: checked for random valid and invalid elements, regular and
// fully degenerate ones, per element type.

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <vector>

#include "element_type_tags.h"
#include "getme/elements/element_quality.h"
#include "getme/elements/transform.h"
#include "random_elements.h"
#include "regular_elements.h"

namespace getme::test {
namespace {

template <typename Tag>
class LaneKernelsTest : public ::testing::Test {};
TYPED_TEST_SUITE(LaneKernelsTest, AllElementTypes, ElementTypeName);

std::uint64_t LaneBits(double value) { return std::bit_cast<std::uint64_t>(value); }

template <ElementType kType>
std::vector<ElementNodes<kType>> TestElements() {
  UnitRandom random(17);
  std::vector<ElementNodes<kType>> elements;
  // Nodes uniform in the unit cube: a mix of valid and invalid elements for every type.
  for (int i = 0; i < 400; ++i) elements.push_back(random.ElementInUnitCube<kType>());
  elements.push_back(RegularElement<kType>());
  ElementNodes<kType> degenerate;
  degenerate.fill(Vec3(0.25, 0.5, 0.75));  // zero normals and zero edge lengths
  elements.push_back(degenerate);
  return elements;
}

template <ElementType kType>
LaneNodes<kType, Lanes> ToLanes(const std::vector<ElementNodes<kType>>& elements,
                                std::size_t first) {
  LaneNodes<kType, Lanes> lanes;
  for (int l = 0; l < kLanes; ++l) {
    const ElementNodes<kType>& nodes = elements[(first + l) % elements.size()];
    for (int k = 0; k < ElementTable<kType>::kNodes; ++k) {
      lanes[k].x[l] = nodes[k].x();
      lanes[k].y[l] = nodes[k].y();
      lanes[k].z[l] = nodes[k].z();
    }
  }
  return lanes;
}

TYPED_TEST(LaneKernelsTest, RegularizingStepGivesEachLaneTheOneElementBits) {
  constexpr ElementType kType = TypeParam::kType;
  const auto elements = TestElements<kType>();
  UnitRandom random(5);
  for (std::size_t first = 0; first < elements.size(); first += kLanes) {
    Lanes sigma;
    for (int l = 0; l < kLanes; ++l) sigma[l] = random.Uniform(0.5, 3.5);
    const auto moved = RegularizingStep<kType, Lanes>(ToLanes<kType>(elements, first), sigma, 0.6);
    for (int l = 0; l < kLanes; ++l) {
      const auto expected =
          RegularizingStep<kType>(elements[(first + l) % elements.size()], sigma[l], 0.6);
      for (int k = 0; k < ElementTable<kType>::kNodes; ++k) {
        EXPECT_EQ(LaneBits(moved[k].x[l]), LaneBits(expected[k].x())) << "element " << first + l;
        EXPECT_EQ(LaneBits(moved[k].y[l]), LaneBits(expected[k].y())) << "element " << first + l;
        EXPECT_EQ(LaneBits(moved[k].z[l]), LaneBits(expected[k].z())) << "element " << first + l;
      }
    }
  }
}

TYPED_TEST(LaneKernelsTest, MeanRatioGivesEachLaneTheOneElementBits) {
  constexpr ElementType kType = TypeParam::kType;
  const auto elements = TestElements<kType>();
  int invalid = 0;
  for (std::size_t first = 0; first < elements.size(); first += kLanes) {
    const Lanes q = MeanRatioOrInvalid<kType, Lanes>(ToLanes<kType>(elements, first));
    for (int l = 0; l < kLanes; ++l) {
      const double expected = MeanRatioOrInvalid<kType>(elements[(first + l) % elements.size()]);
      EXPECT_EQ(LaneBits(q[l]), LaneBits(expected)) << "element " << first + l;
      if (expected == kInvalidQuality) ++invalid;
    }
  }
  EXPECT_GT(invalid, 0);  // the invalid branch was exercised
}

}  // namespace
}  // namespace getme::test
