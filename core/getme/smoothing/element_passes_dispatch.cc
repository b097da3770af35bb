// Highway compiles this file once per target (foreach_target.h re-includes it): the part between
// HWY_BEFORE_NAMESPACE and HWY_AFTER_NAMESPACE with that target's instruction set and in its own
// namespace, so no inline function compiled for AVX-512 can stand in for the baseline one (the
// one-definition hazard of compiling a file with -mavx512f). The HWY_ONCE part, compiled once,
// picks a target's table at run time.
//
// Only the arithmetic of element_passes.h is vectorised here, and it is written with GCC vector
// types, not Highway ops: the kernels were already generic over their lane type, and the wider
// lanes must give the reference's bits, which holds because every lane operation is an IEEE 754
// operation on that lane (lanes.h). Highway's part is what a library does better than a
// hand-written switch: per-target compilation and isolation. Only its headers are used: the run
// time check is wide_vector_support.h, which says why.
// -ffp-contract=off (core/CMakeLists.txt) keeps the compiler from fusing a·b + c into one
// rounding, which would change bits.

#include "getme/smoothing/element_passes_dispatch.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "getme/smoothing/element_passes_dispatch.cc"
// AVX-512 and AVX2, besides the baseline Highway always compiles: the SSE targets would only
// repeat the reference's two lanes. (Highway 1.0 sets HWY_TARGETS itself; a target is left out
// by disabling it.)
#ifndef HWY_DISABLED_TARGETS
#define HWY_DISABLED_TARGETS (HWY_SSSE3 | HWY_SSE4 | HWY_AVX3_DL)
#endif
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

HWY_BEFORE_NAMESPACE();
namespace getme {
namespace HWY_NAMESPACE {

// One vector register of doubles; never fewer than the reference's two.
constexpr int kTargetLanes = std::max<int>(2, HWY_MAX_BYTES / sizeof(double));

// flatten: the kernels are templates defined outside this target's region, so only by being
// inlined here are they compiled with its instruction set (and with no call passing a wide vector
// between differently compiled functions).
template <ElementType kType>
[[gnu::flatten]] void MeanRatioOfRange(const BlockRange& range, double* quality) {
  MeanRatioPass<kType, kTargetLanes>(range, quality);
}

template <ElementType kType>
[[gnu::flatten]] void WarpageOfRange(const BlockRange& range, double* warpage) {
  WarpagePass<kType, kTargetLanes>(range, warpage);
}

template <ElementType kType>
[[gnu::flatten]] void ScatterTransformOfRange(const BlockRange& range,
                                              const TransformPassSettings& settings) {
  ScatterTransformPass<kType, kTargetLanes>(range, settings);
}

// The list passes (a sequential pick's elements, a polish step's) take at most 4 lanes. Their
// lists are short and split by type (a tetrahedral node has about 24 elements, a hexahedral one
// 8, a mixed one runs of 1–4), so 8 lanes leave many empty, and the Hessian kernel's live values
// spill from 8-lane registers. Measured on this AVX-512 machine (docs/benchmarks.md, "Element
// lists …"): the whole engine 10–28 % faster on the shared meshes with the lists at 4 lanes,
// while the whole-mesh passes stay fastest at 8 (1M elements).
constexpr int kListLanes = std::min(kTargetLanes, 4);

template <ElementType kType>
[[gnu::flatten]] void MeanRatioOfList(const ElementList& list, double* quality) {
  MeanRatioListPass<kType, kListLanes>(list, quality);
}

template <ElementType kType>
[[gnu::flatten]] void CostAndQualityOfList(const ElementList& list, double* cost, double* quality) {
  CostAndQualityListPass<kType, kListLanes>(list, cost, quality);
}

template <ElementType kType>
[[gnu::flatten]] void HessianOfList(const ElementList& list, const int* node,
                                    InverseMeanRatioHessianOf<double>* derivatives) {
  HessianListPass<kType, kListLanes>(list, node, derivatives);
}

template <ElementType kType>
[[gnu::flatten]] void MeanRatioGradientOfList(const ElementList& list, MeanRatioAndGradient* out) {
  MeanRatioGradientListPass<kType, kListLanes>(list, out);
}

extern const ElementPasses kTargetPasses;
const ElementPasses kTargetPasses = {
    kTargetLanes,
    {&MeanRatioOfRange<ElementType::kTetrahedron>, &MeanRatioOfRange<ElementType::kHexahedron>,
     &MeanRatioOfRange<ElementType::kPyramid>, &MeanRatioOfRange<ElementType::kPrism>},
    {&WarpageOfRange<ElementType::kTetrahedron>, &WarpageOfRange<ElementType::kHexahedron>,
     &WarpageOfRange<ElementType::kPyramid>, &WarpageOfRange<ElementType::kPrism>},
    {&ScatterTransformOfRange<ElementType::kTetrahedron>,
     &ScatterTransformOfRange<ElementType::kHexahedron>,
     &ScatterTransformOfRange<ElementType::kPyramid>,
     &ScatterTransformOfRange<ElementType::kPrism>},
    {&MeanRatioOfList<ElementType::kTetrahedron>, &MeanRatioOfList<ElementType::kHexahedron>,
     &MeanRatioOfList<ElementType::kPyramid>, &MeanRatioOfList<ElementType::kPrism>},
    {&CostAndQualityOfList<ElementType::kTetrahedron>,
     &CostAndQualityOfList<ElementType::kHexahedron>, &CostAndQualityOfList<ElementType::kPyramid>,
     &CostAndQualityOfList<ElementType::kPrism>},
    {&HessianOfList<ElementType::kTetrahedron>, &HessianOfList<ElementType::kHexahedron>,
     &HessianOfList<ElementType::kPyramid>, &HessianOfList<ElementType::kPrism>},
    {&MeanRatioGradientOfList<ElementType::kTetrahedron>,
     &MeanRatioGradientOfList<ElementType::kHexahedron>,
     &MeanRatioGradientOfList<ElementType::kPyramid>,
     &MeanRatioGradientOfList<ElementType::kPrism>},
};

}  // namespace HWY_NAMESPACE
}  // namespace getme
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include "absl/strings/str_cat.h"
#include "getme/smoothing/wide_vector_support.h"

