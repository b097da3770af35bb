// The inverse-mean-ratio cost of core/getme/elements/mean_ratio_derivatives.h and its node
// gradient and Hessian: the cost against an independent evaluation of Def. 3 / eq. (10) from the
// paper's tables, the derivatives against central finite differences of the cost, and the
// properties a polish relies on (regular elements are minima, similarity invariance, the Def. 2
// barrier, convexity, descent). Last, the mean ratio's own gradient with respect to every node
// (core/getme/elements/mean_ratio_gradient.h, for the worst-cluster stage) against central
// differences of q.
//
// Derivatives are compared on their natural scale, c/d for the gradient and c/d² for the Hessian
// (c the cost, d the node's distance to the barrier, BarrierDistance), not relative to themselves:
// they may vanish. Finite-difference steps are a fixed fraction of d; the error model is below.

#include "getme/elements/mean_ratio_derivatives.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

#include "element_type_tags.h"
#include "getme/elements/element_quality.h"
#include "getme/elements/mean_ratio_gradient.h"
#include "paper_tables.h"
#include "random_elements.h"
#include "reference_kernels.h"
#include "regular_elements.h"

namespace getme::test {
namespace {

constexpr int kDerivativeTrials = 200;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

template <typename Tag>
class MeanRatioDerivativesTest : public ::testing::Test {};
TYPED_TEST_SUITE(MeanRatioDerivativesTest, AllElementTypes, ElementTypeName);

// 1/q_k for every node tetrahedron from the paper's transcribed tables, Eigen's W⁻¹ and
// determinant (no code shared with the kernel); +∞ for an invalid element.
double ReferenceInverseCost(ElementType type, const Points& p) {
  const PaperTables& paper = Paper(type);
  const Eigen::Matrix3d w_inverse = paper.target.inverse();
  double sum = 0.0;
  for (int k = 0; k < static_cast<int>(paper.node_tets.size()); ++k) {
    const Eigen::Matrix3d d = NodeTetEdges(type, p, k);
    if (!(d.determinant() > 0.0)) return kInfinity;
    const Eigen::Matrix3d s = d * w_inverse;
    sum += s.squaredNorm() / (3.0 * std::pow(s.determinant(), 2.0 / 3.0));
  }
  return sum / static_cast<double>(paper.node_tets.size());
}

// The relative condition number of the node tetrahedra's determinants: the largest
// |d0| |d1| |d2| / |det D| (Hadamard: ≥ 1). A determinant, and with it 1/q_k, is known to about
// ε times this, so the flatter an element the looser a comparison of two evaluations must be.
double DeterminantCondition(ElementType type, const Points& p) {
  double condition = 1.0;
  for (int k = 0; k < static_cast<int>(Paper(type).node_tets.size()); ++k) {
    const Eigen::Matrix3d d = NodeTetEdges(type, p, k);
    const double product = d.col(0).norm() * d.col(1).norm() * d.col(2).norm();
    condition = std::max(condition, product / std::abs(d.determinant()));
  }
  return condition;
}

// The distance from node `node` to the barrier: the smallest distance to the plane through the
// other three nodes of a node tetrahedron that contains it. Any move shorter than this keeps every
// such tetrahedron positively oriented, and the others do not depend on the node.
double BarrierDistance(ElementType type, const Points& p, int node) {
  double distance = kInfinity;
  for (const IndexTuple& tet : Paper(type).node_tets) {
    if (std::find(tet.begin(), tet.end(), node) == tet.end()) continue;
    Points others;
    for (int v : tet) {
      if (v != node) others.push_back(p[v]);
    }
    const Eigen::Vector3d normal = (others[1] - others[0]).cross(others[2] - others[0]);
    distance = std::min(distance, std::abs((p[node] - others[0]).dot(normal)) / normal.norm());
  }
  return distance;
}

// For the worst errors recorded as test properties (--gtest_output=xml).
std::string Scientific(double value) {
  std::ostringstream out;
  out << std::scientific << std::setprecision(2) << value;
  return out.str();
}

template <ElementType kType>
ElementNodes<kType> Moved(ElementNodes<kType> p, int node, const Vec3& delta) {
  p[node] += delta;
  return p;
}

// The gradient of f with respect to node `node` by central differences of step h.
template <ElementType kType, typename F>
Vec3 CentralDifferences(F f, const ElementNodes<kType>& p, int node, double h) {
  Vec3 difference;
  for (int j = 0; j < 3; ++j) {
    const Vec3 step = h * Vec3::Unit(j);
    difference[j] = (f(Moved<kType>(p, node, step)) - f(Moved<kType>(p, node, -step))) / (2.0 * h);
  }
  return difference;
}

// The regular element with every node displaced uniformly in [−amplitude, amplitude]³ (edges are
// 1), redrawn until valid: distorted elements of moderate quality, next to the paper's random
// elements in the unit cube (UnitRandom), many of which are nearly flat.
template <ElementType kType>
ElementNodes<kType> DistortedRegularElement(UnitRandom& random, double amplitude) {
  while (true) {
    ElementNodes<kType> p = RegularElement<kType>();
    for (Vec3& node : p) {
      const double x = random.Uniform(-amplitude, amplitude);
      const double y = random.Uniform(-amplitude, amplitude);
      const double z = random.Uniform(-amplitude, amplitude);
      node += Vec3(x, y, z);
    }
    if (IsValid<kType>(p)) return p;
  }
}

// Even trials: the paper's random elements; odd trials: distorted regular elements.
template <ElementType kType>
ElementNodes<kType> TrialElement(UnitRandom& random, int trial) {
  return trial % 2 == 0 ? random.ValidElementInUnitCube<kType>()
                        : DistortedRegularElement<kType>(random, 0.3);
}

// Error model of the finite differences, x = h/d the step over the barrier distance. Near the
// barrier one 1/q_k ∝ N (d − s)^(−2/3) dominates (N varies on the element's scale, which is at
// least d), so the n-th derivative along a direction is about a_n c/dⁿ with
// a_3 = (2/3)(5/3)(8/3) ≈ 3.0 and a_4 = a_3 · 11/3 ≈ 11. Truncation:
//   gradient from central differences of c:   x²/6 · a_3 ≈ 0.5 x²  on the scale c/d,
//   Hessian from central differences of ∇c:   x²/6 · a_4 ≈ 1.8 x²  on the scale c/d²,
//   Hessian from second differences of c (diagonal step 2h): (2x)²/12 · a_4 ≈ 3.7 x² on c/d².
// Rounding: c is known to a relative ε κ (κ = DeterminantCondition: the flattest node
// tetrahedron's determinant is the least accurate quantity) and ∇c to ε κ on its scale c/d, which
// the differences divide by x, x and x² respectively. Each tolerance is 10 × (truncation +
// rounding): the factor covers N's own variation, the √3 or 3 of a vector or matrix norm and the
// other node tetrahedra. Test properties record the largest error / tolerance seen.
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
constexpr double kModelMargin = 10.0;
// Two evaluations of the cost of the same shape (the reference, or the kernel on a similar image)
// round the determinants differently: they differ by a few ε κ, times coordinates / element size
// for an image (lemma1_invariance_test.cc). Seen: ≤ 3.3 ε κ and ≤ 12 ε κ over 5000 trials.
constexpr double kRoundingMargin = 100.0;
constexpr double kGradientStepFraction = 1e-4;          // x for the gradient and ∇c differences
constexpr double kSecondDifferenceStepFraction = 3e-4;  // x for second differences of c

double GradientTolerance(double condition) {
  constexpr double x = kGradientStepFraction;
  return kModelMargin * (0.5 * x * x + kEpsilon * condition / x);
}
double HessianFromGradientTolerance(double condition) {
  constexpr double x = kGradientStepFraction;
  return kModelMargin * (1.8 * x * x + kEpsilon * condition / x);
}
double HessianFromCostTolerance(double condition) {
  constexpr double x = kSecondDifferenceStepFraction;
  return kModelMargin * (3.7 * x * x + kEpsilon * condition / (x * x));
}

TYPED_TEST(MeanRatioDerivativesTest, GradientMatchesCentralDifferencesOfTheCost) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(1401 + TypeIndex(kType));
  double worst = 0.0;
  for (int trial = 0; trial < kDerivativeTrials; ++trial) {
    const ElementNodes<kType> p = TrialElement<kType>(random, trial);
    const double condition = DeterminantCondition(kType, ToPoints<kType>(p));
    for (int node = 0; node < NodeCount(kType); ++node) {
      const InverseMeanRatioGradientResult result = InverseMeanRatioGradient<kType>(p, node);
      const double cost = InverseMeanRatioCost<kType>(p);
      ASSERT_EQ(result.cost, cost);
      const double d = BarrierDistance(kType, ToPoints<kType>(p), node);
      const double h = kGradientStepFraction * d;
      const Vec3 difference = CentralDifferences<kType>(
          [](const ElementNodes<kType>& q) { return InverseMeanRatioCost<kType>(q); }, p, node, h);
      const double error = (difference - result.gradient).norm() / (cost / d);
      const double tolerance = GradientTolerance(condition);
      worst = std::max(worst, error / tolerance);
      EXPECT_LE(error, tolerance) << "trial " << trial << ", node " << node << ": analytic "
                                  << result.gradient.transpose() << ", differences "
                                  << difference.transpose() << ", cost " << cost << ", d " << d;
    }
  }
  ::testing::Test::RecordProperty("worst_error_over_tolerance", Scientific(worst));
}

TYPED_TEST(MeanRatioDerivativesTest, HessianMatchesCentralDifferences) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(1402 + TypeIndex(kType));
  double worst_from_gradient = 0.0;
  double worst_from_cost = 0.0;
  for (int trial = 0; trial < kDerivativeTrials; ++trial) {
    const ElementNodes<kType> p = TrialElement<kType>(random, trial);
    const double condition = DeterminantCondition(kType, ToPoints<kType>(p));
    for (int node = 0; node < NodeCount(kType); ++node) {
      const InverseMeanRatioHessianResult result = InverseMeanRatioHessian<kType>(p, node);
      const InverseMeanRatioGradientResult gradient_only = InverseMeanRatioGradient<kType>(p, node);
      ASSERT_EQ(result.cost, gradient_only.cost);
      ASSERT_EQ(result.gradient, gradient_only.gradient);
      const double cost = result.cost;
      const double d = BarrierDistance(kType, ToPoints<kType>(p), node);
      const double scale = cost / (d * d);

      const double h = kGradientStepFraction * d;
      Eigen::Matrix3d from_gradient;
      for (int j = 0; j < 3; ++j) {
        const Vec3 step = h * Vec3::Unit(j);
        from_gradient.col(j) =
            (InverseMeanRatioGradient<kType>(Moved<kType>(p, node, step), node).gradient -
             InverseMeanRatioGradient<kType>(Moved<kType>(p, node, -step), node).gradient) /
            (2.0 * h);
      }
      const double error_gradient = (from_gradient - result.hessian).norm() / scale;
      const double tolerance_gradient = HessianFromGradientTolerance(condition);
      worst_from_gradient = std::max(worst_from_gradient, error_gradient / tolerance_gradient);
      EXPECT_LE(error_gradient, tolerance_gradient)
          << "trial " << trial << ", node " << node << ": analytic\n"
          << result.hessian << "\ndifferences of the gradient\n"
          << from_gradient;

      const double h2 = kSecondDifferenceStepFraction * d;
      const auto cost_at = [&](const Vec3& delta) {
        return InverseMeanRatioCost<kType>(Moved<kType>(p, node, delta));
      };
      Eigen::Matrix3d from_cost;
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
          const Vec3 a = h2 * Vec3::Unit(i);
          const Vec3 b = h2 * Vec3::Unit(j);
          from_cost(i, j) =
              (cost_at(a + b) - cost_at(a - b) - cost_at(b - a) + cost_at(-a - b)) / (4 * h2 * h2);
        }
      }
      const double error_cost = (from_cost - result.hessian).norm() / scale;
      const double tolerance_cost = HessianFromCostTolerance(condition);
      worst_from_cost = std::max(worst_from_cost, error_cost / tolerance_cost);
      EXPECT_LE(error_cost, tolerance_cost)
          << "trial " << trial << ", node " << node << ": analytic\n"
          << result.hessian << "\nsecond differences of the cost\n"
          << from_cost;
    }
  }
  ::testing::Test::RecordProperty("worst_error_over_tolerance_from_gradient",
                                  Scientific(worst_from_gradient));
  ::testing::Test::RecordProperty("worst_error_over_tolerance_from_cost",
                                  Scientific(worst_from_cost));
}

