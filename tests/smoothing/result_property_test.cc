// Property (issue 7, "never a broken mesh"): over random hybrid meshes — some with inverted
// elements — and random parameter sets, Smooth() either fails with a user-facing status or
// returns a mesh that an independent recount finds valid, whose immovable nodes are bit-identical
// to the input and whose reported q_min / q_mean are those of the returned coordinates. It never
// fails with Internal (that would be ResultCheck catching an engine fault).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <random>

#include "getme/mesh/mesh_quality.h"
#include "getme/meshgen/hybrid_block.h"
#include "getme/parallel/thread_pool.h"
#include "getme/smoothing/smoother.h"
#include "reference_quality.h"
#include "smoothing_test_support.h"

namespace getme {
namespace {

constexpr int kCases = 40;

struct Case {
  int nx, ny, nz;
  double distortion;
  bool inverted_input;
  SmoothingParams params;
  std::vector<NodeId> caller_fixed;
};

Case RandomCase(std::mt19937_64& random, int index) {
  auto uniform = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(random);
  };
  auto pick = [&](int n) { return static_cast<int>(random() % n); };
  Case c;
  c.nx = 3 + pick(3);
  c.ny = 3 + pick(3);
  c.nz = 3 + pick(3);
  c.distortion = uniform(0.0, 0.45);
  c.inverted_input = index % 4 == 3;
  constexpr Method kMethods[] = {Method::kGetme,   Method::kSimultaneous, Method::kSequential,
                                 Method::kWarpage, Method::kSmartLaplace, Method::kLaplace};
  SmoothingParams& p = c.params;
  p.method = kMethods[pick(6)];
  p.threads = 1 + pick(2);
  p.fix_boundary = pick(2) == 0;
  p.untangle = pick(4) != 0;
  if (pick(3) == 0) p.UseLiteralPaperAlgorithm();
  for (ElementType type : kAllElementTypes) {
    const int t = TypeIndex(type);
    p.simultaneous_sigma_min[t] *= uniform(0.5, 1.5);
    p.simultaneous_sigma_max[t] = p.simultaneous_sigma_min[t] * uniform(1.0, 1.5);
    p.sequential_sigma[t] *= uniform(0.5, 1.5);
  }
  p.simultaneous_rho = uniform(0.05, 1.0);
  p.simultaneous_eta = uniform(0.0, 2.0);
  p.sequential_rho = uniform(0.001, 0.5);
  p.gamma = uniform(0.05, 1.0);
  p.simultaneous_max_iterations = 1 + pick(60);
  p.sequential_max_iterations = 1 + pick(3000);
  p.laplace_max_iterations = 1 + pick(30);
  return c;
}

// Mean ratio by the Eigen reference, invalid elements as 0 (docs/paper-notes.md#invalid-elements).
double ReferenceQuality(const Mesh& mesh, ElementId e, bool& valid) {
  mesh_test::Points points;
  for (NodeId n : mesh.element_nodes(e)) {
    points.emplace_back(mesh.x()[n], mesh.y()[n], mesh.z()[n]);
  }
  valid = mesh_test::ReferenceIsValid(mesh.type(e), points);
  return valid ? mesh_test::ReferenceMeanRatio(mesh.type(e), points) : 0.0;
}

TEST(ResultPropertyTest, EverySuccessIsValidKeepsFixedNodesAndReportsItsOwnQuality) {
  std::mt19937_64 random(20261121);
  int successes = 0;
  for (int index = 0; index < kCases; ++index) {
    Case c = RandomCase(random, index);
    const std::uint64_t seed = random();
    SCOPED_TRACE(::testing::Message()
                 << "case " << index << ": " << c.nx << "x" << c.ny << "x" << c.nz << " distortion "
                 << c.distortion << " seed " << seed << " method " << MethodName(c.params.method)
                 << " threads " << c.params.threads << " fix_boundary " << c.params.fix_boundary
                 << " untangle " << c.params.untangle << " inverted input " << c.inverted_input);
    auto built = meshgen::HybridBlock(c.nx, c.ny, c.nz, c.distortion, seed);
    ASSERT_TRUE(built.ok()) << built.status();
    Mesh& mesh = *built;
    for (NodeId n = static_cast<NodeId>(seed % 7); n < mesh.node_count(); n += 7 + index % 5) {
      mesh.set_fixed(n, true);
    }
    if (c.inverted_input) {
      // A free interior node pushed a cube length across its neighbours inverts elements.
      for (NodeId n = static_cast<NodeId>(mesh.node_count() / 2); n < mesh.node_count(); ++n) {
        if (!mesh.is_boundary(n) && !mesh.is_fixed(n)) {
          mesh.x()[n] += 1.2;
          break;
        }
      }
    }
    const std::vector<NodeId> immovable = testing::ImmovableNodes(mesh, c.params);
    const testing::CoordinateSnapshot before(mesh);
    // The engine takes its before-and-after measures with its vector passes: they must be the
    // bits of the one-element MeasureElements, quality, warpage and validity alike.
    ThreadPool pool(2);
    const MeshQuality input_quality = EvaluateMeshQuality(mesh, pool);

    auto result = Smooth(mesh, c.params);
    if (!result.ok()) {
      // Refusals a user can act on: an invalid input without untangling or beyond it, plain
      // Laplace inverting elements. Never an engine fault, never a bad parameter (all valid).
      EXPECT_EQ(result.status().code(), absl::StatusCode::kFailedPrecondition) << result.status();
      continue;
    }
    ++successes;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(result->before.q_min),
              std::bit_cast<std::uint64_t>(input_quality.q_min));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(result->before.q_mean),
              std::bit_cast<std::uint64_t>(input_quality.q_mean));
    EXPECT_EQ(result->before.invalid, input_quality.invalid);
    EXPECT_EQ(result->before.first_invalid, input_quality.first_invalid);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(result->before.warpage_max),
              std::bit_cast<std::uint64_t>(input_quality.warpage_max));
    EXPECT_EQ(std::bit_cast<std::uint64_t>(result->before.warpage_mean),
              std::bit_cast<std::uint64_t>(input_quality.warpage_mean));
    EXPECT_EQ(result->before.histogram, input_quality.histogram);
    const ElementMeasures measured = MeasureElements(mesh, pool);
    for (ElementId e = 0; e < mesh.element_count(); ++e) {
      ASSERT_EQ(std::bit_cast<std::uint64_t>(result->after_elements.quality[e]),
                std::bit_cast<std::uint64_t>(measured.quality[e]))
          << "element " << e;
      ASSERT_EQ(std::bit_cast<std::uint64_t>(result->after_elements.warpage[e]),
                std::bit_cast<std::uint64_t>(measured.warpage[e]))
          << "element " << e;
      ASSERT_EQ(result->after_elements.valid[e], measured.valid[e]) << "element " << e;
    }
    for (NodeId n : immovable) {
      ASSERT_EQ(std::bit_cast<std::uint64_t>(mesh.x()[n]),
                std::bit_cast<std::uint64_t>(before.x[n]));
      ASSERT_EQ(std::bit_cast<std::uint64_t>(mesh.y()[n]),
                std::bit_cast<std::uint64_t>(before.y[n]));
      ASSERT_EQ(std::bit_cast<std::uint64_t>(mesh.z()[n]),
                std::bit_cast<std::uint64_t>(before.z[n]));
    }
    double q_min = 1.0, q_sum = 0.0;
    std::int64_t invalid = 0;
    // The per-element measures handed to the CLI's writer are the result's own, element by
    // element.
    ASSERT_EQ(result->after_elements.quality.size(),
              static_cast<std::size_t>(mesh.element_count()));
    ASSERT_EQ(result->after_elements.valid.size(), static_cast<std::size_t>(mesh.element_count()));
    for (ElementId e = 0; e < mesh.element_count(); ++e) {
      bool valid = false;
      const double q = ReferenceQuality(mesh, e, valid);
      EXPECT_NEAR(result->after_elements.quality[e], q, 1e-12) << "element " << e;
      EXPECT_EQ(result->after_elements.valid[e] != 0, valid) << "element " << e;
      invalid += valid ? 0 : 1;
      q_min = std::min(q_min, q);
      q_sum += q;
    }
    EXPECT_EQ(invalid, 0);
    EXPECT_EQ(result->after.invalid, 0);
    // The reference uses Eigen's inverse and pow, the engine closed forms and cbrt: equal to
    // rounding.
    EXPECT_NEAR(result->after.q_min, q_min, 1e-12);
    EXPECT_NEAR(result->after.q_mean, q_sum / static_cast<double>(mesh.element_count()), 1e-12);
  }
  RecordProperty("successes", successes);
  // The property must not hold vacuously: most cases smooth.
  EXPECT_GE(successes, kCases / 2);
}

}  // namespace
}  // namespace getme
