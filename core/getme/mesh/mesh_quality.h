#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "getme/elements/element_type.h"
#include "getme/mesh/mesh.h"
#include "getme/parallel/thread_pool.h"

namespace getme {

struct TypeQuality {
  std::int64_t count = 0;
  double q_min = 1.0;  // over the type's elements; 1 when count == 0
  double q_mean = 0.0;
  std::int64_t invalid = 0;
};

// Mesh statistics of eq. (12) plus what a user of a mesh tool asks for. Invalid elements count as
// q = 0 in q_min and q_mean (docs/paper-notes.md#invalid-elements).
struct MeshQuality {
  std::int64_t elements = 0;
  double q_min = 0.0;
  double q_mean = 0.0;
  std::int64_t invalid = 0;
  std::vector<ElementId> first_invalid;  // ascending, at most QualityOptions::max_listed_invalid
  double warpage_max = 0.0;              // over elements with quad faces
  double warpage_mean = 0.0;             // mean element warpage over elements with quad faces
  std::array<TypeQuality, kElementTypeCount> by_type{};
  // histogram[i] counts elements with q in [i/bins, (i+1)/bins); q = 1 falls into the last bin.
  std::vector<std::int64_t> histogram;
};

struct QualityOptions {
  int histogram_bins = 20;
  int max_listed_invalid = 10;
};

// Per-element measures of one mesh state, indexed by global element id.
struct ElementMeasures {
  std::vector<double> quality;      // mean ratio (Def. 3), 0 for an invalid element
  std::vector<double> warpage;      // Sec. 4.4; 0 for tetrahedra
  std::vector<std::uint8_t> valid;  // Def. 2: 1 valid, 0 invalid
};
// All three in one pass: each element's nodes are gathered once, not once per measure.
ElementMeasures MeasureElements(const Mesh& mesh, ThreadPool& pool);
// The same from measures already taken, e.g. by the smoother's vector passes with the same bits:
// `mean_ratio_or_invalid[e]` is MeanRatioOrInvalid of element e (element_quality.h;
// kInvalidQuality where invalid) and `warpage[e]` its Warpage.
ElementMeasures MeasuresFrom(std::span<const double> mean_ratio_or_invalid,
                             std::vector<double> warpage);

// Per-element mean ratio (0 for invalid elements), indexed by global element id.
void ComputeElementQualities(const Mesh& mesh, ThreadPool& pool, std::vector<double>& quality);
std::vector<double> ComputeElementQualities(const Mesh& mesh, ThreadPool& pool);
// Per-element warpage (Sec. 4.4), indexed by global element id.
std::vector<double> ComputeElementWarpages(const Mesh& mesh, ThreadPool& pool);
// Per-element validity (Def. 2), indexed by global element id.
std::vector<std::uint8_t> ComputeElementValidity(const Mesh& mesh, ThreadPool& pool);

// MeasureElements, then SummarizeMeasures.
MeshQuality EvaluateMeshQuality(const Mesh& mesh, ThreadPool& pool,
                                const QualityOptions& options = {});
// The statistics of measures MeasureElements took of `mesh`.
MeshQuality SummarizeMeasures(const Mesh& mesh, const ElementMeasures& measures, ThreadPool& pool,
                              const QualityOptions& options = {});

// q_min / q_mean of given per-element qualities, where a negative entry (kInvalidQuality) is an
// invalid element counted as q = 0; the sum runs over fixed-size chunks in a fixed order so the
// result does not depend on the thread count.
struct QualitySummary {
  double q_min = 0.0;
  double q_mean = 0.0;
  std::int64_t invalid = 0;  // negative entries
};
QualitySummary SummarizeQualities(std::span<const double> quality, ThreadPool& pool);
// The same over quality[order[0]], quality[order[1]], ...: with Mesh::canonical_order() the sum
// does not depend on how elements of different types are interleaved.
QualitySummary SummarizeQualities(std::span<const double> quality, std::span<const ElementId> order,
                                  ThreadPool& pool);

}  // namespace getme