// Symmetric (to rounding: the two outer-product terms are formed symmetrically) and positive
// semi-definite: each 1/q_k is convex in one node on the valid region (see the header), so a
// negative eigenvalue beyond rounding would be a wrong Hessian.
TYPED_TEST(MeanRatioDerivativesTest, HessianIsSymmetricAndPositiveSemiDefinite) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(1403 + TypeIndex(kType));
  for (int trial = 0; trial < kDerivativeTrials; ++trial) {
    const ElementNodes<kType> p = TrialElement<kType>(random, trial);
    for (int node = 0; node < NodeCount(kType); ++node) {
      const Eigen::Matrix3d h = InverseMeanRatioHessian<kType>(p, node).hessian;
      const double norm = h.norm();
      EXPECT_LE((h - h.transpose()).norm(), 1e-15 * norm) << "trial " << trial << "\n" << h;
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(h, Eigen::EigenvaluesOnly);
      EXPECT_GE(eigen.eigenvalues().minCoeff(), -1e-12 * norm)
          << "trial " << trial << ", node " << node << ": eigenvalues "
          << eigen.eigenvalues().transpose();
    }
  }
}

TYPED_TEST(MeanRatioDerivativesTest, CostIsTheMeanOfInverseTetrahedralMeanRatios) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(1404 + TypeIndex(kType));
  double worst = 0.0;
  for (int trial = 0; trial < kDerivativeTrials; ++trial) {
    const ElementNodes<kType> p = TrialElement<kType>(random, trial);
    const Points points = ToPoints<kType>(p);
    const double cost = InverseMeanRatioCost<kType>(p);
    const double expected = ReferenceInverseCost(kType, points);
    const double tolerance = kRoundingMargin * kEpsilon * DeterminantCondition(kType, points);
    worst = std::max(worst, std::abs(cost / expected - 1.0) / tolerance);
    EXPECT_NEAR(cost / expected, 1.0, tolerance) << "trial " << trial;
    // Every 1/q_k ≥ 1 (Def. 3: q_k ≤ 1), and the arithmetic mean of 1/q_k is at least the
    // reciprocal of their arithmetic mean q (eq. 10), with equality for one node tetrahedron.
    const double q = MeanRatioOrInvalid<kType>(p);
    EXPECT_GE(cost, 1.0) << "trial " << trial;
    if constexpr (kType == ElementType::kTetrahedron) {
      EXPECT_NEAR(cost * q, 1.0, tolerance) << "trial " << trial;
    } else {
      EXPECT_GE(cost * q, 1.0 - tolerance) << "trial " << trial;
    }
  }
  ::testing::Test::RecordProperty("worst_error_over_tolerance", Scientific(worst));
}

