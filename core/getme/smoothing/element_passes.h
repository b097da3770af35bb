#pragma once

// The two passes over every element that a simultaneous iteration (Sec. 3.1) spends its time in:
// the mean ratio of each element (Def. 3, eq. 10, with validity, Def. 2) and the regularizing
// step with its weight (Step 1: eqs. 4, 8, 11; Step 2.1: w_j = (1 − q_j)^η), which adds into
// Step 2's node sums. Each runs over a range of one type block's entries (the scatter over a
// tile, in the tiles' visiting order: parallel/element_tiles.h), kWidth elements per kernel call
// (lanes.h).
//
// They are templates over the width so that one source gives the reference two-lane pass
// (compiled for the baseline x86-64) and the 4- and 8-lane passes that
// element_passes_dispatch.cc compiles for AVX2 and AVX-512 and picks at run time. Each lane
// computes exactly what the double kernels compute for its element, so every width writes the
// same bits (tests/elements/element_passes_test.cc).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <type_traits>

#include "getme/elements/element_quality.h"
#include "getme/elements/lanes.h"
#include "getme/elements/mean_ratio_derivatives.h"
#include "getme/elements/mean_ratio_gradient.h"
#include "getme/elements/transform.h"
#include "getme/elements/vec3.h"

namespace getme {

// Entries [begin, end) of one type block (or of a reordered copy of its ids), with the mesh's
// coordinates.
struct BlockRange {
  std::span<const double> x, y, z;
  const NodeId* nodes = nullptr;        // the block's node ids, kNodes per entry
  const ElementId* elements = nullptr;  // the block's element ids
  std::int64_t begin = 0;
  std::int64_t end = 0;
};

// Step 2's running sums of one node: Σ_j w_j p'_{i,j} and Σ_j w_j.
struct NodeSum {
  double x = 0.0, y = 0.0, z = 0.0, w = 0.0;
};

// What Step 1 of the simultaneous substep needs besides the nodes, for one type.
struct TransformPassSettings {
  double sigma_min = 0.0;  // σ_j = sigma_min + sigma_span · (1 − q_j) (Step 1.1)
  double sigma_span = 0.0;
  double rho = 0.0;                 // relaxation ρ (eq. 11)
  double eta = 0.0;                 // weight exponent η (Step 2.1)
  const double* quality = nullptr;  // per element; an invalid element (−1) counts as q = 0
  NodeSum* sums = nullptr;          // per node: the contributions are added here
};

// w_j = (1 − q_j)^η (Step 2.1). The paper's η = 1/4 (and 1/2, 1) as square roots, which act on
// whole lanes and are correctly rounded; other exponents through libm's pow, lane by lane.
template <typename S>
GETME_LANE_INLINE S WeightOfElement(S defect, double eta) {
  if (eta == 0.25) return Sqrt(Sqrt(defect));
  if (eta == 0.5) return Sqrt(defect);
  if (eta == 1.0) return defect;
  if constexpr (std::is_same_v<S, double>) {
    return std::pow(defect, eta);
  } else {
    S weight;
    for (int l = 0; l < kLaneCount<S>; ++l) weight[l] = std::pow(defect[l], eta);
    return weight;
  }
}

// The per-element numbers of the whole-mesh passes below, over lanes.
struct MeanRatioMeasure {
  template <ElementType kType, typename S>
  GETME_LANE_INLINE static S Of(const LaneNodes<kType, S>& p) {
    return MeanRatioOrInvalid<kType, S>(p);
  }
};
struct WarpageMeasure {
  template <ElementType kType, typename S>
  GETME_LANE_INLINE static S Of(const LaneNodes<kType, S>& p) {
    return WarpageOf<kType, S>(p);
  }
};

// out[range.elements[i]] = Measure::Of entry i, kWidth entries at a time.
template <ElementType kType, int kWidth, typename Measure>
GETME_LANE_INLINE void PerElementPass(const BlockRange& range, double* out) {
  constexpr int kNodes = ElementTable<kType>::kNodes;
  for (std::int64_t i = range.begin; i < range.end; i += kWidth) {
    const int count = static_cast<int>(std::min<std::int64_t>(kWidth, range.end - i));
    const LanesOf<kWidth> value = Measure::template Of<kType, LanesOf<kWidth>>(
        GatherLanes<kType, kWidth>(range.x, range.y, range.z, range.nodes + i * kNodes, count));
    for (int l = 0; l < count; ++l) out[range.elements[i + l]] = value[l];
  }
}

// quality[element] = MeanRatioOrInvalid of every element of the range.
template <ElementType kType, int kWidth>
void MeanRatioPass(const BlockRange& range, double* quality) {
  PerElementPass<kType, kWidth, MeanRatioMeasure>(range, quality);
}

// warpage[element] = Warpage of every element of the range (element_quality.h): the measures a
// run reports before and after (smoother.cc), where the warpage of every hexahedron's six faces,
// one element at a time, cost more than the mean ratio.
template <ElementType kType, int kWidth>
void WarpagePass(const BlockRange& range, double* warpage) {
  PerElementPass<kType, kWidth, WarpageMeasure>(range, warpage);
}

// A list of elements of one type, anywhere in their block: the elements a sequential pick
// evaluates (Sec. 3.2, Step 3.1).
struct ElementList {
  std::span<const double> x, y, z;
  const NodeId* const* node_lists = nullptr;  // per element: its kNodes node ids
  std::int64_t count = 0;
};

// The nodes of the list's elements i, i + 1, … one per lane, kWidth of them: lanes past the list's
// end repeat its last element, and their results are dropped.
template <ElementType kType, int kWidth>
GETME_LANE_INLINE LaneNodes<kType, LanesOf<kWidth>> GatherListLanes(const ElementList& list,
                                                                    std::int64_t i) {
  const std::int64_t last = list.count - 1;
  const NodeId* lane_nodes[kWidth];
  for (int l = 0; l < kWidth; ++l) lane_nodes[l] = list.node_lists[std::min(i + l, last)];
  return GatherLanes<kType, kWidth>(list.x, list.y, list.z, lane_nodes);
}

// quality[i] = MeanRatioOrInvalid of the list's element i.
template <ElementType kType, int kWidth>
void MeanRatioListPass(const ElementList& list, double* quality) {
  for (std::int64_t i = 0; i < list.count; i += kWidth) {
    const int count = static_cast<int>(std::min<std::int64_t>(kWidth, list.count - i));
    const LanesOf<kWidth> q =
        MeanRatioOrInvalid<kType, LanesOf<kWidth>>(GatherListLanes<kType, kWidth>(list, i));
    for (int l = 0; l < count; ++l) quality[i + l] = q[l];
  }
}

// cost[i] and quality[i] = CostAndQuality of the list's element i (mean_ratio_derivatives.h):
// a polish trial's elements, around the node it moved.
template <ElementType kType, int kWidth>
void CostAndQualityListPass(const ElementList& list, double* cost, double* quality) {
  for (std::int64_t i = 0; i < list.count; i += kWidth) {
    const int count = static_cast<int>(std::min<std::int64_t>(kWidth, list.count - i));
    const InverseMeanRatioCostAndQualityOf<LanesOf<kWidth>> r =
        CostAndQuality<kType, LanesOf<kWidth>>(GatherListLanes<kType, kWidth>(list, i));
    for (int l = 0; l < count; ++l) {
      cost[i + l] = r.cost[l];
      quality[i + l] = r.quality[l];
    }
  }
}

// derivatives[i] = the cost, gradient and Hessian of the list's element i with respect to its
// local node node[i] (mean_ratio_derivatives.h): a polish step's elements, around its node. For
// a tetrahedron, hexahedron or prism, those of the element turned so that the node is its node 0
// (equal up to rounding); for a pyramid, InverseMeanRatioHessianLanes.
template <ElementType kType, int kWidth>
void HessianListPass(const ElementList& list, const int* node,
                     InverseMeanRatioHessianOf<double>* derivatives) {
  for (std::int64_t i = 0; i < list.count; i += kWidth) {
    const int count = static_cast<int>(std::min<std::int64_t>(kWidth, list.count - i));
    InverseMeanRatioHessianOf<LanesOf<kWidth>> r;
    if constexpr (HasFirstNodeSymmetry<kType>) {
      // Each element turned so that its node comes first (element_tables.h): every lane then
      // needs the same node tetrahedra's derivatives, and only those that hold node 0.
      constexpr int kNodes = ElementTable<kType>::kNodes;
      NodeId turned[kWidth][kNodes];
      const NodeId* lane_nodes[kWidth];
      for (int l = 0; l < kWidth; ++l) {
        const std::int64_t entry = i + std::min(l, count - 1);
        const auto& symmetry = ElementTable<kType>::kSymmetryToFirst[node[entry]];
        for (int k = 0; k < kNodes; ++k) turned[l][k] = list.node_lists[entry][symmetry[k]];
        lane_nodes[l] = turned[l];
      }
      r = InverseMeanRatioHessianAtFirstNode<kType, LanesOf<kWidth>>(
          GatherLanes<kType, kWidth>(list.x, list.y, list.z, lane_nodes));
    } else {
      LaneMaskOf<kWidth> lane_node{};
      for (int l = 0; l < kWidth; ++l) lane_node[l] = node[i + std::min(l, count - 1)];
      r = InverseMeanRatioHessianLanes<kType, LanesOf<kWidth>>(
          GatherListLanes<kType, kWidth>(list, i), lane_node);
    }
    for (int l = 0; l < count; ++l) {
      InverseMeanRatioHessianOf<double>& out = derivatives[i + l];
      out.cost = r.cost[l];
      out.gradient = {r.gradient.x[l], r.gradient.y[l], r.gradient.z[l]};
      for (int k = 0; k < 6; ++k) out.hessian[k] = r.hessian[k][l];
    }
  }
}

// One element's mean ratio and its gradient over the element's nodes (MeanRatioWithGradientOf,
// mean_ratio_gradient.h): the worst-cluster stage's term of an element.
struct MeanRatioAndGradient {
  double quality = kInvalidQuality;             // unclamped; kInvalidQuality if invalid
  std::array<Vec3, kMaxElementNodes> gradient;  // ∂q/∂p of node k, k < the element's node count
};

// out[i] = the mean ratio and gradient of the list's element i.
template <ElementType kType, int kWidth>
void MeanRatioGradientListPass(const ElementList& list, MeanRatioAndGradient* out) {
  for (std::int64_t i = 0; i < list.count; i += kWidth) {
    const int count = static_cast<int>(std::min<std::int64_t>(kWidth, list.count - i));
    const MeanRatioGradientOf<kType, LanesOf<kWidth>> r =
        MeanRatioWithGradientOf<kType, LanesOf<kWidth>>(GatherListLanes<kType, kWidth>(list, i));
    for (int l = 0; l < count; ++l) {
      MeanRatioAndGradient& element = out[i + l];
      element.quality = r.quality[l];
      for (int k = 0; k < ElementTable<kType>::kNodes; ++k) {
        element.gradient[k] = Vec3(r.gradient[k].x[l], r.gradient[k].y[l], r.gradient[k].z[l]);
      }
    }
  }
}

// Step 1 on the entries [range.begin, range.end) of one type block (or of a reordering of it,
// parallel/element_tiles.h): transform each element with its σ_j, scale and relax it, and add
// w_j·p'_{i,j} and w_j to the sums of its nodes (Step 2's numerators and denominators). The
// elements add in range order, each its nodes in node order, so a node's sums are the same bits
// for every width; the caller makes sure no other thread adds to these nodes meanwhile.
template <ElementType kType, int kWidth>
void ScatterTransformPass(const BlockRange& range, const TransformPassSettings& settings) {
  using S = LanesOf<kWidth>;
  constexpr int kNodes = ElementTable<kType>::kNodes;
  for (std::int64_t i = range.begin; i < range.end; i += kWidth) {
    const int count = static_cast<int>(std::min<std::int64_t>(kWidth, range.end - i));
    // Lanes past `count` repeat the last element; their results are dropped.
    S q{};
    for (int l = 0; l < kWidth; ++l) {
      q[l] = std::max(0.0, settings.quality[range.elements[i + std::min(l, count - 1)]]);
    }
    const NodeId* element_nodes = range.nodes + i * kNodes;
    const auto moved = RegularizingStep<kType, S>(
        GatherLanes<kType, kWidth>(range.x, range.y, range.z, element_nodes, count),
        settings.sigma_min + settings.sigma_span * (1.0 - q), settings.rho);
    const S weights = WeightOfElement(1.0 - q, settings.eta);
    std::array<Point3<S>, kNodes> weighted;
    for (int k = 0; k < kNodes; ++k) weighted[k] = weights * moved[k];
    for (int l = 0; l < count; ++l) {
      for (int k = 0; k < kNodes; ++k) {
        NodeSum& sum = settings.sums[element_nodes[l * kNodes + k]];
        sum.x += weighted[k].x[l];
        sum.y += weighted[k].y[l];
        sum.z += weighted[k].z[l];
        sum.w += weights[l];
      }
    }
  }
}

}  // namespace getme
