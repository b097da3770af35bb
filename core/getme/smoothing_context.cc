#include "getme/smoothing_context.h"

#include <algorithm>

#include "getme/block_loops.h"
#include "getme/chunked_summary.h"
#include "getme/vec3.h"

namespace getme {
SmoothingContext::SmoothingContext(Mesh& mesh_in, const SmoothingParams& params_in,
                                   ThreadPool& pool_in, const ProgressCallback& progress_in,
                                   const CancellationToken* cancel_in)
    : mesh(mesh_in),
      params(params_in),
      pool(pool_in),
      progress(progress_in),
      cancel(cancel_in),
      start(std::chrono::steady_clock::now()) {
  movable.resize(mesh.node_count());
  for (std::int64_t i = 0; i < mesh.node_count(); ++i) {
    const auto node = static_cast<NodeId>(i);
    movable[i] = !mesh.is_fixed(node) && !(params.fix_boundary && mesh.is_boundary(node)) ? 1 : 0;
  }
  RefreshQuality();
}

double SmoothingContext::ElapsedSeconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void SmoothingContext::RefreshQuality() {
  quality.resize(mesh.element_count());
  const Mesh& m = mesh;
  ParallelForEachBlock(
      m, pool,
      [&]<ElementType kType>(const ElementBlock& block, std::int64_t begin, std::int64_t end) {
        constexpr int kNodes = ElementTable<kType>::kNodes;
        for (std::int64_t i = begin; i < end; ++i) {
          quality[block.elements[i]] =
              MeanRatioOrInvalid<kType>(GatherNodes<kType>(m, block.nodes.data() + i * kNodes));
        }
      });
}

namespace {

// The qualities of block entries [begin, end), kLanes elements at a time (lanes.h), stored and
// added to the chunk's sums in entry order.
template <ElementType kType>
void RefreshBlockRange(const Mesh& mesh, const ElementBlock& block, std::int64_t begin,
                       std::int64_t end, std::vector<double>& quality, QualityAccumulator& chunk) {
  constexpr int kNodes = ElementTable<kType>::kNodes;
  for (std::int64_t i = begin; i < end; i += kLanes) {
    const int count = static_cast<int>(std::min<std::int64_t>(kLanes, end - i));
    const Lanes q = MeanRatioOrInvalid<kType, Lanes>(
        GatherLanes<kType>(mesh.x(), mesh.y(), mesh.z(), block.nodes.data() + i * kNodes, count));
    for (int l = 0; l < count; ++l) {
      quality[block.elements[i + l]] = q[l];
      chunk.Add(q[l]);
    }
  }
}

}  // namespace

SmoothingContext::Summary SmoothingContext::RefreshQualityAndSummarize() {
  quality.resize(mesh.element_count());
  // The chunks run over canonical positions, as Summarize's do, so each quality is added to its
  // chunk's sums in the same order and the summary has the same bits.
  auto refresh_chunk = [&](std::int64_t first, std::int64_t last, QualityAccumulator& chunk) {
    ForEachCanonicalRange(
        mesh, first, last,
        [&]<ElementType kType>(const ElementBlock& block, std::int64_t begin, std::int64_t end) {
          RefreshBlockRange<kType>(mesh, block, begin, end, quality, chunk);
        });
  };
  return SummarizeInChunks(mesh.element_count(), pool, refresh_chunk);
}

void SmoothingContext::FinishPhase(PhaseSummary& summary, const Summary& state,
                                   double phase_start) const {
  summary.q_min = state.q_min;
  summary.q_mean = state.q_mean;
  summary.seconds = ElapsedSeconds() - phase_start;
  Report({summary.phase, summary.iterations, state.q_min, state.q_mean, state.invalid, 0,
          ElapsedSeconds(), true});
}

double ElementQualityOrInvalid(const Mesh& mesh, ElementId element) {
  const NodeId* ids = mesh.element_nodes(element).data();
  return DispatchElementType(mesh.type(element), [&]<ElementType kType>() {
    return MeanRatioOrInvalid<kType>(GatherNodes<kType>(mesh, ids));
  });
}

}  // namespace getme