// The polish evaluates trial positions with CostAndQuality: its quality must be the very bits
// of MeanRatioOrInvalid (the polish writes it into the per-element qualities the result check
// compares against a fresh evaluation) and its cost those of InverseMeanRatioCost.
TYPED_TEST(MeanRatioDerivativesTest, CostAndQualityEqualTheSeparateFunctionsBitForBit) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(1407 + TypeIndex(kType));
  int invalid = 0;
  for (int trial = 0; trial < kDerivativeTrials; ++trial) {
    ElementNodes<kType> p = TrialElement<kType>(random, trial);
    // Every third element mirrored (x → −x): every node tetrahedron inverted.
    if (trial % 3 == 2) {
      for (Vec3& node : p) node.x() = -node.x();
    }
    const InverseMeanRatioCostAndQuality both = CostAndQuality<kType>(p);
    EXPECT_EQ(both.quality, MeanRatioOrInvalid<kType>(p)) << "trial " << trial;
    EXPECT_EQ(both.cost, InverseMeanRatioCost<kType>(p)) << "trial " << trial;
    invalid += both.quality == kInvalidQuality;
  }
  // Both branches ran: the mirrored elements are inverted (cost +∞, quality kInvalidQuality).
  EXPECT_GT(invalid, 0);
  EXPECT_LT(invalid, kDerivativeTrials);
}