namespace getme {
namespace {

// The reference: compiled for the baseline, outside every Highway target.
const ElementPasses kReferencePasses = {
    kLanes,
    {&MeanRatioPass<ElementType::kTetrahedron, kLanes>,
     &MeanRatioPass<ElementType::kHexahedron, kLanes>,
     &MeanRatioPass<ElementType::kPyramid, kLanes>, &MeanRatioPass<ElementType::kPrism, kLanes>},
    {&WarpagePass<ElementType::kTetrahedron, kLanes>,
     &WarpagePass<ElementType::kHexahedron, kLanes>, &WarpagePass<ElementType::kPyramid, kLanes>,
     &WarpagePass<ElementType::kPrism, kLanes>},
    {&ScatterTransformPass<ElementType::kTetrahedron, kLanes>,
     &ScatterTransformPass<ElementType::kHexahedron, kLanes>,
     &ScatterTransformPass<ElementType::kPyramid, kLanes>,
     &ScatterTransformPass<ElementType::kPrism, kLanes>},
    {&MeanRatioListPass<ElementType::kTetrahedron, kLanes>,
     &MeanRatioListPass<ElementType::kHexahedron, kLanes>,
     &MeanRatioListPass<ElementType::kPyramid, kLanes>,
     &MeanRatioListPass<ElementType::kPrism, kLanes>},
    {&CostAndQualityListPass<ElementType::kTetrahedron, kLanes>,
     &CostAndQualityListPass<ElementType::kHexahedron, kLanes>,
     &CostAndQualityListPass<ElementType::kPyramid, kLanes>,
     &CostAndQualityListPass<ElementType::kPrism, kLanes>},
    {&HessianListPass<ElementType::kTetrahedron, kLanes>,
     &HessianListPass<ElementType::kHexahedron, kLanes>,
     &HessianListPass<ElementType::kPyramid, kLanes>,
     &HessianListPass<ElementType::kPrism, kLanes>},
    {&MeanRatioGradientListPass<ElementType::kTetrahedron, kLanes>,
     &MeanRatioGradientListPass<ElementType::kHexahedron, kLanes>,
     &MeanRatioGradientListPass<ElementType::kPyramid, kLanes>,
     &MeanRatioGradientListPass<ElementType::kPrism, kLanes>},
};

// Widest first.
std::vector<const ElementPasses*> RunnablePasses() {
  std::vector<const ElementPasses*> passes;
  [[maybe_unused]] const WideVectorSupport supported = DetectWideVectorSupport();
#if HWY_TARGETS & HWY_AVX3
  if (supported.avx512) passes.push_back(&N_AVX3::kTargetPasses);
#endif
#if HWY_TARGETS & HWY_AVX2
  if (supported.avx2) passes.push_back(&N_AVX2::kTargetPasses);
#endif
  passes.push_back(&kReferencePasses);
  return passes;
}

}  // namespace

absl::StatusOr<const ElementPasses*> ElementPassesFor(int lanes) {
  if (lanes != 0 && lanes != 2 && lanes != 4 && lanes != 8) {
    return absl::InvalidArgumentError(
        absl::StrCat("kernel lanes must be 0 (widest supported), 2, 4 or 8, not ", lanes));
  }
  static const std::vector<const ElementPasses*> runnable = RunnablePasses();
  for (const ElementPasses* passes : runnable) {
    if (lanes == 0 || passes->lanes == lanes) return passes;
  }
  return absl::FailedPreconditionError(
      absl::StrCat("kernel lanes ", lanes, ": this machine's CPU does not run ", lanes,
                   "-wide double vectors (", lanes == 8 ? "AVX-512" : "AVX2", ")"));
}

std::vector<int> SupportedLaneWidths() {
  std::vector<int> widths;
  for (int lanes : {2, 4, 8}) {
    if (ElementPassesFor(lanes).ok()) widths.push_back(lanes);
  }
  return widths;
}

}  // namespace getme
#endif  // HWY_ONCE
