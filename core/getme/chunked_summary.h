#pragma once

// The deterministic q_min / q_mean reduction: fixed chunks of positions, each summed in order,
// chunk sums added in chunk order. Shared by SummarizeQualities and the simultaneous substep's
// fused quality pass, which must give bit-identical summaries.

#include <algorithm>
#include <cstdint>
#include <vector>

#include "getme/mesh_quality.h"
#include "getme/thread_pool.h"

namespace getme {

// Fixed chunk size of deterministic reductions: independent of the thread count.
inline constexpr std::int64_t kReductionChunk = 8192;

// q_min, Σq and the invalid count of one chunk, added to in order.
class QualityAccumulator {
 public:
  // raw: a mean ratio, or negative (kInvalidQuality) for an invalid element, counted as q = 0.
  void Add(double raw) {
    const double q = std::max(0.0, raw);
    sums_.q_min = std::min(sums_.q_min, q);
    sums_.q_mean += q;
    if (raw < 0.0) ++sums_.invalid;
  }
  const QualitySummary& sums() const { return sums_; }

 private:
  QualitySummary sums_{1.0, 0.0, 0};  // q_mean holds Σq
};

// Calls fill(begin, end, accumulator) for the chunks [c·kReductionChunk, (c+1)·kReductionChunk)
// of [0, count), in parallel; fill adds positions begin, begin+1, ..., end-1 in that order.
template <typename Fill>
QualitySummary SummarizeInChunks(std::int64_t count, ThreadPool& pool, Fill&& fill) {
  if (count == 0) return {};
  const std::int64_t chunks = (count + kReductionChunk - 1) / kReductionChunk;
  std::vector<QualitySummary> partial(chunks);
  pool.ParallelFor(chunks, 1, [&](std::int64_t first, std::int64_t last) {
    for (std::int64_t c = first; c < last; ++c) {
      QualityAccumulator chunk;
      fill(c * kReductionChunk, std::min(count, (c + 1) * kReductionChunk), chunk);
      partial[c] = chunk.sums();
    }
  });
  QualitySummary summary{1.0, 0.0, 0};
  for (const QualitySummary& chunk : partial) {
    summary.q_min = std::min(summary.q_min, chunk.q_min);
    summary.q_mean += chunk.q_mean;
    summary.invalid += chunk.invalid;
  }
  summary.q_mean /= static_cast<double>(count);
  return summary;
}

}  // namespace getme
