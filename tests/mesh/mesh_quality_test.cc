// EvaluateMeshQuality and the per-element quality functions against an independent Eigen
// re-computation (reference_quality.h) on small mixed meshes with distorted and inverted elements.

#include "getme/mesh/mesh_quality.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "getme/mesh/mesh.h"
#include "getme/parallel/thread_pool.h"
#include "mesh_spec.h"
#include "reference_quality.h"

namespace getme::mesh_test {
namespace {

constexpr double kTolerance = 1e-12;

// Adds an element with its own nodes, so elements of any shape can sit side by side.
std::int64_t AddLooseElement(MeshSpec& spec, ElementType type, const Points& points,
                             const Eigen::Vector3d& shift) {
  std::vector<std::int64_t> ids;
  for (const Eigen::Vector3d& p : points) ids.push_back(spec.AddNode(p + shift));
  return spec.AddElement(type, ids);
}

const Points kUnitCube = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                          {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const Points kRegularTet = {{0, 0, 0},
                            {1, 0, 0},
                            {0.5, std::sqrt(3.0) / 2, 0},
                            {0.5, std::sqrt(3.0) / 6, std::sqrt(2.0 / 3)}};
const Points kRegularPyramid = {
    {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, std::sqrt(2.0) / 2}};
const Points kRegularPrism = {{0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0},
                              {0, 0, 1}, {1, 0, 1}, {0.5, std::sqrt(3.0) / 2, 1}};

Points Scaled(const Points& points, double factor) {
  Points scaled;
  for (const Eigen::Vector3d& p : points) scaled.push_back(p * factor);
  return scaled;
}

Points WithNode(Points points, int k, const Eigen::Vector3d& p) {
  points[k] = p;
  return points;
}

// One element of each kind of trouble; element 5 is inverted.
MeshSpec DistortedMixedMesh() {
  MeshSpec spec;
  const auto at = [](double i) { return Eigen::Vector3d(3.0 * i, 0, 0); };
  AddLooseElement(spec, ElementType::kHexahedron, kUnitCube, at(0));                  // 0
  AddLooseElement(spec, ElementType::kTetrahedron, Scaled(kRegularTet, 2.0), at(1));  // 1
  AddLooseElement(spec, ElementType::kHexahedron, WithNode(kUnitCube, 6, {1.3, 1.2, 1.4}),
                  at(2));  // 2
  AddLooseElement(spec, ElementType::kPyramid, WithNode(kRegularPyramid, 4, {0.3, 0.6, 0.5}),
                  at(3));  // 3
  AddLooseElement(spec, ElementType::kPrism, WithNode(kRegularPrism, 4, {1.1, 0.1, 1.5}),
                  at(4));  // 4
  Points inverted = kRegularTet;
  std::swap(inverted[1], inverted[2]);
  AddLooseElement(spec, ElementType::kTetrahedron, inverted, at(5));  // 5
  AddLooseElement(spec, ElementType::kTetrahedron,
                  {{0, 0, 0}, {1, 0, 0}, {0.2, 0.3, 0}, {0.3, 0.3, 0.2}}, at(6));  // 6
  AddLooseElement(spec, ElementType::kPyramid, kRegularPyramid, at(7));            // 7
  AddLooseElement(spec, ElementType::kPrism,
                  {{0, 0, 0},
                   {1.2, 0.1, 0},
                   {0.4, 0.7, 0.1},
                   {0.3, 0.2, 0.9},
                   {1.0, 0.1, 1.3},
                   {0.6, 0.9, 1.0}},
                  at(8));  // 8
  AddLooseElement(spec, ElementType::kHexahedron,
                  {{0, 0, 0},
                   {2, 0, 0},
                   {2, 1, 0},
                   {0, 1, 0},
                   {0, 0, 0.6},
                   {2, 0, 0.6},
                   {2, 1, 0.6},
                   {0, 1, 0.6}},
                  at(9));  // 9
  return spec;
}

struct Reference {
  std::vector<double> quality;  // 0 for invalid
  std::vector<bool> valid;
  std::vector<double> warpage;
};

Reference ComputeReference(const MeshSpec& spec) {
  Reference reference;
  for (std::size_t e = 0; e < spec.elements.size(); ++e) {
    const ElementType type = spec.elements[e].type;
    const Points points = spec.ElementPoints(static_cast<std::int64_t>(e));
    reference.valid.push_back(ReferenceIsValid(type, points));
    reference.quality.push_back(ReferenceMeanRatio(type, points));
    reference.warpage.push_back(ReferenceWarpage(type, points));
  }
  return reference;
}

std::vector<std::int64_t> ReferenceHistogram(const std::vector<double>& quality, int bins) {
  std::vector<std::int64_t> histogram(bins, 0);
  for (double q : quality) {
    // Quality 1 (and the reference's 1 + rounding) belongs to the last bin.
    ++histogram[std::min(bins - 1, static_cast<int>(std::floor(q * bins)))];
  }
  return histogram;
}

// The reference and the kernel may differ in the last bits; keep test qualities away from bin
// edges so that cannot move an element into the neighbouring bin.
void AssertQualitiesAwayFromBinEdges(const std::vector<double>& quality, int bins) {
  for (std::size_t e = 0; e < quality.size(); ++e) {
    const double q = quality[e];
    if (q == 0.0 || q > 1.0 - 1e-12) continue;
    const double scaled = q * bins;
    ASSERT_GT(std::abs(scaled - std::round(scaled)), 1e-9)
        << "element " << e << " has q = " << q << ", on a bin edge of " << bins << " bins";
  }
}

Mesh BuildOrDie(const MeshSpec& spec) {
  absl::StatusOr<Mesh> mesh = BuildMesh(spec);
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  return std::move(mesh).value();
}

class DistortedMixedMeshQuality : public ::testing::Test {
 protected:
  const MeshSpec spec_ = DistortedMixedMesh();
  const Reference reference_ = ComputeReference(spec_);
  const Mesh mesh_ = BuildOrDie(spec_);
  ThreadPool pool_{2};
};

TEST_F(DistortedMixedMeshQuality, FixtureHasTheIntendedShapes) {
  // Guards against a fixture that would make the tests below trivial.
  EXPECT_EQ(std::count(reference_.valid.begin(), reference_.valid.end(), false), 1);
  EXPECT_FALSE(reference_.valid[5]);
  EXPECT_EQ(reference_.quality[0], 1.0);
  for (int e : {2, 3, 4, 6, 8, 9}) {
    EXPECT_LT(reference_.quality[e], 0.95) << "element " << e;
    EXPECT_GT(reference_.quality[e], 0.05) << "element " << e;
  }
  EXPECT_GT(reference_.warpage[2], 0.01);
  EXPECT_GT(reference_.warpage[4], 0.01);
  EXPECT_GT(reference_.warpage[8], 0.01);
}

TEST_F(DistortedMixedMeshQuality, PerElementQualitiesWarpagesAndValidityMatchReference) {
  const std::vector<double> quality = ComputeElementQualities(mesh_, pool_);
  const std::vector<double> warpage = ComputeElementWarpages(mesh_, pool_);
  const std::vector<std::uint8_t> valid = ComputeElementValidity(mesh_, pool_);
  ASSERT_EQ(quality.size(), spec_.elements.size());
  ASSERT_EQ(warpage.size(), spec_.elements.size());
  ASSERT_EQ(valid.size(), spec_.elements.size());
  for (std::size_t e = 0; e < spec_.elements.size(); ++e) {
    EXPECT_NEAR(quality[e], std::min(1.0, reference_.quality[e]), kTolerance) << "element " << e;
    EXPECT_GE(quality[e], 0.0) << "element " << e;
    EXPECT_LE(quality[e], 1.0) << "element " << e;
    EXPECT_NEAR(warpage[e], reference_.warpage[e], kTolerance) << "element " << e;
    EXPECT_EQ(valid[e] != 0, reference_.valid[e]) << "element " << e;
  }
}

TEST_F(DistortedMixedMeshQuality, OnePassMeasuresMatchReferenceAndSummariseAsEvaluate) {
  const ElementMeasures measures = MeasureElements(mesh_, pool_);
  ASSERT_EQ(measures.quality.size(), spec_.elements.size());
  ASSERT_EQ(measures.warpage.size(), spec_.elements.size());
  ASSERT_EQ(measures.valid.size(), spec_.elements.size());
  for (std::size_t e = 0; e < spec_.elements.size(); ++e) {
    EXPECT_NEAR(measures.quality[e], std::min(1.0, reference_.quality[e]), kTolerance)
        << "element " << e;
    EXPECT_NEAR(measures.warpage[e], reference_.warpage[e], kTolerance) << "element " << e;
    EXPECT_EQ(measures.valid[e] != 0, reference_.valid[e]) << "element " << e;
  }
  const MeshQuality summarised = SummarizeMeasures(mesh_, measures, pool_);
  const MeshQuality evaluated = EvaluateMeshQuality(mesh_, pool_);
  EXPECT_EQ(summarised.q_min, evaluated.q_min);
  EXPECT_EQ(summarised.q_mean, evaluated.q_mean);
  EXPECT_EQ(summarised.invalid, 1);
  EXPECT_EQ(summarised.first_invalid, std::vector<ElementId>{5});
  EXPECT_EQ(summarised.warpage_max, evaluated.warpage_max);
  EXPECT_EQ(summarised.histogram, evaluated.histogram);
}

TEST_F(DistortedMixedMeshQuality, MeshMinimumAndMeanCountInvalidAsZero) {
  const MeshQuality result = EvaluateMeshQuality(mesh_, pool_);
  double sum = 0.0;
  for (double q : reference_.quality) sum += std::min(1.0, q);
  EXPECT_EQ(result.elements, 10);
  EXPECT_EQ(result.q_min, 0.0);  // the inverted element
  EXPECT_NEAR(result.q_mean, sum / 10.0, kTolerance);
  EXPECT_EQ(result.invalid, 1);
  EXPECT_EQ(result.first_invalid, (std::vector<ElementId>{5}));
}

TEST_F(DistortedMixedMeshQuality, PerTypeStatisticsMatchReference) {
  const MeshQuality result = EvaluateMeshQuality(mesh_, pool_);
  for (ElementType type : kAllElementTypes) {
    std::int64_t count = 0, invalid = 0;
    double minimum = 1.0, sum = 0.0;
    for (std::size_t e = 0; e < spec_.elements.size(); ++e) {
      if (spec_.elements[e].type != type) continue;
      ++count;
      const double q = std::min(1.0, reference_.quality[e]);
      minimum = std::min(minimum, q);
      sum += q;
      invalid += reference_.valid[e] ? 0 : 1;
    }
    const TypeQuality& stats = result.by_type[TypeIndex(type)];
    EXPECT_EQ(stats.count, count) << TypeName(type);
    EXPECT_NEAR(stats.q_min, minimum, kTolerance) << TypeName(type);
    EXPECT_NEAR(stats.q_mean, sum / static_cast<double>(count), kTolerance) << TypeName(type);
    EXPECT_EQ(stats.invalid, invalid) << TypeName(type);
  }
  EXPECT_EQ(result.by_type[TypeIndex(ElementType::kTetrahedron)].count, 3);
  EXPECT_EQ(result.by_type[TypeIndex(ElementType::kTetrahedron)].invalid, 1);
  EXPECT_EQ(result.by_type[TypeIndex(ElementType::kTetrahedron)].q_min, 0.0);
}

TEST_F(DistortedMixedMeshQuality, WarpageMaxAndMeanOverElementsWithQuadFaces) {
  const MeshQuality result = EvaluateMeshQuality(mesh_, pool_);
  double maximum = 0.0, sum = 0.0;
  int count = 0;
  for (std::size_t e = 0; e < spec_.elements.size(); ++e) {
    if (spec_.elements[e].type == ElementType::kTetrahedron) continue;
    maximum = std::max(maximum, reference_.warpage[e]);
    sum += reference_.warpage[e];
    ++count;
  }
  ASSERT_EQ(count, 7);
  EXPECT_NEAR(result.warpage_max, maximum, kTolerance);
  EXPECT_NEAR(result.warpage_mean, sum / count, kTolerance);
}

TEST_F(DistortedMixedMeshQuality, HistogramMatchesReferenceForSeveralBinCounts) {
  for (int bins : {1, 2, 7, 20, 64}) {
    AssertQualitiesAwayFromBinEdges(reference_.quality, bins);
    QualityOptions options;
    options.histogram_bins = bins;
    const MeshQuality result = EvaluateMeshQuality(mesh_, pool_, options);
    EXPECT_EQ(result.histogram, ReferenceHistogram(reference_.quality, bins)) << bins << " bins";
  }
}

TEST_F(DistortedMixedMeshQuality, DefaultHistogramHasTwentyBinsWithQualityOneInTheLast) {
  const MeshQuality result = EvaluateMeshQuality(mesh_, pool_);
  ASSERT_EQ(result.histogram.size(), 20u);
  EXPECT_EQ(result.histogram, ReferenceHistogram(reference_.quality, 20));
  // The unit cube (q = 1 exactly), the regular tetrahedron and the regular pyramid.
  EXPECT_EQ(result.histogram.back(), 3);
  EXPECT_EQ(result.histogram.front(), 1);  // the inverted element, counted as q = 0
}

TEST(MeshQualityInvalidList, ListsTheFirstInvalidIdsUpToTheLimit) {
  MeshSpec spec;
  Points inverted = kRegularTet;
  std::swap(inverted[0], inverted[3]);
  const std::vector<int> invalid_ids = {1, 3, 4, 8};
  for (int e = 0; e < 10; ++e) {
    const bool invalid = std::count(invalid_ids.begin(), invalid_ids.end(), e) != 0;
    AddLooseElement(spec, ElementType::kTetrahedron, invalid ? inverted : kRegularTet,
                    Eigen::Vector3d(2.0 * e, 0, 0));
  }
  const Mesh mesh = BuildOrDie(spec);
  ThreadPool pool(1);
  for (const auto& [limit, expected] : std::vector<std::pair<int, std::vector<ElementId>>>{
           {0, {}}, {1, {1}}, {2, {1, 3}}, {4, {1, 3, 4, 8}}, {100, {1, 3, 4, 8}}}) {
    QualityOptions options;
    options.max_listed_invalid = limit;
    const MeshQuality result = EvaluateMeshQuality(mesh, pool, options);
    EXPECT_EQ(result.first_invalid, expected) << "max_listed_invalid " << limit;
    EXPECT_EQ(result.invalid, 4) << "max_listed_invalid " << limit;
  }
  EXPECT_EQ(EvaluateMeshQuality(mesh, pool).first_invalid, (std::vector<ElementId>{1, 3, 4, 8}));
}

TEST(MeshQualityRegularBlock, AllUnitHexesHaveQualityOneInTheLastBinAndNoWarpage) {
  const Mesh mesh = BuildOrDie(HexBlock(3));
  ThreadPool pool(2);
  for (int bins : {1, 3, 20}) {
    QualityOptions options;
    options.histogram_bins = bins;
    const MeshQuality result = EvaluateMeshQuality(mesh, pool, options);
    std::vector<std::int64_t> expected(bins, 0);
    expected.back() = 27;
    EXPECT_EQ(result.histogram, expected) << bins << " bins";
    EXPECT_EQ(result.q_min, 1.0);
    EXPECT_EQ(result.q_mean, 1.0);
    EXPECT_EQ(result.invalid, 0);
    EXPECT_TRUE(result.first_invalid.empty());
    EXPECT_EQ(result.warpage_max, 0.0);
    EXPECT_EQ(result.warpage_mean, 0.0);
  }
  // Types without elements report count 0, q_min 1 and q_mean 0 (mesh_quality.h).
  const MeshQuality result = EvaluateMeshQuality(mesh, pool);
  for (ElementType type : {ElementType::kTetrahedron, ElementType::kPyramid, ElementType::kPrism}) {
    const TypeQuality& stats = result.by_type[TypeIndex(type)];
    EXPECT_EQ(stats.count, 0) << TypeName(type);
    EXPECT_EQ(stats.q_min, 1.0) << TypeName(type);
    EXPECT_EQ(stats.q_mean, 0.0) << TypeName(type);
    EXPECT_EQ(stats.invalid, 0) << TypeName(type);
  }
  EXPECT_EQ(result.by_type[TypeIndex(ElementType::kHexahedron)].count, 27);
}

// Jittered 21³ block: more elements than one reduction chunk (8192) and than one ParallelFor
// grain, with some elements inverted by the jitter.
MeshSpec JitteredBlock() {
  MeshSpec spec = HexBlock(21);
  std::mt19937 random(20240611);
  std::uniform_real_distribution<double> jitter(-0.35, 0.35);
  for (Eigen::Vector3d& p : spec.nodes)
    p += Eigen::Vector3d(jitter(random), jitter(random), jitter(random));
  return spec;
}

TEST(MeshQualityThreads, ResultIsIdenticalForAnyThreadCountAndMatchesReference) {
  const MeshSpec spec = JitteredBlock();
  const Reference reference = ComputeReference(spec);
  const Mesh mesh = BuildOrDie(spec);
  ThreadPool single(1);
  const MeshQuality expected = EvaluateMeshQuality(mesh, single);

  const auto invalid = std::count(reference.valid.begin(), reference.valid.end(), false);
  ASSERT_GT(invalid, 0) << "the jitter should invert some elements";
  double sum = 0.0, warpage_sum = 0.0;
  for (std::size_t e = 0; e < reference.quality.size(); ++e) {
    sum += reference.quality[e];
    warpage_sum += reference.warpage[e];
  }
  EXPECT_EQ(expected.invalid, invalid);
  EXPECT_EQ(expected.q_min, 0.0);
  EXPECT_NEAR(expected.q_mean, sum / static_cast<double>(reference.quality.size()), 1e-10);
  EXPECT_NEAR(expected.warpage_mean, warpage_sum / static_cast<double>(reference.quality.size()),
              1e-10);
  EXPECT_NEAR(expected.warpage_max,
              *std::max_element(reference.warpage.begin(), reference.warpage.end()), kTolerance);

  for (int threads : {2, 3, 8}) {
    ThreadPool pool(threads);
    const MeshQuality result = EvaluateMeshQuality(mesh, pool);
    EXPECT_EQ(result.q_min, expected.q_min) << threads << " threads";
    EXPECT_EQ(result.q_mean, expected.q_mean) << threads << " threads";
    EXPECT_EQ(result.invalid, expected.invalid) << threads << " threads";
    EXPECT_EQ(result.first_invalid, expected.first_invalid) << threads << " threads";
    EXPECT_EQ(result.warpage_max, expected.warpage_max) << threads << " threads";
    EXPECT_EQ(result.warpage_mean, expected.warpage_mean) << threads << " threads";
    EXPECT_EQ(result.histogram, expected.histogram) << threads << " threads";
    for (int t = 0; t < kElementTypeCount; ++t) {
      EXPECT_EQ(result.by_type[t].q_min, expected.by_type[t].q_min) << threads << " threads";
      EXPECT_EQ(result.by_type[t].q_mean, expected.by_type[t].q_mean) << threads << " threads";
    }
  }
}

}  // namespace
}  // namespace getme::mesh_test