// Each node tetrahedron of a regular element (unit edges) is the target W up to a rotation
// R_k (S_k = R_k), where 1/q_k takes its minimum 1: cost 1 and zero gradient at every node. There
// the header's Hessian reduces to (1/3)(2|b|² I + (2/3) u uᵗ) per node tetrahedron, u = R_k b with
// b the node's row of E W⁻¹: eigenvalues (2/3)|b|² (twice) and (8/9)|b|², trace (20/9)|b|². So
// the element's Hessian has trace (20/9) Σ|b|² / K and smallest eigenvalue ≥ (2/3) Σ|b|² / K,
// with b from the paper's W (Def. 3) here: a strict minimum along every move of every node.
TYPED_TEST(MeanRatioDerivativesTest, RegularElementIsAMinimumAtEveryNode) {
  constexpr ElementType kType = TypeParam::kType;
  const ElementNodes<kType> p = RegularElement<kType>();
  const PaperTables& paper = Paper(kType);
  const Eigen::Matrix3d w_inverse = paper.target.inverse();
  const double tets = static_cast<double>(paper.node_tets.size());
  EXPECT_NEAR(InverseMeanRatioCost<kType>(p), 1.0, 1e-14);
  for (int node = 0; node < NodeCount(kType); ++node) {
    double sum_b2 = 0.0;
    for (const IndexTuple& tet : paper.node_tets) {
      const auto found = std::find(tet.begin(), tet.end(), node);
      if (found == tet.end()) continue;
      const int m = static_cast<int>(found - tet.begin());
      // Row m of E W⁻¹: E's row 0 is (−1, −1, −1), row m > 0 the unit row e_m.
      const Eigen::RowVector3d b = m == 0 ? Eigen::RowVector3d(-w_inverse.colwise().sum())
                                          : Eigen::RowVector3d(w_inverse.row(m - 1));
      sum_b2 += b.squaredNorm();
    }
    const InverseMeanRatioHessianResult result = InverseMeanRatioHessian<kType>(p, node);
    EXPECT_NEAR(result.cost, 1.0, 1e-14) << "node " << node;
    EXPECT_LE(result.gradient.norm(), 1e-14) << "node " << node << ": " << result.gradient;
    EXPECT_NEAR(result.hessian.trace(), 20.0 / 9.0 * sum_b2 / tets, 1e-13) << "node " << node;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(result.hessian,
                                                               Eigen::EigenvaluesOnly);
    EXPECT_GE(eigen.eigenvalues().minCoeff(), 2.0 / 3.0 * sum_b2 / tets - 1e-13)
        << "node " << node << ": eigenvalues " << eigen.eigenvalues().transpose();
    EXPECT_GT(sum_b2, 0.0) << "node " << node;
  }
}

