#pragma once

// Run-time choice of the element passes' width (element_passes.h): 2 lanes (the reference, any
// x86-64), 4 (AVX2) or 8 (AVX-512), by what the machine that runs them supports. Google Highway
// detects the CPU's and the OS's support and compiles the wider passes in their own target
// namespaces with the target's instruction set (docs/design.md, "Wide kernels").

#include <array>
#include <cstdint>
#include <vector>

#include "absl/status/statusor.h"
#include "getme/elements/element_type.h"
#include "getme/smoothing/element_passes.h"

namespace getme {

// A pass over a block range that writes one number per element (by element id), per type.
using WholeMeshPass = std::array<void (*)(const BlockRange&, double* out), kElementTypeCount>;

struct ElementPasses {
  // The whole-mesh passes' width; the list passes take at most 4 (element_passes_dispatch.cc).
  int lanes = 0;
  // Indexed by TypeIndex.
  WholeMeshPass mean_ratio{};  // MeanRatioOrInvalid
  WholeMeshPass warpage{};     // Warpage (Sec. 4.4)
  std::array<void (*)(const BlockRange&, const TransformPassSettings&), kElementTypeCount>
      scatter_transform{};
  std::array<void (*)(const ElementList&, double* quality), kElementTypeCount> mean_ratio_list{};
  std::array<void (*)(const ElementList&, double* cost, double* quality), kElementTypeCount>
      cost_and_quality_list{};
  std::array<void (*)(const ElementList&, const int* node,
                      InverseMeanRatioHessianOf<double>* derivatives),
             kElementTypeCount>
      hessian_list{};
  std::array<void (*)(const ElementList&, MeanRatioAndGradient* out), kElementTypeCount>
      mean_ratio_gradient_list{};
};

// The passes of `lanes` lanes (2, 4 or 8), or with lanes = 0 the widest this machine runs.
// FailedPrecondition when this machine cannot run that width; InvalidArgument for any other
// number.
absl::StatusOr<const ElementPasses*> ElementPassesFor(int lanes);

// The widths this machine runs, narrowest first (always starts with 2).
std::vector<int> SupportedLaneWidths();

}  // namespace getme
