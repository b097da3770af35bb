#include "getme/smoothing_context.h"

#include <algorithm>

#include "getme/block_loops.h"
#include "getme/vec3.h"

namespace getme {
namespace {

constexpr std::int64_t kReductionChunk = 8192;

}  // namespace

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

SmoothingContext::Summary SmoothingContext::Summarize() const {
  const auto count = static_cast<std::int64_t>(quality.size());
  const std::int64_t chunks = (count + kReductionChunk - 1) / kReductionChunk;
  std::vector<Summary> partial(chunks);
  std::vector<double> sums(chunks);
  pool.ParallelFor(chunks, 1, [&](std::int64_t first, std::int64_t last) {
    for (std::int64_t c = first; c < last; ++c) {
      const std::int64_t begin = c * kReductionChunk;
      const std::int64_t end = std::min(count, begin + kReductionChunk);
      Summary s{1.0, 0.0, 0};
      double sum = 0.0;
      for (std::int64_t i = begin; i < end; ++i) {
        const double q = std::max(0.0, quality[i]);
        s.q_min = std::min(s.q_min, q);
        sum += q;
        if (quality[i] < 0.0) ++s.invalid;
      }
      partial[c] = s;
      sums[c] = sum;
    }
  });
  Summary total{1.0, 0.0, 0};
  double sum = 0.0;
  for (std::int64_t c = 0; c < chunks; ++c) {
    total.q_min = std::min(total.q_min, partial[c].q_min);
    total.invalid += partial[c].invalid;
    sum += sums[c];
  }
  total.q_mean = count > 0 ? sum / static_cast<double>(count) : 0.0;
  return total;
}

double ElementQualityOrInvalid(const Mesh& mesh, ElementId element) {
  const NodeId* ids = mesh.element_nodes(element).data();
  return DispatchElementType(mesh.type(element), [&]<ElementType kType>() {
    return MeanRatioOrInvalid<kType>(GatherNodes<kType>(mesh, ids));
  });
}

}  // namespace getme