// Lemma 1's setting: x ↦ ζ R x + t. The cost is invariant; the gradient transforms as R ∇c / ζ
// and the Hessian as R H Rᵗ / ζ² (the chain rule for c(ζ R x + t) = c(x)). A similarity with
// small ζ and large t loses relative precision of the shape (coordinates / element size), which
// the tolerance carries, as in lemma1_invariance_test.cc, times the determinant condition.
TYPED_TEST(MeanRatioDerivativesTest, InvariantUnderTranslationRotationAndScaling) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(1405 + TypeIndex(kType));
  double worst = 0.0;
  for (int trial = 0; trial < kDerivativeTrials; ++trial) {
    const ElementNodes<kType> p = TrialElement<kType>(random, trial);
    const Points points = ToPoints<kType>(p);
    Similarity similarity = random.RandomSimilarity();
    // Pure translation, pure rotation and pure scaling first, then general similarities.
    if (trial % 4 == 0) similarity = {1.0, Eigen::Matrix3d::Identity(), similarity.translation};
    if (trial % 4 == 1) similarity = {1.0, similarity.rotation, Eigen::Vector3d::Zero()};
    if (trial % 4 == 2)
      similarity = {similarity.scale, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()};
    const ElementNodes<kType> image = ToNodes<kType>(similarity(points));
    double magnitude = 0.0;
    for (const Eigen::Vector3d& x : similarity(points)) magnitude = std::max(magnitude, x.norm());
    const double tolerance = kRoundingMargin * kEpsilon *
                             std::max(1.0, magnitude / similarity.scale) *
                             DeterminantCondition(kType, points);
    const double cost = InverseMeanRatioCost<kType>(p);
    const double cost_error = std::abs(InverseMeanRatioCost<kType>(image) / cost - 1.0);
    worst = std::max(worst, cost_error / tolerance);
    EXPECT_LE(cost_error, tolerance) << "trial " << trial << ", zeta " << similarity.scale;
    for (int node = 0; node < NodeCount(kType); ++node) {
      const InverseMeanRatioHessianResult before = InverseMeanRatioHessian<kType>(p, node);
      const InverseMeanRatioHessianResult after = InverseMeanRatioHessian<kType>(image, node);
      const double d = BarrierDistance(kType, points, node);
      const Eigen::Matrix3d& r = similarity.rotation;
      const double zeta = similarity.scale;
      const double gradient_error =
          (zeta * after.gradient - r * before.gradient).norm() / (cost / d);
      const double hessian_error =
          (zeta * zeta * after.hessian - r * before.hessian * r.transpose()).norm() /
          (cost / (d * d));
      worst = std::max(worst, std::max(gradient_error, hessian_error) / tolerance);
      EXPECT_LE(gradient_error, tolerance) << "trial " << trial << ", node " << node;
      EXPECT_LE(hessian_error, tolerance) << "trial " << trial << ", node " << node;
    }
  }
  ::testing::Test::RecordProperty("worst_error_over_tolerance", Scientific(worst));
}

