#pragma once

#include <chrono>
#include <cstdint>
#include <span>
#include <vector>

#include "getme/elements/element_quality.h"
#include "getme/elements/vec3.h"
#include "getme/mesh/mesh.h"
#include "getme/mesh/mesh_quality.h"
#include "getme/parallel/thread_pool.h"
#include "getme/smoothing/boundary_slide.h"
#include "getme/smoothing/element_passes_dispatch.h"
#include "getme/smoothing/progress.h"
#include "getme/smoothing/smoother.h"
#include "getme/smoothing/smoothing_params.h"

namespace getme {

// What every phase of one Smooth() call shares: the mesh, which nodes may move, the current
// per-element quality (kept up to date by each phase so the next one need not recompute it),
// progress reporting and cancellation.
struct SmoothingContext {
  // With `slide`, boundary nodes it says slide are movable too (boundary_slide.h), and with
  // keep_layers its columns' nodes move only as columns.
  SmoothingContext(Mesh& mesh_in, const SmoothingParams& params_in, ThreadPool& pool_in,
                   const ProgressCallback& progress_in, const CancellationToken* cancel_in,
                   const BoundarySlide* slide_in = nullptr);

  Mesh& mesh;
  const SmoothingParams& params;
  ThreadPool& pool;
  const ProgressCallback& progress;
  const CancellationToken* cancel;
  std::chrono::steady_clock::time_point start;
  const BoundarySlide* slide;
  // The whole-mesh element passes of params.kernel_lanes lanes (element_passes_dispatch.h); the
  // reference two lanes if this machine cannot run that width (Smooth() refuses such params
  // before it builds a context).
  const ElementPasses& passes;
  // 1 for nodes the smoothers may move: not caller-fixed, and not boundary if fix_boundary
  // unless it slides.
  std::vector<std::uint8_t> movable;
  // 1 for the boundary nodes that slide on the input's surface (a subset of movable).
  std::vector<std::uint8_t> sliding;
  // With keep_layers: 1 for the column nodes (kept_layers.h) the layer phase may move, as a
  // column (layer_phase.h): not fixed by the caller, and on a held boundary only if they slide.
  // Column nodes are never movable in the other phases.
  std::vector<std::uint8_t> column_movable;
  // Per element: mean ratio in [0, 1], or kInvalidQuality for an invalid element.
  std::vector<double> quality;

  double ElapsedSeconds() const;
  // Where a smoother that put `node` at `point` must put it: on its surface for a sliding node,
  // `point` itself for any other. Every phase passes each new position through this, with the
  // node's position before the move (`from`, where it belongs) to start the search from.
  Vec3 Placed(NodeId node, const Vec3& point, const Vec3& from) const {
    return sliding[node] ? slide->Project(node, point, &from) : point;
  }
  // Whether any node of the element is movable: elements without one keep their quality through
  // every phase.
  bool HasMovableNode(ElementId element) const {
    for (NodeId node : mesh.element_nodes(element)) {
      if (movable[node]) return true;
    }
    return false;
  }
  bool Cancelled() const { return cancel != nullptr && cancel->cancelled(); }
  void Report(const ProgressEvent& event) const {
    if (progress) progress(event);
  }
  // Recomputes `quality` for the whole mesh.
  void RefreshQuality();
  // Every element's warpage (Sec. 4.4), by element id, from the vector passes.
  std::vector<double> Warpages() const;
  // node_lists[i] = elements[i]'s node ids, for QualitiesOf.
  void NodeListsOf(std::span<const ElementId> elements,
                   std::vector<const NodeId*>& node_lists) const;
  // quality_out[i] = the mean ratio or kInvalidQuality of elements[i], whose node ids NodeListsOf
  // gave, computed passes.lanes elements at a time within each run of one type (the same bits as
  // ElementQualityOrInvalid).
  void QualitiesOf(std::span<const ElementId> elements, std::span<const NodeId* const> node_lists,
                   std::span<double> quality_out) const;
  // q_min and q_mean of `quality` with invalid elements as 0, and the invalid count.
  using Summary = QualitySummary;
  Summary Summarize() const { return SummarizeQualities(quality, mesh.canonical_order(), pool); }
  // Completes a phase: records the state it hands on and its duration in `summary`, and reports
  // the phase's final event.
  void FinishPhase(PhaseSummary& summary, const Summary& state, double phase_start) const;
};

// While it lives, the context's sliding boundary nodes are held like any boundary node: the
// phases run as on a held boundary. With a sliding boundary and the polish, GETMe's substeps and
// a first polish run under it, so sliding starts from exactly the held run's result
// (docs/boundary.md#when-nodes-slide).
class SlidingNodesHeld {
 public:
  explicit SlidingNodesHeld(SmoothingContext& context);
  ~SlidingNodesHeld();
  SlidingNodesHeld(const SlidingNodesHeld&) = delete;
  SlidingNodesHeld& operator=(const SlidingNodesHeld&) = delete;

 private:
  SmoothingContext& context_;
  std::vector<std::uint8_t> movable_;
  std::vector<std::uint8_t> sliding_;
};

// Mean ratio or kInvalidQuality of one element, dispatched on its type.
double ElementQualityOrInvalid(const Mesh& mesh, ElementId element);

}  // namespace getme
