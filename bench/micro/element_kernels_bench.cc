// (a) transform + scaling + relaxation and (b) mean ratio, per element type: nanoseconds per
// element over a batch of distorted elements that stays in the L2 cache, so the figures are the
// kernels' arithmetic, without the mesh's gather and scatter. Each one element at a time (the
// sequential substep's way) and kLanes at a time (/lanes: the simultaneous substep's way).

#include <benchmark/benchmark.h>

#include <array>
#include <chrono>
#include <cmath>
#include <random>
#include <vector>

#include "getme/elements/element_quality.h"
#include "getme/elements/transform.h"

namespace getme::bench {
namespace {

constexpr int kBatch = 1024;

// The regular element of each type with edge length 1 (node 0 at the origin; the edges spanning
// node 0's node tetrahedron are the columns of W, paper eq. (10), for the hexahedron rotated).
template <ElementType kType>
ElementNodes<kType> RegularElement() {
  const double h = std::sqrt(3.0) / 2.0;
  if constexpr (kType == ElementType::kTetrahedron) {
    return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, h, 0),
            Vec3(0.5, std::sqrt(3.0) / 6.0, std::sqrt(2.0 / 3.0))};
  } else if constexpr (kType == ElementType::kHexahedron) {
    return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
            Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1)};
  } else if constexpr (kType == ElementType::kPyramid) {
    return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0),
            Vec3(0.5, 0.5, std::sqrt(0.5))};
  } else {
    return {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, h, 0),
            Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(0.5, h, 1)};
  }
}

// Regular elements with every coordinate moved by up to ±0.25, invalid ones drawn again: the
// mix of qualities a smoother meets (q between about 0.3 and 1).
template <ElementType kType>
std::vector<ElementNodes<kType>> DistortedElements() {
  std::mt19937_64 random(42);
  std::uniform_real_distribution<double> offset(-0.25, 0.25);
  std::vector<ElementNodes<kType>> elements;
  while (static_cast<int>(elements.size()) < kBatch) {
    ElementNodes<kType> nodes = RegularElement<kType>();
    for (Vec3& node : nodes) node += Vec3(offset(random), offset(random), offset(random));
    if (IsValid<kType>(nodes)) elements.push_back(nodes);
  }
  return elements;
}

// Runs kernel over the batch once per benchmark iteration and reports ns_per_element.
template <ElementType kType, typename Kernel>
void RunPerElement(benchmark::State& state, Kernel&& kernel) {
  const std::vector<ElementNodes<kType>> elements = DistortedElements<kType>();
  double total_seconds = 0.0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    for (const ElementNodes<kType>& nodes : elements) kernel(nodes);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.SetIterationTime(seconds);
    total_seconds += seconds;
  }
  state.counters["ns_per_element"] =
      1e9 * total_seconds / (static_cast<double>(state.iterations()) * kBatch);
}

template <ElementType kType>
void BM_RegularizingStep(benchmark::State& state) {
  const int t = TypeIndex(kType);
  // The simultaneous substep's σ range and ρ (Sec. 4): σ_min for the batch, σ_max would do too.
  constexpr std::array<double, kElementTypeCount> kSigma = {0.77, 2.57, 1.86, 1.59};
  RunPerElement<kType>(state, [&](const ElementNodes<kType>& nodes) {
    auto moved = RegularizingStep<kType>(nodes, kSigma[t], 2.0 / 3.0);
    benchmark::DoNotOptimize(moved);
  });
}

// The same kernels on kLanes elements at once (lanes.h), as the simultaneous substep's passes
// over the mesh run them; ns_per_element counts every element of the batch.
template <ElementType kType>
std::vector<LaneNodes<kType, Lanes>> InLanes(const std::vector<ElementNodes<kType>>& elements) {
  std::vector<LaneNodes<kType, Lanes>> groups(elements.size() / kLanes);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    for (int l = 0; l < kLanes; ++l) {
      const ElementNodes<kType>& nodes = elements[g * kLanes + l];
      for (int k = 0; k < ElementTable<kType>::kNodes; ++k) {
        groups[g][k].x[l] = nodes[k].x();
        groups[g][k].y[l] = nodes[k].y();
        groups[g][k].z[l] = nodes[k].z();
      }
    }
  }
  return groups;
}

