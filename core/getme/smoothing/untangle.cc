#include "getme/smoothing/untangle.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_format.h"
#include "absl/strings/str_join.h"
#include "getme/elements/element_quality.h"
#include "getme/elements/transform.h"
#include "getme/elements/vec3.h"
#include "getme/mesh/local_index.h"
#include "getme/mesh/node_colouring.h"
#include "getme/parallel/block_loops.h"

namespace getme {
namespace {

constexpr int kListedElements = 10;
// β_E = kBetaFraction · det W · L_E³: the determinant a node tetrahedron of element E would have
// if E were the regular element of its type (Def. 3's W) with edge length kBetaFraction^(1/3) L_E,
// L_E the element's mean edge length in the input. A positive target: reaching it leaves a margin
// above det = 0 that rounding cannot take away, while staying below the determinants of any
// reasonably shaped element, whose terms are then zero and which the untangler leaves alone.
//
// Measured (docs/untangling.md): a small β makes node-by-node descent crawl, since each step
// only halves the gap to β: 0.01 leaves one element of pave3 and one of hex_5_tangled inverted
// after 200 sweeps, 0.05 needs 28 sweeps on pave3 and 10 on hex_5_tangled, 0.3 needs 14 and 1.
// 0.3 also hands GETMe a better start: mixed-hex-pyr-tet ends at q_mean 0.780 (0.777 from 0.1,
// below Mesquite's 0.788 by more than the reference test's 0.01), pave3 at q_min 0.503.
constexpr double kBetaFraction = 0.3;
// Newton steps per node visit: on one active term the step halves β − det (the objective is a
// cube), so a handful turns a corner from inverted to valid.
constexpr int kNewtonSteps = 8;
constexpr int kBacktrackingSteps = 30;
// A step may move a node by at most this many times its local length (the mean L_E of its
// elements): a nearly degenerate opposite face gives a tiny det gradient and so a huge Newton
// step that lowers the objective but throws the node across the mesh.
constexpr double kMaxStepLengths = 0.5;
// A sweep counts as progress if it lowers the objective by this fraction, or the invalid count.
constexpr double kSweepTolerance = 1e-6;
// Nodes per ParallelFor chunk within one colour: smaller than polish.cc's, since most nodes of a
// colour are skipped (inactive) and the active ones cluster around the tangles.
constexpr std::int64_t kUntangleNodeGrain = 16;

template <ElementType kType>
constexpr double RegularDeterminant() {
  // det W for the unit-edge regular element: the inverse of W⁻¹'s (upper triangular) diagonal.
  constexpr auto& w = ElementTable<kType>::kTargetInverse;
  return 1.0 / (w[0][0] * w[1][1] * w[2][2]);
}

// det D(T_k) of node tetrahedron (t0, t1, t2, t3) is (p1 − p0)·((p2 − p0) × (p3 − p0)); with the
// other three nodes held it is affine in node t_m's position, with this gradient.
inline Vec3 DeterminantGradient(const Vec3& a, const Vec3& b, const Vec3& c, int m) {
  switch (m) {
    case 1:
      return b.cross(c);
    case 2:
      return c.cross(a);
    case 3:
      return a.cross(b);
    default:
      return -(b.cross(c) + c.cross(a) + a.cross(b));
  }
}

// The untangling objective of one element: Σ_k max(0, 1 − det D(T_k)/β_E)³ over its node
// tetrahedra (zero iff every det ≥ β_E; positive for every invalid element).
template <ElementType kType>
double ElementObjective(const ElementNodes<kType>& p, double beta) {
  double sum = 0.0;
  for (int k = 0; k < static_cast<int>(ElementTable<kType>::kNodeTets.size()); ++k) {
    const double hinge = 1.0 - NodeTetDeterminant<kType>(p, k) / beta;
    if (hinge > 0.0) sum += hinge * hinge * hinge;
    // A NaN determinant: no finite objective; the caller rejects the position.
    if (std::isnan(hinge)) return std::numeric_limits<double>::infinity();
  }
  return sum;
}

class Untangler {
 public:
  Untangler(SmoothingContext& context, std::vector<std::uint8_t> movable)
      : context_(context), mesh_(context.mesh), movable_(std::move(movable)) {}

  absl::StatusOr<PhaseSummary> Run();

 private:
  // The node's share of the objective (its elements' terms that depend on it), and with
  // kDerivatives its gradient and Hessian with respect to the node's position.
  template <bool kDerivatives>
  double NodeObjective(NodeId node, Vec3* gradient, Eigen::Matrix3d* hessian) const;
  // Up to kNewtonSteps damped Newton steps on one node. Reads the node's elements, writes only
  // the node's coordinates: nodes of one colour may run concurrently.
  void UntangleNode(NodeId node);
  // Objective of every element into objective_ (in parallel) and their sum in canonical order.
  double TotalObjective();
  std::vector<ElementId> InvalidElements() const;
  // FailedPrecondition if an invalid element has a non-positive corner whose four nodes may not
  // move: a proof that no untangling can succeed.
  absl::Status CheckPinnedCorners() const;
  absl::Status Stalled(const std::vector<ElementId>& invalid, std::int64_t sweeps) const;