// The polish takes a node's derivatives from its elements turned so that the node comes first
// (ElementTable::kSymmetryToFirst, element_passes.h). Each such turn must be a symmetry of the
// element's cost: the turned element's cost, gradient and Hessian at node 0 equal the element's at
// the node, to rounding (the same error model as the similarity test above), and validity is the
// same. A permutation that is not a rotation of the regular element changes the node tetrahedra
// and fails this. The pyramid has no such turns (its apex is not like its base nodes).
TYPED_TEST(MeanRatioDerivativesTest, TurningTheNodeFirstKeepsCostAndDerivatives) {
  constexpr ElementType kType = TypeParam::kType;
  if constexpr (!HasFirstNodeSymmetry<kType>) {
    static_assert(kType == ElementType::kPyramid);
    GTEST_SKIP() << "no rotation takes a pyramid's apex to a base node";
  } else {
    constexpr int kNodes = ElementTable<kType>::kNodes;
    UnitRandom random(2207 + TypeIndex(kType));
    for (int node = 0; node < kNodes; ++node) {
      const auto& symmetry = ElementTable<kType>::kSymmetryToFirst[node];
      EXPECT_EQ(symmetry[0], node);
      std::array<bool, kNodes> used{};
      for (int k : symmetry) used[k] = true;
      EXPECT_TRUE(std::all_of(used.begin(), used.end(), [](bool u) { return u; }))
          << "kSymmetryToFirst[" << node << "] is not a permutation";
    }
    int invalid = 0;
    for (int trial = 0; trial < kDerivativeTrials; ++trial) {
      // The trial elements, and half as many again from the unit cube: invalid ones among them.
      const ElementNodes<kType> p =
          trial % 3 == 2 ? random.ElementInUnitCube<kType>() : TrialElement<kType>(random, trial);
      const Points points = ToPoints<kType>(p);
      const double cost = InverseMeanRatioCost<kType>(p);
      for (int node = 0; node < kNodes; ++node) {
        SCOPED_TRACE(::testing::Message() << "trial " << trial << ", node " << node);
        ElementNodes<kType> turned;
        for (int k = 0; k < kNodes; ++k) {
          turned[k] = p[ElementTable<kType>::kSymmetryToFirst[node][k]];
        }
        const InverseMeanRatioHessianResult at_node = InverseMeanRatioHessian<kType>(p, node);
        const InverseMeanRatioHessianResult first = InverseMeanRatioHessian<kType>(turned, 0);
        if (!std::isfinite(cost)) {
          ++invalid;
          EXPECT_EQ(first.cost, kInfinity);
          continue;
        }
        double magnitude = 0.0;
        for (const Eigen::Vector3d& x : points) magnitude = std::max(magnitude, x.norm());
        const double tolerance = kRoundingMargin * kEpsilon * std::max(1.0, magnitude) *
                                 DeterminantCondition(kType, points);
        const double d = BarrierDistance(kType, points, node);
        EXPECT_LE(std::abs(first.cost / at_node.cost - 1.0), tolerance);
        EXPECT_LE((first.gradient - at_node.gradient).norm() / (cost / d), tolerance);
        EXPECT_LE((first.hessian - at_node.hessian).norm() / (cost / (d * d)), tolerance);
      }
    }
    EXPECT_GT(invalid, 0);
  }
}