template <ElementType kType, typename Kernel>
void RunPerLaneGroup(benchmark::State& state, Kernel&& kernel) {
  const std::vector<LaneNodes<kType, Lanes>> groups = InLanes<kType>(DistortedElements<kType>());
  double total_seconds = 0.0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    for (const LaneNodes<kType, Lanes>& nodes : groups) kernel(nodes);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.SetIterationTime(seconds);
    total_seconds += seconds;
  }
  state.counters["ns_per_element"] =
      1e9 * total_seconds / (static_cast<double>(state.iterations()) * kBatch);
}

template <ElementType kType>
void BM_RegularizingStepLanes(benchmark::State& state) {
  constexpr std::array<double, kElementTypeCount> kSigma = {0.77, 2.57, 1.86, 1.59};
  const Lanes sigma = Splat<Lanes>(kSigma[TypeIndex(kType)]);
  RunPerLaneGroup<kType>(state, [&](const LaneNodes<kType, Lanes>& nodes) {
    auto moved = RegularizingStep<kType, Lanes>(nodes, sigma, 2.0 / 3.0);
    benchmark::DoNotOptimize(moved);
  });
}

template <ElementType kType>
void BM_MeanRatioLanes(benchmark::State& state) {
  RunPerLaneGroup<kType>(state, [](const LaneNodes<kType, Lanes>& nodes) {
    Lanes q = MeanRatioOrInvalid<kType, Lanes>(nodes);
    benchmark::DoNotOptimize(q);
  });
}

template <ElementType kType>
void BM_MeanRatio(benchmark::State& state) {
  RunPerElement<kType>(state, [](const ElementNodes<kType>& nodes) {
    double q = MeanRatioOrInvalid<kType>(nodes);
    benchmark::DoNotOptimize(q);
  });
}

BENCHMARK(BM_RegularizingStep<ElementType::kTetrahedron>)
    ->Name("RegularizingStep/tet")
    ->UseManualTime();
BENCHMARK(BM_RegularizingStep<ElementType::kHexahedron>)
    ->Name("RegularizingStep/hex")
    ->UseManualTime();
BENCHMARK(BM_RegularizingStep<ElementType::kPyramid>)
    ->Name("RegularizingStep/pyramid")
    ->UseManualTime();
BENCHMARK(BM_RegularizingStep<ElementType::kPrism>)
    ->Name("RegularizingStep/prism")
    ->UseManualTime();
BENCHMARK(BM_RegularizingStepLanes<ElementType::kTetrahedron>)
    ->Name("RegularizingStep/tet/lanes")
    ->UseManualTime();
BENCHMARK(BM_RegularizingStepLanes<ElementType::kHexahedron>)
    ->Name("RegularizingStep/hex/lanes")
    ->UseManualTime();
BENCHMARK(BM_RegularizingStepLanes<ElementType::kPyramid>)
    ->Name("RegularizingStep/pyramid/lanes")
    ->UseManualTime();
BENCHMARK(BM_RegularizingStepLanes<ElementType::kPrism>)
    ->Name("RegularizingStep/prism/lanes")
    ->UseManualTime();
BENCHMARK(BM_MeanRatio<ElementType::kTetrahedron>)->Name("MeanRatio/tet")->UseManualTime();
BENCHMARK(BM_MeanRatio<ElementType::kHexahedron>)->Name("MeanRatio/hex")->UseManualTime();
BENCHMARK(BM_MeanRatio<ElementType::kPyramid>)->Name("MeanRatio/pyramid")->UseManualTime();
BENCHMARK(BM_MeanRatio<ElementType::kPrism>)->Name("MeanRatio/prism")->UseManualTime();
BENCHMARK(BM_MeanRatioLanes<ElementType::kTetrahedron>)
    ->Name("MeanRatio/tet/lanes")
    ->UseManualTime();
BENCHMARK(BM_MeanRatioLanes<ElementType::kHexahedron>)
    ->Name("MeanRatio/hex/lanes")
    ->UseManualTime();
BENCHMARK(BM_MeanRatioLanes<ElementType::kPyramid>)
    ->Name("MeanRatio/pyramid/lanes")
    ->UseManualTime();
BENCHMARK(BM_MeanRatioLanes<ElementType::kPrism>)->Name("MeanRatio/prism/lanes")->UseManualTime();

}  // namespace
}  // namespace getme::bench
