#include "getme/smoothing/smoothing_context.h"

#include <algorithm>
#include <utility>

#include "getme/elements/vec3.h"
#include "getme/mesh/type_runs.h"
#include "getme/parallel/block_loops.h"

namespace getme {
namespace {

const ElementPasses& PassesOrReference(int lanes) {
  const absl::StatusOr<const ElementPasses*> passes = ElementPassesFor(lanes);
  return passes.ok() ? **passes : **ElementPassesFor(kLanes);
}

}  // namespace

SmoothingContext::SmoothingContext(Mesh& mesh_in, const SmoothingParams& params_in,
                                   ThreadPool& pool_in, const ProgressCallback& progress_in,
                                   const CancellationToken* cancel_in,
                                   const BoundarySlide* slide_in)
    : mesh(mesh_in),
      params(params_in),
      pool(pool_in),
      progress(progress_in),
      cancel(cancel_in),
      start(std::chrono::steady_clock::now()),
      slide(slide_in),
      passes(PassesOrReference(params_in.kernel_lanes)) {
  movable.resize(mesh.node_count());
  sliding.assign(mesh.node_count(), 0);
  column_movable.assign(mesh.node_count(), 0);
  // Kept layers: every column node, its wall node included, moves only with its column.
  std::vector<std::uint8_t> in_column(mesh.node_count(), 0);
  if (params.keep_layers && slide != nullptr && slide->kept_layers() != nullptr) {
    const KeptLayers& layers = *slide->kept_layers();
    for (NodeId node : layers.wall) in_column[node] = 1;
    for (NodeId node : layers.nodes) in_column[node] = 1;
  }
  for (std::int64_t i = 0; i < mesh.node_count(); ++i) {
    const auto node = static_cast<NodeId>(i);
    const bool held_boundary = params.fix_boundary && mesh.is_boundary(node);
    const bool may_move =
        !mesh.is_fixed(node) &&
        (!held_boundary || (params.slide_boundary && slide != nullptr && slide->Slides(node)));
    const bool slides = may_move && held_boundary;
    if (in_column[i]) {
      column_movable[i] = may_move ? 1 : 0;
      continue;
    }
    sliding[i] = slides ? 1 : 0;
    movable[i] = may_move ? 1 : 0;
  }
  RefreshQuality();
}

double SmoothingContext::ElapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

namespace {

// out[e] = the pass's number for every element e, block by block on the pool: passes.lanes
// elements at a time, with the same bits as one at a time (element_passes.h).
void RunWholeMeshPass(const Mesh& mesh, ThreadPool& pool, const WholeMeshPass& pass, double* out) {
  ParallelForEachBlock(
      mesh, pool,
      [&]<ElementType kType>(const ElementBlock& block, std::int64_t begin, std::int64_t end) {
        pass[TypeIndex(kType)](
            {mesh.x(), mesh.y(), mesh.z(), block.nodes.data(), block.elements.data(), begin, end},
            out);
      });
}

}  // namespace

void SmoothingContext::RefreshQuality() {
  quality.resize(mesh.element_count());
  RunWholeMeshPass(mesh, pool, passes.mean_ratio, quality.data());
}

std::vector<double> SmoothingContext::Warpages() const {
  std::vector<double> warpage(mesh.element_count());
  RunWholeMeshPass(mesh, pool, passes.warpage, warpage.data());
  return warpage;
}

void SmoothingContext::NodeListsOf(std::span<const ElementId> elements,
                                   std::vector<const NodeId*>& node_lists) const {
  node_lists.resize(elements.size());
  for (std::size_t i = 0; i < elements.size(); ++i) {
    node_lists[i] = mesh.element_nodes(elements[i]).data();
  }
}

void SmoothingContext::QualitiesOf(std::span<const ElementId> elements,
                                   std::span<const NodeId* const> node_lists,
                                   std::span<double> quality_out) const {
  ForEachTypeRun(mesh, elements, [&](ElementType type, std::int64_t begin, std::int64_t end) {
    passes.mean_ratio_list[TypeIndex(type)](
        {mesh.x(), mesh.y(), mesh.z(), node_lists.data() + begin, end - begin},
        quality_out.data() + begin);
  });
}

void SmoothingContext::FinishPhase(PhaseSummary& summary, const Summary& state,
                                   double phase_start) const {
  summary.q_min = state.q_min;
  summary.q_mean = state.q_mean;
  summary.seconds = ElapsedSeconds() - phase_start;
  Report({summary.phase, summary.iterations, state.q_min, state.q_mean, state.invalid, 0,
          ElapsedSeconds(), true});
}

SlidingNodesHeld::SlidingNodesHeld(SmoothingContext& context)
    : context_(context), movable_(context.movable), sliding_(context.sliding) {
  for (std::size_t node = 0; node < sliding_.size(); ++node) {
    if (sliding_[node]) context_.movable[node] = 0;
  }
  std::fill(context_.sliding.begin(), context_.sliding.end(), std::uint8_t{0});
}

SlidingNodesHeld::~SlidingNodesHeld() {
  context_.movable = std::move(movable_);
  context_.sliding = std::move(sliding_);
}

double ElementQualityOrInvalid(const Mesh& mesh, ElementId element) {
  const NodeId* ids = mesh.element_nodes(element).data();
  return DispatchElementType(mesh.type(element), [&]<ElementType kType>() {
    return MeanRatioOrInvalid<kType>(GatherNodes<kType>(mesh, ids));
  });
}

}  // namespace getme