// Def. 2 as a barrier: node t_0 of each node tetrahedron of a regular element moves straight
// toward the plane of the tetrahedron's other three nodes, its distance shrinking by 10 each time
// down to 1e-12. That 1/q_k grows like distance^(−2/3), so the cost rises monotonically past 1e6;
// the other node tetrahedra stay valid along the way (checked); one step past the plane, and the
// mirror image, are +∞ with zero derivatives.
TYPED_TEST(MeanRatioDerivativesTest, FlatteningANodeTetrahedronIsABarrier) {
  constexpr ElementType kType = TypeParam::kType;
  const ElementNodes<kType> regular = RegularElement<kType>();
  const Points points = ToPoints<kType>(regular);
  int paths = 0;
  for (const IndexTuple& tet : Paper(kType).node_tets) {
    const int node = tet[0];
    const Eigen::Vector3d a = points[tet[1]];
    const Eigen::Vector3d normal = (points[tet[2]] - a).cross(points[tet[3]] - a).normalized();
    const Eigen::Vector3d foot = points[node] - (points[node] - a).dot(normal) * normal;
    const auto at = [&](double fraction) {
      ElementNodes<kType> p = regular;
      p[node] = foot + fraction * (points[node] - foot);
      return p;
    };
    // Only paths along which the element stays valid until the plane is reached test the barrier
    // of this one tetrahedron; the regular element of every type has such paths (counted below).
    if (!IsValid<kType>(at(1e-12))) continue;
    ++paths;
    double previous = InverseMeanRatioCost<kType>(regular);
    for (double fraction = 0.1; fraction >= 1e-12; fraction /= 10.0) {
      const double cost = InverseMeanRatioCost<kType>(at(fraction));
      EXPECT_TRUE(std::isfinite(cost)) << "node " << node << ", fraction " << fraction;
      EXPECT_GT(cost, previous) << "node " << node << ", fraction " << fraction;
      previous = cost;
    }
    EXPECT_GT(previous, 1e6) << "node " << node;
    const InverseMeanRatioHessianResult past = InverseMeanRatioHessian<kType>(at(-1e-3), node);
    EXPECT_EQ(past.cost, kInfinity) << "node " << node;
    EXPECT_EQ(past.gradient, Vec3::Zero()) << "node " << node;
    EXPECT_EQ(past.hessian, Eigen::Matrix3d::Zero()) << "node " << node;
  }
  EXPECT_GE(paths, 1);
  ::testing::Test::RecordProperty("paths", paths);

  const ElementNodes<kType> mirrored = ToNodes<kType>(Mirrored(points));
  EXPECT_EQ(InverseMeanRatioCost<kType>(mirrored), kInfinity);
  for (int node = 0; node < NodeCount(kType); ++node) {
    const InverseMeanRatioHessianResult result = InverseMeanRatioHessian<kType>(mirrored, node);
    EXPECT_EQ(result.cost, kInfinity);
    EXPECT_EQ(result.gradient, Vec3::Zero());
    EXPECT_EQ(result.hessian, Eigen::Matrix3d::Zero());
  }
}

// A step of length t = 1e-5 d against the gradient lowers the cost by t |∇c| to first order.
// Whenever |∇c| ≥ 1e-3 c/d (not negligible on its natural scale) that is ≥ 1e-8 c, while the
// second-order remainder is about ½ t² · a_2 c/d² ≈ 5.6e-11 c (a_2 = (2/3)(5/3), as in the error
// model above), ≤ 0.6 %, and rounding ε κ c adds ≤ 0.2 % for κ ≤ 1e5 (the flattest of these
// elements): the observed decrease must match t |∇c| within 1 %.
TYPED_TEST(MeanRatioDerivativesTest, StepAgainstTheGradientLowersTheCost) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(1406 + TypeIndex(kType));
  int checked = 0;
  int total = 0;
  for (int trial = 0; trial < kDerivativeTrials; ++trial) {
    const ElementNodes<kType> p = TrialElement<kType>(random, trial);
    for (int node = 0; node < NodeCount(kType); ++node) {
      ++total;
      const InverseMeanRatioGradientResult result = InverseMeanRatioGradient<kType>(p, node);
      const double d = BarrierDistance(kType, ToPoints<kType>(p), node);
      const double slope = result.gradient.norm();
      if (slope < 1e-3 * result.cost / d) continue;
      ++checked;
      const double length = 1e-5 * d;
      const Vec3 step = -length * result.gradient / slope;
      const double lowered = InverseMeanRatioCost<kType>(Moved<kType>(p, node, step));
      EXPECT_LT(lowered, result.cost) << "trial " << trial << ", node " << node;
      EXPECT_NEAR((result.cost - lowered) / (length * slope), 1.0, 0.01)
          << "trial " << trial << ", node " << node;
    }
  }
  // Most nodes of distorted elements are far from their own optimum.
  EXPECT_GE(checked, total * 9 / 10) << checked << " of " << total;
  ::testing::Test::RecordProperty("checked", checked);
  ::testing::Test::RecordProperty("total", total);
}