  SmoothingContext& context_;
  Mesh& mesh_;
  const std::vector<std::uint8_t> movable_;
  std::vector<double> beta_;          // per element
  std::vector<double> node_length_;   // per node: the mean L_E of its elements (step cap)
  std::vector<double> objective_;     // per element, refreshed by TotalObjective
  std::vector<std::uint8_t> active_;  // per node: some element of it has a positive objective
};

template <bool kDerivatives>
double Untangler::NodeObjective(NodeId node, Vec3* gradient, Eigen::Matrix3d* hessian) const {
  double f = 0.0;
  if constexpr (kDerivatives) {
    gradient->setZero();
    hessian->setZero();
  }
  for (ElementId e : mesh_.node_elements(node)) {
    const std::span<const NodeId> ids = mesh_.element_nodes(e);
    const double inverse_beta = 1.0 / beta_[e];
    DispatchElementType(mesh_.type(e), [&]<ElementType kType>() {
      const int local = LocalIndex<kType>(ids.data(), node);
      const ElementNodes<kType> p = GatherNodes<kType>(mesh_, ids.data());
      for (const auto& t : ElementTable<kType>::kNodeTets) {
        int m = 0;
        while (m < 4 && t[m] != local) ++m;
        if (m == 4) continue;  // this corner does not depend on the node
        const Vec3 a = p[t[1]] - p[t[0]];
        const Vec3 b = p[t[2]] - p[t[0]];
        const Vec3 c = p[t[3]] - p[t[0]];
        const double hinge = 1.0 - a.dot(b.cross(c)) * inverse_beta;
        if (std::isnan(hinge)) {
          f = std::numeric_limits<double>::infinity();
          continue;
        }
        if (!(hinge > 0.0)) continue;
        f += hinge * hinge * hinge;
        if constexpr (kDerivatives) {
          // h = 1 − det/β is affine with ∇h = −∇det/β, so ∇h³ = 3h²∇h and ∇²h³ = 6h ∇h∇hᵗ:
          // positive semi-definite, and the sum over terms is the Hessian of a convex function.
          const Vec3 dh = -inverse_beta * DeterminantGradient(a, b, c, m);
          *gradient += (3.0 * hinge * hinge) * dh;
          *hessian += (6.0 * hinge) * dh * dh.transpose();
        }
      }
    });
  }
  return f;
}

void Untangler::UntangleNode(NodeId node) {
  auto x = mesh_.x();
  auto y = mesh_.y();
  auto z = mesh_.z();
  auto place = [&](const Vec3& p) {
    x[node] = p[0];
    y[node] = p[1];
    z[node] = p[2];
  };
  const double max_step = kMaxStepLengths * node_length_[node];
  for (int step = 0; step < kNewtonSteps; ++step) {
    Vec3 g;
    Eigen::Matrix3d h;
    const double f = NodeObjective<true>(node, &g, &h);
    if (!(f > 0.0) || !std::isfinite(f) || !g.allFinite() || g.squaredNorm() == 0.0) return;
    // The Hessian is only semi-definite (one active corner gives rank one); g lies in its range,
    // so a tiny ridge yields the minimum-norm Newton step, which moves the node only along the
    // gradients of the active determinants.
    const double ridge = 1e-12 * h.trace();
    const Eigen::LDLT<Eigen::Matrix3d> ldlt(h + ridge * Eigen::Matrix3d::Identity());
    Vec3 d = ldlt.solve(-g);
    if (ldlt.info() != Eigen::Success || !d.allFinite() || !(g.dot(d) < 0.0)) {
      d = -(f / g.squaredNorm()) * g;  // where the linear model of f reaches zero
    }
    const double length = d.norm();
    if (length > max_step) d *= max_step / length;

    const Vec3 start(x[node], y[node], z[node]);
    const double slope = g.dot(d);
    double alpha = 1.0;
    double f_new = f;
    bool accepted = false;
    for (int attempt = 0; attempt <= kBacktrackingSteps; ++attempt) {
      place(context_.Placed(node, start + alpha * d, start));
      f_new = NodeObjective<false>(node, nullptr, nullptr);
      if (f_new <= f + 1e-4 * alpha * slope) {  // Armijo
        accepted = true;
        break;
      }
      alpha *= 0.5;
    }
    if (!accepted) {
      place(start);
      return;
    }
    if (f_new == 0.0 || f - f_new < 1e-6 * f) return;
  }
}

double Untangler::TotalObjective() {
  const Mesh& mesh = mesh_;
  ParallelForEachBlock(
      mesh, context_.pool,
      [&]<ElementType kType>(const ElementBlock& block, std::int64_t begin, std::int64_t end) {
        constexpr int kNodes = ElementTable<kType>::kNodes;
        for (std::int64_t i = begin; i < end; ++i) {
          const ElementId e = block.elements[i];
          objective_[e] = ElementObjective<kType>(
              GatherNodes<kType>(mesh, block.nodes.data() + i * kNodes), beta_[e]);
        }
      });
  // Serial and in canonical order: the same bits for any thread count.
  double sum = 0.0;
  std::fill(active_.begin(), active_.end(), 0);
  for (ElementId e : mesh_.canonical_order()) {
    sum += objective_[e];
    if (objective_[e] > 0.0) {
      for (NodeId node : mesh_.element_nodes(e)) active_[node] = 1;
    }
  }
  return sum;
}

std::vector<ElementId> Untangler::InvalidElements() const {
  std::vector<ElementId> invalid;
  for (ElementId e = 0; e < mesh_.element_count(); ++e) {
    if (context_.quality[e] < 0.0) invalid.push_back(e);
  }
  return invalid;
}

absl::Status Untangler::CheckPinnedCorners() const {
  // Moving free nodes cannot change det D(T_k) of a corner whose four nodes are all immovable.
  std::vector<std::string> listed;
  std::int64_t pinned_elements = 0;
  bool boundary_involved = false;
  for (ElementId e : InvalidElements()) {
    const std::span<const NodeId> ids = mesh_.element_nodes(e);
    std::string corner;
    DispatchElementType(mesh_.type(e), [&]<ElementType kType>() {
      const ElementNodes<kType> p = GatherNodes<kType>(mesh_, ids.data());
      for (int k = 0; k < static_cast<int>(ElementTable<kType>::kNodeTets.size()); ++k) {
        const auto& t = ElementTable<kType>::kNodeTets[k];
        const double det = NodeTetDeterminant<kType>(p, k);
        if (det > 0.0) continue;
        bool pinned = true;
        for (int m = 0; m < 4; ++m) pinned &= movable_[ids[t[m]]] == 0;
        if (!pinned) continue;
        std::vector<std::string> nodes;
        for (int m = 0; m < 4; ++m) {
          const NodeId node = ids[t[m]];
          const bool fixed = mesh_.is_fixed(node);
          boundary_involved |= !fixed;
          nodes.push_back(absl::StrCat(node, fixed ? " fixed" : " boundary"));
        }
        corner = absl::StrFormat("element %d (%s), corner of node %d: det %.6g with nodes %s", e,
                                 TypeName(kType), ids[t[0]], det, absl::StrJoin(nodes, ", "));
        return;
      }
    });
    if (corner.empty()) continue;
    ++pinned_elements;
    if (static_cast<int>(listed.size()) < kListedElements) listed.push_back(std::move(corner));
  }
  if (pinned_elements == 0) return absl::OkStatus();
  return absl::FailedPreconditionError(absl::StrCat(
      "cannot untangle: ", pinned_elements, " invalid element",
      pinned_elements == 1 ? " has" : "s have",
      " a corner with det <= 0 whose node tetrahedron (the corner node and its three edge "
      "neighbours) has only immovable nodes, so no move of the free nodes can make ",
      pinned_elements == 1 ? "it" : "them", " valid: ", absl::StrJoin(listed, "; "),
      pinned_elements > kListedElements ? "; ..." : "",
      boundary_involved && !context_.params.untangle_free_boundary
          ? " (untangle_free_boundary lets boundary nodes that are not input-fixed move)"
          : ""));
}

absl::Status Untangler::Stalled(const std::vector<ElementId>& invalid, std::int64_t sweeps) const {
  std::vector<std::string> listed;
  for (std::size_t i = 0; i < invalid.size() && i < kListedElements; ++i) {
    listed.push_back(absl::StrCat(invalid[i], " (", TypeName(mesh_.type(invalid[i])), ")"));
  }
  return absl::FailedPreconditionError(absl::StrCat(
      "could not untangle ", invalid.size(), " invalid element", invalid.size() == 1 ? "" : "s",
      ": ", absl::StrJoin(listed, ", "), invalid.size() > kListedElements ? ", ..." : "",
      " (the untangling objective stopped decreasing after ", sweeps,
      " sweeps; every inverted corner has a free node, so this is no proof that it is "
      "impossible)"));
}

absl::StatusOr<PhaseSummary> Untangler::Run() {
  const double phase_start = context_.ElapsedSeconds();
  PhaseSummary summary{Phase::kUntangle, 0, 0.0, 0.0, 0.0, 0};
  if (absl::Status s = CheckPinnedCorners(); !s.ok()) return s;

  // β per element and the step cap per node, from the input once: the objective stays the same
  // function for the whole phase, so every accepted step lowers one and the same sum.
  beta_.resize(mesh_.element_count());
  for (ElementId e = 0; e < mesh_.element_count(); ++e) {
    const NodeId* ids = mesh_.element_nodes(e).data();
    beta_[e] = DispatchElementType(mesh_.type(e), [&]<ElementType kType>() {
      const double length = MeanEdgeLength<kType>(GatherNodes<kType>(mesh_, ids));
      return kBetaFraction * RegularDeterminant<kType>() * length * length * length;
    });
    // A collapsed element (all nodes at one point) has no scale of its own.
    if (!(beta_[e] > 0.0) || !std::isfinite(beta_[e])) beta_[e] = 0.0;
  }
  // Fallback scale for collapsed elements: the mean β of the others.
  double beta_sum = 0.0;
  std::int64_t beta_count = 0;
  for (ElementId e : mesh_.canonical_order()) {
    if (beta_[e] > 0.0) {
      beta_sum += beta_[e];
      ++beta_count;
    }
  }
  const double beta_fallback = beta_count > 0 ? beta_sum / static_cast<double>(beta_count) : 1.0;
  for (double& b : beta_) {
    if (!(b > 0.0)) b = beta_fallback;
  }
  node_length_.assign(mesh_.node_count(), 0.0);
  for (std::int64_t i = 0; i < mesh_.node_count(); ++i) {
    const auto node = static_cast<NodeId>(i);
    const std::span<const ElementId> elements = mesh_.node_elements(node);
    double sum = 0.0;
    for (ElementId e : elements) {
      const double regular = DispatchElementType(
          mesh_.type(e), [&]<ElementType kType>() { return RegularDeterminant<kType>(); });
      sum += std::cbrt(beta_[e] / (kBetaFraction * regular));
    }
    if (!elements.empty()) node_length_[i] = sum / static_cast<double>(elements.size());
  }
  objective_.assign(mesh_.element_count(), 0.0);
  active_.assign(mesh_.node_count(), 0);

  // Computed once, from the mesh and the movable nodes only: the sweep order, and so the result,
  // does not depend on the thread count.
  const NodeColouring colouring = ColourNodes(mesh_, movable_);
  std::vector<ElementId> invalid = InvalidElements();
  double objective = TotalObjective();
  std::int64_t sweep = 0;
  while (!invalid.empty() && sweep < context_.params.untangle_max_iterations) {
    if (context_.Cancelled()) return absl::CancelledError("smoothing cancelled while untangling");
    ++sweep;
    for (int c = 0; c < colouring.colour_count(); ++c) {
      const std::span<const NodeId> nodes = colouring.Colour(c);
      context_.pool.ParallelFor(static_cast<std::int64_t>(nodes.size()), kUntangleNodeGrain,
                                [&](std::int64_t begin, std::int64_t end) {
                                  for (std::int64_t i = begin; i < end; ++i) {
                                    // Nodes whose elements all had zero objective at the start
                                    // of the sweep have nothing to gain.
                                    if (active_[nodes[i]]) UntangleNode(nodes[i]);
                                  }
                                });
    }
    context_.RefreshQuality();
    const std::size_t invalid_before = invalid.size();
    invalid = InvalidElements();
    const double previous = objective;
    objective = TotalObjective();
    summary.iterations = sweep;
    const SmoothingContext::Summary state = context_.Summarize();
    context_.Report({Phase::kUntangle, sweep, state.q_min, state.q_mean, state.invalid, 0,
                     context_.ElapsedSeconds(), false});
    const bool progress =
        invalid.size() < invalid_before || previous - objective > kSweepTolerance * previous;
    if (!progress) break;
  }
  const SmoothingContext::Summary state = context_.Summarize();
  context_.FinishPhase(summary, state, phase_start);
  if (!invalid.empty()) return Stalled(invalid, summary.iterations);
  return summary;
}

}  // namespace

std::vector<std::uint8_t> UntangleMovable(const Mesh& mesh, const SmoothingParams& params,
                                          std::span<const std::uint8_t> movable,
                                          std::span<const double> quality) {
  std::vector<std::uint8_t> result(movable.begin(), movable.end());
  if (!params.untangle_free_boundary) return result;
  for (ElementId e = 0; e < mesh.element_count(); ++e) {
    if (!(quality[e] < 0.0)) continue;
    for (NodeId node : mesh.element_nodes(e)) {
      if (!mesh.is_fixed(node)) result[node] = 1;
    }
  }
  return result;
}

absl::StatusOr<PhaseSummary> RunUntangle(SmoothingContext& context) {
  return Untangler(context,
                   UntangleMovable(context.mesh, context.params, context.movable, context.quality))
      .Run();
}

}  // namespace getme
