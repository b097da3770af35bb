// The wide element passes (issue 16, item 2: 4 lanes with AVX2, 8 with AVX-512, chosen at run time)
// against the reference two-lane pass and against the one-element kernels: every lane must write
// the bits the one-element kernels give for its element, whatever the width, the range's start
// and its ragged end, so a run's result cannot depend on the machine's vector width. Widths this
// machine cannot run are checked to be refused, not silently narrowed.

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "element_type_tags.h"
#include "getme/elements/element_quality.h"
#include "getme/elements/mean_ratio_derivatives.h"
#include "getme/elements/mean_ratio_gradient.h"
#include "getme/elements/transform.h"
#include "getme/smoothing/element_passes_dispatch.h"
#include "random_elements.h"
#include "regular_elements.h"

namespace getme::test {
namespace {

std::uint64_t Bits(double value) { return std::bit_cast<std::uint64_t>(value); }

// Every element of a test block owns its nodes; element ids run backwards, so a pass that wrote
// block order instead of the element ids would be caught.
template <ElementType kType>
struct TestBlock {
  std::vector<ElementNodes<kType>> elements;
  std::vector<double> x, y, z;
  std::vector<NodeId> nodes;
  std::vector<ElementId> ids;

  BlockRange Range(std::int64_t begin, std::int64_t end) const {
    return {x, y, z, nodes.data(), ids.data(), begin, end};
  }
  ElementId IdOf(std::size_t entry) const { return ids[entry]; }
};

template <ElementType kType>
TestBlock<kType> MakeBlock() {
  UnitRandom random(23);
  TestBlock<kType> block;
  // Nodes uniform in the unit cube: valid and invalid elements of every type.
  for (int i = 0; i < 400; ++i) block.elements.push_back(random.ElementInUnitCube<kType>());
  block.elements.push_back(RegularElement<kType>());
  ElementNodes<kType> degenerate;
  degenerate.fill(Vec3(0.25, 0.5, 0.75));  // zero normals and zero edge lengths
  block.elements.push_back(degenerate);
  // Tiny elements: det² is subnormal, so their lanes take the cube root's libm fallback while
  // their neighbours in the same vector take the polynomial (cube_root.h).
  for (int i = 0; i < 11; ++i) {
    ElementNodes<kType> tiny = RegularElement<kType>();
    for (Vec3& node : tiny) node *= 1e-52;
    block.elements.insert(block.elements.begin() + 7 * i + 3, tiny);
  }
  const auto count = static_cast<ElementId>(block.elements.size());  // 413: no width divides it
  for (ElementId e = 0; e < count; ++e) {
    for (const Vec3& node : block.elements[e]) {
      block.nodes.push_back(static_cast<NodeId>(block.x.size()));
      block.x.push_back(node.x());
      block.y.push_back(node.y());
      block.z.push_back(node.z());
    }
    block.ids.push_back(count - 1 - e);
  }
  return block;
}

// (begin, end) ranges: whole, starting off a vector boundary, and shorter than any vector.
constexpr std::int64_t kRanges[][2] = {{0, 413}, {3, 408}, {5, 6}, {400, 413}};

// A list of the block's entries (stride · k) mod n, k < count: scattered through the block, with
// repeats once count passes n; the list passes see each entry's node ids only.
struct ScatteredList {
  std::vector<std::int64_t> entries;
  std::vector<const NodeId*> node_lists;
};

template <ElementType kType>
ScatteredList ScatterList(const TestBlock<kType>& block, std::int64_t stride, std::int64_t count) {
  const auto n = static_cast<std::int64_t>(block.elements.size());
  ScatteredList list;
  for (std::int64_t k = 0; k < count; ++k) {
    list.entries.push_back((stride * k) % n);
    list.node_lists.push_back(block.nodes.data() +
                              list.entries.back() * ElementTable<kType>::kNodes);
  }
  return list;
}

// Runs check(passes, lanes) with the passes of every width this machine runs, traced with the
// width.
template <typename Check>
void ForEachWidth(const Check& check) {
  for (int lanes : SupportedLaneWidths()) {
    SCOPED_TRACE(::testing::Message() << lanes << " lanes");
    const absl::StatusOr<const ElementPasses*> passes = ElementPassesFor(lanes);
    ASSERT_TRUE(passes.ok()) << passes.status();
    check(**passes, lanes);
  }
}

template <typename Tag>
class ElementPassesTest : public ::testing::Test {};
TYPED_TEST_SUITE(ElementPassesTest, AllElementTypes, ElementTypeName);

// Runs the whole-mesh pass `pass_of(passes)` (one number per element) over every range of
// kRanges at every width: every entry inside the range must get expected(element)'s bits, and no
// entry outside it may be written. Calls count(expected) once per element, at 2 lanes over the
// whole block.
template <ElementType kType, typename PassOf, typename Expected, typename Count>
void CheckWholeMeshPass(const PassOf& pass_of, const Expected& expected_of, const Count& count) {
  const TestBlock<kType> block = MakeBlock<kType>();
  const std::size_t n = block.elements.size();
  ForEachWidth([&](const ElementPasses& passes, int lanes) {
    ASSERT_EQ(passes.lanes, lanes);
    for (const auto& [begin, end] : kRanges) {
      std::vector<double> out(n, std::numeric_limits<double>::quiet_NaN());
      pass_of(passes)[TypeIndex(kType)](block.Range(begin, end), out.data());
      for (std::int64_t i = 0; i < static_cast<std::int64_t>(n); ++i) {
        const double written = out[block.IdOf(i)];
        if (i < begin || i >= end) {
          EXPECT_TRUE(std::isnan(written))
              << "entry " << i << " outside [" << begin << ", " << end << ") was written";
          continue;
        }
        const double expected = expected_of(block.elements[i]);
        EXPECT_EQ(Bits(written), Bits(expected))
            << "entry " << i << ": " << written << " vs " << expected;
        if (lanes == 2 && begin == 0) count(expected);
      }
    }
  });
}

TYPED_TEST(ElementPassesTest, MeanRatioPassGivesTheOneElementBitsAtEveryWidth) {
  constexpr ElementType kType = TypeParam::kType;
  int invalid = 0;
  CheckWholeMeshPass<kType>(
      [](const ElementPasses& passes) { return passes.mean_ratio; },
      [](const ElementNodes<kType>& nodes) { return MeanRatioOrInvalid<kType>(nodes); },
      [&](double expected) { invalid += expected == kInvalidQuality; });
  // The random elements include invalid ones, so the validity lanes were exercised too.
  EXPECT_GT(invalid, 10);
}

// The warpage pass (the measures a run reports before and after): the one-element Warpage's bits
// in every lane, degenerate faces (warpage 2) included.
TYPED_TEST(ElementPassesTest, WarpagePassGivesTheOneElementBitsAtEveryWidth) {
  constexpr ElementType kType = TypeParam::kType;
  int warped = 0;
  int degenerate = 0;
  CheckWholeMeshPass<kType>([](const ElementPasses& passes) { return passes.warpage; },
                            [](const ElementNodes<kType>& nodes) { return Warpage<kType>(nodes); },
                            [&](double expected) {
                              warped += expected > 0.0 && expected < 2.0;
                              degenerate += expected == 2.0;
                            });
  if constexpr (kType == ElementType::kTetrahedron) {
    EXPECT_EQ(warped + degenerate, 0);  // no quad face
  } else {
    EXPECT_GT(warped, 100);
    EXPECT_GE(degenerate, 1);  // the all-one-point element
  }
}

// The list pass (a sequential pick's elements, anywhere in their block): every list length from
// 1 to past the widest vector, in a scattered order with repeats, must write the one-element bits
// into the list's own slots and nothing past them.
TYPED_TEST(ElementPassesTest, MeanRatioListPassGivesTheOneElementBitsAtEveryWidth) {
  constexpr ElementType kType = TypeParam::kType;
  const TestBlock<kType> block = MakeBlock<kType>();
  const auto n = static_cast<std::int64_t>(block.elements.size());
  // Entries 0, 37, 74, ... modulo n: scattered, and every 413th repeats.
  const ScatteredList list = ScatterList<kType>(block, 37, 2 * n);
  const std::vector<std::int64_t>& entries = list.entries;
  const std::vector<const NodeId*>& node_lists = list.node_lists;
  int invalid = 0;
  ForEachWidth([&](const ElementPasses& passes, int lanes) {
    for (const std::int64_t count : {1, 2, 3, 5, 8, 9, 17, 826}) {
      std::vector<double> quality(count + 1, std::numeric_limits<double>::quiet_NaN());
      passes.mean_ratio_list[TypeIndex(kType)](
          {block.x, block.y, block.z, node_lists.data(), count}, quality.data());
      for (std::int64_t i = 0; i < count; ++i) {
        const double expected = MeanRatioOrInvalid<kType>(block.elements[entries[i]]);
        EXPECT_EQ(Bits(quality[i]), Bits(expected))
            << "list entry " << i << " (block entry " << entries[i] << "), " << count
            << " elements: " << quality[i] << " vs " << expected;
        if (lanes == 2 && count == 826 && expected == kInvalidQuality) ++invalid;
      }
      EXPECT_TRUE(std::isnan(quality[count])) << "the slot past " << count << " was written";
    }
  });
  EXPECT_GT(invalid, 10);
}

// The polish's trials evaluate a node's elements through the cost-and-quality list pass: each
// must get the one-element CostAndQuality's bits (mean_ratio_derivatives.h), invalid ones
// included, at every width.
TYPED_TEST(ElementPassesTest, CostAndQualityListPassGivesTheOneElementBitsAtEveryWidth) {
  constexpr ElementType kType = TypeParam::kType;
  const TestBlock<kType> block = MakeBlock<kType>();
  const auto n = static_cast<std::int64_t>(block.elements.size());
  const ScatteredList list = ScatterList<kType>(block, 53, n);
  const std::vector<std::int64_t>& entries = list.entries;
  const std::vector<const NodeId*>& node_lists = list.node_lists;
  int invalid = 0;
  ForEachWidth([&](const ElementPasses& passes, int lanes) {
    for (const std::int64_t count :
         {std::int64_t{1}, std::int64_t{3}, std::int64_t{7}, std::int64_t{9}, n}) {
      std::vector<double> cost(count + 1, std::numeric_limits<double>::quiet_NaN());
      std::vector<double> quality(count + 1, std::numeric_limits<double>::quiet_NaN());
      passes.cost_and_quality_list[TypeIndex(kType)](
          {block.x, block.y, block.z, node_lists.data(), count}, cost.data(), quality.data());
      for (std::int64_t i = 0; i < count; ++i) {
        const InverseMeanRatioCostAndQuality expected =
            CostAndQuality<kType>(block.elements[entries[i]]);
        EXPECT_EQ(Bits(quality[i]), Bits(expected.quality))
            << "list entry " << i << ": " << quality[i] << " vs " << expected.quality;
        EXPECT_EQ(Bits(cost[i]), Bits(expected.cost))
            << "list entry " << i << ": " << cost[i] << " vs " << expected.cost;
        if (lanes == 2 && count == n && expected.quality == kInvalidQuality) ++invalid;
      }
      EXPECT_TRUE(std::isnan(quality[count]) && std::isnan(cost[count]))
          << "the slot past " << count << " was written";
    }
  });
  EXPECT_GT(invalid, 10);
}

// The element with its nodes in the order kSymmetryToFirst[node] gives (element_tables.h), where
// the type has one: its node `node` comes first.
template <ElementType kType>
ElementNodes<kType> TurnedToFirst(const ElementNodes<kType>& p, int node) {
  if constexpr (HasFirstNodeSymmetry<kType>) {
    ElementNodes<kType> turned;
    for (int k = 0; k < ElementTable<kType>::kNodes; ++k) {
      turned[k] = p[ElementTable<kType>::kSymmetryToFirst[node][k]];
    }
    return turned;
  } else {
    return p;
  }
}

// A polish step takes the derivatives of its node's elements through the Hessian list pass, each
// element with respect to its own local node: every lane must get the one-element bits
// (InverseMeanRatioHessian), invalid elements included (cost +∞, zero derivatives), at every width.
// Those of the element turned so that its node comes first, where the type has the symmetry
// (mean_ratio_derivatives_test.cc checks that turning keeps the values).
TYPED_TEST(ElementPassesTest, HessianListPassGivesTheOneElementBitsAtEveryWidth) {
  constexpr ElementType kType = TypeParam::kType;
  constexpr int kNodes = ElementTable<kType>::kNodes;
  const TestBlock<kType> block = MakeBlock<kType>();
  const auto n = static_cast<std::int64_t>(block.elements.size());
  const ScatteredList list = ScatterList<kType>(block, 29, n);
  const std::vector<std::int64_t>& entries = list.entries;
  const std::vector<const NodeId*>& node_lists = list.node_lists;
  std::vector<int> local;  // every node, mixed within each vector
  for (std::int64_t k = 0; k < n; ++k)
    local.push_back(static_cast<int>((k * 7 + k / kNodes) % kNodes));
  int invalid = 0;
  ForEachWidth([&](const ElementPasses& passes, int lanes) {
    for (const std::int64_t count :
         {std::int64_t{1}, std::int64_t{2}, std::int64_t{5}, std::int64_t{11}, n}) {
      std::vector<InverseMeanRatioHessianOf<double>> got(count);
      passes.hessian_list[TypeIndex(kType)]({block.x, block.y, block.z, node_lists.data(), count},
                                            local.data(), got.data());
      for (std::int64_t i = 0; i < count; ++i) {
        const InverseMeanRatioHessianResult expected =
            HasFirstNodeSymmetry<kType>
                ? InverseMeanRatioHessian<kType>(
                      TurnedToFirst<kType>(block.elements[entries[i]], local[i]), 0)
                : InverseMeanRatioHessian<kType>(block.elements[entries[i]], local[i]);
        const InverseMeanRatioHessianResult lane = ToHessianResult(got[i]);
        SCOPED_TRACE(::testing::Message() << "list entry " << i << ", node " << local[i]);
        EXPECT_EQ(Bits(lane.cost), Bits(expected.cost));
        for (int r = 0; r < 3; ++r) {
          EXPECT_EQ(Bits(lane.gradient[r]), Bits(expected.gradient[r])) << "gradient " << r;
          for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(Bits(lane.hessian(r, c)), Bits(expected.hessian(r, c)))
                << "hessian " << r << "," << c;
          }
        }
        if (lanes == 2 && count == n && !std::isfinite(expected.cost)) ++invalid;
      }
    }
  });
  EXPECT_GT(invalid, 10);
}

// The worst-cluster stage evaluates its elements' mean ratios and gradients through the gradient
// list pass: every lane must get the one-element MeanRatioWithGradient's bits for every node
// (mean_ratio_gradient.h), invalid elements included (kInvalidQuality, zero gradient), at every
// width, and nothing past the list may be written.
TYPED_TEST(ElementPassesTest, MeanRatioGradientListPassGivesTheOneElementBitsAtEveryWidth) {
  constexpr ElementType kType = TypeParam::kType;
  constexpr int kNodes = ElementTable<kType>::kNodes;
  const TestBlock<kType> block = MakeBlock<kType>();
  const auto n = static_cast<std::int64_t>(block.elements.size());
  const ScatteredList list = ScatterList<kType>(block, 31, n);
  const std::vector<std::int64_t>& entries = list.entries;
  const std::vector<const NodeId*>& node_lists = list.node_lists;
  int invalid = 0;
  ForEachWidth([&](const ElementPasses& passes, int lanes) {
    for (const std::int64_t count :
         {std::int64_t{1}, std::int64_t{3}, std::int64_t{6}, std::int64_t{13}, n}) {
      MeanRatioAndGradient untouched;
      untouched.quality = std::numeric_limits<double>::quiet_NaN();
      untouched.gradient.fill(Vec3::Zero());
      std::vector<MeanRatioAndGradient> got(count + 1, untouched);
      passes.mean_ratio_gradient_list[TypeIndex(kType)](
          {block.x, block.y, block.z, node_lists.data(), count}, got.data());
      for (std::int64_t i = 0; i < count; ++i) {
        SCOPED_TRACE(::testing::Message() << "list entry " << i);
        const MeanRatioGradientResult<kType> expected =
            MeanRatioWithGradient<kType>(block.elements[entries[i]]);
        EXPECT_EQ(Bits(got[i].quality), Bits(expected.quality))
            << got[i].quality << " vs " << expected.quality;
        for (int k = 0; k < kNodes; ++k) {
          for (int c = 0; c < 3; ++c) {
            EXPECT_EQ(Bits(got[i].gradient[k][c]), Bits(expected.gradient[k][c]))
                << "node " << k << ", coordinate " << c;
          }
        }
        if (lanes == 2 && count == n && expected.quality == kInvalidQuality) ++invalid;
      }
      EXPECT_TRUE(std::isnan(got[count].quality)) << "the slot past " << count << " was written";
    }
  });
  EXPECT_GT(invalid, 10);
}

// A block whose elements share nodes: kNodes distinct nodes each, drawn from a pool of 90 random
// points, so most nodes collect contributions from many elements and the order they are added in
// shows in the last bits.
template <ElementType kType>
TestBlock<kType> SharedNodeBlock() {
  constexpr int kNodes = ElementTable<kType>::kNodes;
  constexpr int kPool = 90;
  UnitRandom random(31);
  TestBlock<kType> block;
  for (int i = 0; i < kPool; ++i) {
    block.x.push_back(random.Uniform());
    block.y.push_back(random.Uniform());
    block.z.push_back(random.Uniform());
  }
  constexpr ElementId kCount = 413;
  for (ElementId e = 0; e < kCount; ++e) {
    std::vector<NodeId> picked;
    while (static_cast<int>(picked.size()) < kNodes) {
      const auto node = static_cast<NodeId>(random.Uniform() * kPool);
      if (std::find(picked.begin(), picked.end(), node) == picked.end()) picked.push_back(node);
    }
    ElementNodes<kType> nodes;
    for (int k = 0; k < kNodes; ++k) {
      nodes[k] = Vec3(block.x[picked[k]], block.y[picked[k]], block.z[picked[k]]);
    }
    block.elements.push_back(nodes);
    block.nodes.insert(block.nodes.end(), picked.begin(), picked.end());
    block.ids.push_back(kCount - 1 - e);
  }
  return block;
}

struct TransformCase {
  double eta;  // 1/4 is the paper's default; 0.3 takes pow lane by lane
  double rho;
};

TYPED_TEST(ElementPassesTest, ScatterTransformPassAddsTheOneElementBitsInOrderAtEveryWidth) {
  constexpr ElementType kType = TypeParam::kType;
  constexpr int kNodes = ElementTable<kType>::kNodes;
  const TestBlock<kType> block = SharedNodeBlock<kType>();
  const std::size_t n = block.elements.size();
  const std::size_t node_count = block.x.size();
  // Qualities as the iteration stores them (−1 for an invalid element), by element id.
  std::vector<double> quality(n);
  int invalid = 0;
  for (std::size_t i = 0; i < n; ++i) {
    quality[block.IdOf(i)] = MeanRatioOrInvalid<kType>(block.elements[i]);
    if (quality[block.IdOf(i)] < 0.0) ++invalid;
  }
  EXPECT_GT(invalid, 10);  // q = 0 lanes (weight 1) are exercised
  // The block in a visiting order that is neither its own nor its reverse, as ElementTiles
  // hands the pass a reordered block.
  std::vector<std::int32_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::int32_t>((i * 157) % n);
  std::vector<NodeId> visit_nodes;
  std::vector<ElementId> visit_ids;
  for (std::int32_t entry : order) {
    visit_nodes.insert(visit_nodes.end(), block.nodes.begin() + entry * kNodes,
                       block.nodes.begin() + (entry + 1) * kNodes);
    visit_ids.push_back(block.IdOf(entry));
  }
  for (const TransformCase& c : {TransformCase{0.25, 0.6}, TransformCase{0.5, 1.0},
                                 TransformCase{1.0, 0.3}, TransformCase{0.3, 0.75}}) {
    for (const auto& [begin, end] : kRanges) {
      TransformPassSettings settings;
      settings.sigma_min = 0.75;
      settings.sigma_span = 2.25;
      settings.rho = c.rho;
      settings.eta = c.eta;
      settings.quality = quality.data();
      // Step 1 on each element alone, with the one-element kernels (transform.h) and the pass's
      // weight rule on a double, added in the visiting order, starting from sums already there.
      std::vector<NodeSum> expected(node_count, NodeSum{1.0, -2.0, 0.5, 0.25});
      for (std::int64_t i = begin; i < end; ++i) {
        const std::int32_t entry = order[i];
        const double q = std::max(0.0, quality[block.IdOf(entry)]);
        const auto moved = RegularizingStep<kType>(
            block.elements[entry], settings.sigma_min + settings.sigma_span * (1.0 - q), c.rho);
        const double weight = WeightOfElement(1.0 - q, c.eta);
        // The weight rule itself against libm's pow: square roots for 1/4 are within an ulp.
        EXPECT_NEAR(weight, std::pow(1.0 - q, c.eta), 4e-16 * std::max(1.0, weight));
        for (int k = 0; k < kNodes; ++k) {
          NodeSum& sum = expected[block.nodes[entry * kNodes + k]];
          sum.x += weight * moved[k].x();
          sum.y += weight * moved[k].y();
          sum.z += weight * moved[k].z();
          sum.w += weight;
        }
      }
      for (int lanes : SupportedLaneWidths()) {
        SCOPED_TRACE(::testing::Message()
                     << lanes << " lanes, eta " << c.eta << ", [" << begin << ", " << end << ")");
        const ElementPasses* passes = *ElementPassesFor(lanes);
        std::vector<NodeSum> sums(node_count, NodeSum{1.0, -2.0, 0.5, 0.25});
        settings.sums = sums.data();
        passes->scatter_transform[TypeIndex(kType)](
            {block.x, block.y, block.z, visit_nodes.data(), visit_ids.data(), begin, end},
            settings);
        for (std::size_t node = 0; node < node_count; ++node) {
          ASSERT_EQ(Bits(sums[node].x), Bits(expected[node].x)) << "node " << node;
          ASSERT_EQ(Bits(sums[node].y), Bits(expected[node].y)) << "node " << node;
          ASSERT_EQ(Bits(sums[node].z), Bits(expected[node].z)) << "node " << node;
          ASSERT_EQ(Bits(sums[node].w), Bits(expected[node].w)) << "node " << node;
        }
      }
    }
  }
}

TEST(ElementPassesForTest, WidthsAreTheReferenceAndWhatTheMachineRuns) {
  const std::vector<int> widths = SupportedLaneWidths();
  ASSERT_FALSE(widths.empty());
  EXPECT_EQ(widths.front(), 2);  // the reference runs on every x86-64
  EXPECT_TRUE(std::is_sorted(widths.begin(), widths.end()));
  // 0 picks the widest.
  const absl::StatusOr<const ElementPasses*> widest = ElementPassesFor(0);
  ASSERT_TRUE(widest.ok()) << widest.status();
  EXPECT_EQ((*widest)->lanes, widths.back());
}

TEST(ElementPassesForTest, WidthsThisMachineCannotRunAreRefusedWithFailedPrecondition) {
  const std::vector<int> widths = SupportedLaneWidths();
  for (int lanes : {4, 8}) {
    const absl::StatusOr<const ElementPasses*> passes = ElementPassesFor(lanes);
    if (std::find(widths.begin(), widths.end(), lanes) != widths.end()) {
      ASSERT_TRUE(passes.ok()) << passes.status();
      EXPECT_EQ((*passes)->lanes, lanes);
    } else {
      EXPECT_EQ(passes.status().code(), absl::StatusCode::kFailedPrecondition);
      EXPECT_NE(passes.status().message().find("does not run"), std::string::npos)
          << passes.status();
    }
  }
}

TEST(ElementPassesForTest, OtherWidthsAreInvalidArguments) {
  for (int lanes : {-1, 1, 3, 16}) {
    const absl::StatusOr<const ElementPasses*> passes = ElementPassesFor(lanes);
    EXPECT_EQ(passes.status().code(), absl::StatusCode::kInvalidArgument) << lanes;
    EXPECT_NE(passes.status().message().find("kernel lanes"), std::string::npos) << passes.status();
  }
}

}  // namespace
}  // namespace getme::test
