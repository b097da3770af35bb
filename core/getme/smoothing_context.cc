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

SmoothingContext::Summary SmoothingContext::RefreshQualityAndSummarize() {
  quality.resize(mesh.element_count());
  const Mesh& m = mesh;
  // The chunks run over canonical positions, as Summarize's do, so each quality is added to its
  // chunk's sums in the same order and the summary has the same bits.
  return SummarizeInChunks(m.element_count(), pool,
                           [&](std::int64_t first, std::int64_t last, QualityAccumulator& chunk) {
                             ForEachCanonicalRange(
                                 m, first, last,
                                 [&]<ElementType kType>(const ElementBlock& block,
                                                        std::int64_t begin, std::int64_t end) {
                                   constexpr int kNodes = ElementTable<kType>::kNodes;
                                   for (std::int64_t i = begin; i < end; ++i) {
                                     const double q = MeanRatioOrInvalid<kType>(
                                         GatherNodes<kType>(m, block.nodes.data() + i * kNodes));
                                     quality[block.elements[i]] = q;
                                     chunk.Add(q);
                                   }
                                 });
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

double ElementQualityOrInvalid(const Mesh& mesh, ElementId element) {
  const NodeId* ids = mesh.element_nodes(element).data();
  return DispatchElementType(mesh.type(element), [&]<ElementType kType>() {
    return MeanRatioOrInvalid<kType>(GatherNodes<kType>(mesh, ids));
  });
}

}  // namespace getme