// q's gradient on the scale 1/d (every q_k ≤ 1 and, near the barrier, q_k ∝ (d − s)^{2/3}, whose
// derivatives are smaller than 1/q_k's of the error model above: its a_3 is 0.3, not 3), so the
// gradient tolerance above holds with room.
TYPED_TEST(MeanRatioDerivativesTest, MeanRatioGradientMatchesCentralDifferencesOfQ) {
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(1411 + TypeIndex(kType));
  double worst = 0.0;
  for (int trial = 0; trial < kDerivativeTrials; ++trial) {
    const ElementNodes<kType> p = TrialElement<kType>(random, trial);
    const double condition = DeterminantCondition(kType, ToPoints<kType>(p));
    const MeanRatioGradientResult<kType> result = MeanRatioWithGradient<kType>(p);
    // The same q as Def. 3's kernel, up to the rounding of the division by K.
    EXPECT_NEAR(result.quality, MeanRatio<kType>(p), kRoundingMargin * kEpsilon * condition);
    for (int node = 0; node < NodeCount(kType); ++node) {
      const double d = BarrierDistance(kType, ToPoints<kType>(p), node);
      const double h = kGradientStepFraction * d;
      const Vec3 difference = CentralDifferences<kType>(
          [](const ElementNodes<kType>& q) { return MeanRatio<kType>(q); }, p, node, h);
      const double error = (difference - result.gradient[node]).norm() * d;
      const double tolerance = GradientTolerance(condition);
      worst = std::max(worst, error / tolerance);
      EXPECT_LE(error, tolerance) << "trial " << trial << ", node " << node << ": analytic "
                                  << result.gradient[node].transpose() << ", differences "
                                  << difference.transpose() << ", d " << d;
    }
  }
  ::testing::Test::RecordProperty("worst_error_over_tolerance", Scientific(worst));
}

TYPED_TEST(MeanRatioDerivativesTest, MeanRatioGradientOfRequestedNodesOnly) {
  // A node left out of `needed` gets zero; the requested ones get exactly the full result's bits
  // (their sums run over the same node tetrahedra in the same order). An invalid element has
  // kInvalidQuality and zero gradients.
  constexpr ElementType kType = TypeParam::kType;
  UnitRandom random(1412 + TypeIndex(kType));
  for (int trial = 0; trial < 20; ++trial) {
    const ElementNodes<kType> p = TrialElement<kType>(random, trial);
    const MeanRatioGradientResult<kType> full = MeanRatioWithGradient<kType>(p);
    for (int node = 0; node < NodeCount(kType); ++node) {
      const MeanRatioGradientResult<kType> one = MeanRatioWithGradient<kType>(p, 1u << node);
      EXPECT_EQ(one.quality, full.quality);
      for (int other = 0; other < NodeCount(kType); ++other) {
        if (other == node) {
          EXPECT_EQ(one.gradient[other], full.gradient[other]) << "node " << node;
        } else {
          EXPECT_EQ(one.gradient[other], Vec3::Zero()) << "node " << other;
        }
      }
    }
  }
  ElementNodes<kType> flat = RegularElement<kType>();
  for (Vec3& node : flat) node[2] = 0.0;
  const MeanRatioGradientResult<kType> invalid = MeanRatioWithGradient<kType>(flat);
  EXPECT_EQ(invalid.quality, kInvalidQuality);
  for (const Vec3& g : invalid.gradient) EXPECT_EQ(g, Vec3::Zero());
}

}  // namespace
}  // namespace getme::test
