#include "getme/mesh/mesh_quality.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "getme/elements/element_quality.h"
#include "getme/elements/vec3.h"
#include "getme/parallel/block_loops.h"

namespace getme {
namespace {

// Fixed chunk size of deterministic reductions: independent of the thread count.
constexpr std::int64_t kReductionChunk = 8192;

// visit.template operator()<kType>(element, nodes) for every element, with its nodes gathered,
// block by block on the pool.
template <typename Visit>
void ForEachGatheredElement(const Mesh& mesh, ThreadPool& pool, Visit&& visit) {
  ParallelForEachBlock(
      mesh, pool,
      [&]<ElementType kType>(const ElementBlock& block, std::int64_t begin, std::int64_t end) {
        constexpr int kNodes = ElementTable<kType>::kNodes;
        for (std::int64_t i = begin; i < end; ++i) {
          const auto nodes = GatherNodes<kType>(mesh, block.nodes.data() + i * kNodes);
          visit.template operator()<kType>(block.elements[i], nodes);
        }
      });
}

template <typename Kernel>
void ComputePerElement(const Mesh& mesh, ThreadPool& pool, Kernel&& kernel, auto* out) {
  ForEachGatheredElement(mesh, pool,
                         [&]<ElementType kType>(ElementId e, const ElementNodes<kType>& nodes) {
                           out[e] = kernel.template operator()<kType>(nodes);
                         });
}

}  // namespace

void ComputeElementQualities(const Mesh& mesh, ThreadPool& pool, std::vector<double>& quality) {
  quality.resize(mesh.element_count());
  ComputePerElement(
      mesh, pool,
      []<ElementType kType>(const ElementNodes<kType>& nodes) { return MeanRatio<kType>(nodes); },
      quality.data());
}

std::vector<double> ComputeElementQualities(const Mesh& mesh, ThreadPool& pool) {
  std::vector<double> quality;
  ComputeElementQualities(mesh, pool, quality);
  return quality;
}

std::vector<double> ComputeElementWarpages(const Mesh& mesh, ThreadPool& pool) {
  std::vector<double> warpage(mesh.element_count());
  ComputePerElement(
      mesh, pool,
      []<ElementType kType>(const ElementNodes<kType>& nodes) { return Warpage<kType>(nodes); },
      warpage.data());
  return warpage;
}

namespace {

// Element e's quality (invalid counted as 0) and validity from its MeanRatioOrInvalid.
void SetQualityAndValidity(ElementMeasures& measures, std::size_t e, double mean_ratio_or_invalid) {
  measures.quality[e] = std::max(0.0, mean_ratio_or_invalid);
  measures.valid[e] = mean_ratio_or_invalid != kInvalidQuality ? 1 : 0;
}

}  // namespace

ElementMeasures MeasureElements(const Mesh& mesh, ThreadPool& pool) {
  ElementMeasures measures;
  const auto count = static_cast<std::size_t>(mesh.element_count());
  measures.quality.resize(count);
  measures.warpage.resize(count);
  measures.valid.resize(count);
  ForEachGatheredElement(mesh, pool,
                         [&]<ElementType kType>(ElementId e, const ElementNodes<kType>& nodes) {
                           // Validity from the same node tetrahedra as the mean ratio (the
                           // determinants IsValid takes, to the bit), so they are formed once.
                           SetQualityAndValidity(measures, e, MeanRatioOrInvalid<kType>(nodes));
                           measures.warpage[e] = Warpage<kType>(nodes);
                         });
  return measures;
}

ElementMeasures MeasuresFrom(std::span<const double> mean_ratio_or_invalid,
                             std::vector<double> warpage) {
  ElementMeasures measures;
  measures.quality.resize(mean_ratio_or_invalid.size());
  measures.valid.resize(mean_ratio_or_invalid.size());
  for (std::size_t e = 0; e < mean_ratio_or_invalid.size(); ++e) {
    SetQualityAndValidity(measures, e, mean_ratio_or_invalid[e]);
  }
  measures.warpage = std::move(warpage);
  return measures;
}

std::vector<std::uint8_t> ComputeElementValidity(const Mesh& mesh, ThreadPool& pool) {
  std::vector<std::uint8_t> valid(mesh.element_count());
  ComputePerElement(
      mesh, pool,
      []<ElementType kType>(const ElementNodes<kType>& nodes) {
        return static_cast<std::uint8_t>(IsValid<kType>(nodes) ? 1 : 0);
      },
      valid.data());
  return valid;
}

namespace {

// Reduces value(0), value(1), ... value(count - 1) in fixed chunks.
template <typename Value>
QualitySummary SummarizeChunked(std::int64_t count, Value&& value, ThreadPool& pool) {
  if (count == 0) return {};
  const std::int64_t chunks = (count + kReductionChunk - 1) / kReductionChunk;
  std::vector<QualitySummary> partial(chunks);  // q_mean holds the chunk's sum
  pool.ParallelFor(chunks, 1, [&](std::int64_t first, std::int64_t last) {
    for (std::int64_t c = first; c < last; ++c) {
      const std::int64_t end = std::min(count, (c + 1) * kReductionChunk);
      QualitySummary chunk{1.0, 0.0, 0};
      for (std::int64_t i = c * kReductionChunk; i < end; ++i) {
        const double raw = value(i);
        const double q = std::max(0.0, raw);
        chunk.q_min = std::min(chunk.q_min, q);
        chunk.q_mean += q;
        if (raw < 0.0) ++chunk.invalid;
      }
      partial[c] = chunk;
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

}  // namespace

QualitySummary SummarizeQualities(std::span<const double> quality, ThreadPool& pool) {
  return SummarizeChunked(
      static_cast<std::int64_t>(quality.size()), [&](std::int64_t i) { return quality[i]; }, pool);
}

QualitySummary SummarizeQualities(std::span<const double> quality, std::span<const ElementId> order,
                                  ThreadPool& pool) {
  return SummarizeChunked(
      static_cast<std::int64_t>(order.size()), [&](std::int64_t i) { return quality[order[i]]; },
      pool);
}

MeshQuality EvaluateMeshQuality(const Mesh& mesh, ThreadPool& pool, const QualityOptions& options) {
  return SummarizeMeasures(mesh, MeasureElements(mesh, pool), pool, options);
}

MeshQuality SummarizeMeasures(const Mesh& mesh, const ElementMeasures& measures, ThreadPool& pool,
                              const QualityOptions& options) {
  const std::vector<double>& quality = measures.quality;
  const std::vector<double>& warpage = measures.warpage;
  const std::vector<std::uint8_t>& valid = measures.valid;
  const QualitySummary summary = SummarizeQualities(quality, mesh.canonical_order(), pool);

  MeshQuality result;
  result.elements = mesh.element_count();
  result.q_min = summary.q_min;
  result.q_mean = summary.q_mean;
  const int bins = std::max(1, options.histogram_bins);
  result.histogram.assign(bins, 0);

  std::int64_t warped_elements = 0;
  double warpage_sum = 0.0;
  for (ElementType type : kAllElementTypes) {
    TypeQuality& stats = result.by_type[TypeIndex(type)];
    const ElementBlock& block = mesh.block(type);
    double sum = 0.0;
    for (ElementId e : block.elements) {
      ++stats.count;
      stats.q_min = std::min(stats.q_min, quality[e]);
      sum += quality[e];
      if (!valid[e]) ++stats.invalid;
      if (type != ElementType::kTetrahedron) {
        ++warped_elements;
        warpage_sum += warpage[e];
        result.warpage_max = std::max(result.warpage_max, warpage[e]);
      }
    }
    if (stats.count > 0) stats.q_mean = sum / static_cast<double>(stats.count);
    result.invalid += stats.invalid;
  }
  if (warped_elements > 0) result.warpage_mean = warpage_sum / static_cast<double>(warped_elements);
  for (std::int64_t e = 0; e < result.elements; ++e) {  // ids ascending: the caller's numbering
    if (!valid[e] && static_cast<int>(result.first_invalid.size()) < options.max_listed_invalid) {
      result.first_invalid.push_back(static_cast<ElementId>(e));
    }
    const int bin = std::min(bins - 1, static_cast<int>(std::floor(quality[e] * bins)));
    ++result.histogram[std::max(0, bin)];
  }
  return result;
}

}  // namespace getme
