#include "getme/smoothing/polish.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "getme/elements/element_quality.h"
#include "getme/elements/mean_ratio_derivatives.h"
#include "getme/elements/vec3.h"
#include "getme/mesh/node_colouring.h"
#include "getme/parallel/block_loops.h"

namespace getme {
namespace {

// Nodes per ParallelFor chunk within one colour: a node step costs a few dozen element
// evaluations, so this many amortise the scheduling.
constexpr std::int64_t kNodeGrain = 64;

int LocalIndex(std::span<const NodeId> nodes, NodeId node) {
  for (int k = 0; k < static_cast<int>(nodes.size()); ++k) {
    if (nodes[k] == node) return k;
  }
  return -1;
}

// Per-element cost, and the per-element trial values one node step writes before it is accepted.
// Nodes of one colour share no element, so their writes never meet: no allocation per node.
struct PolishState {
  std::vector<double> cost;
  std::vector<double> trial_cost;
  std::vector<double> trial_quality;
};

void ComputeElementCosts(const Mesh& mesh, ThreadPool& pool, std::vector<double>& cost) {
  cost.resize(mesh.element_count());
  ParallelForEachBlock(
      mesh, pool,
      [&]<ElementType kType>(const ElementBlock& block, std::int64_t begin, std::int64_t end) {
        constexpr int kNodes = ElementTable<kType>::kNodes;
        for (std::int64_t i = begin; i < end; ++i) {
          cost[block.elements[i]] = InverseMeanRatioCost<kType>(
              GatherNodes<kType>(mesh, block.nodes.data() + i * kNodes));
        }
      });
}

// Serial, in element id order: the same bits for any thread count, and cheap next to a sweep.
double MeanCost(const std::vector<double>& cost) {
  if (cost.empty()) return 0.0;
  double sum = 0.0;
  for (double c : cost) sum += c;
  return sum / static_cast<double>(cost.size());
}

// The summed cost, gradient and Hessian of `node`'s elements with respect to the node, in the
// fixed order of its node_elements row. False if an element is already past the barrier.
bool NodeDerivatives(const Mesh& mesh, NodeId node, double& cost, Vec3& gradient,
                     Eigen::Matrix3d& hessian) {
  cost = 0.0;
  gradient.setZero();
  hessian.setZero();
  for (ElementId e : mesh.node_elements(node)) {
    const std::span<const NodeId> ids = mesh.element_nodes(e);
    const int local = LocalIndex(ids, node);
    const bool finite = DispatchElementType(mesh.type(e), [&]<ElementType kType>() {
      const InverseMeanRatioHessianResult r =
          InverseMeanRatioHessian<kType>(GatherNodes<kType>(mesh, ids.data()), local);
      cost += r.cost;
      gradient += r.gradient;
      hessian += r.hessian;
      return std::isfinite(r.cost);
    });
    if (!finite) return false;
  }
  return true;
}

// Evaluates the node's elements at the node's current position into the trial arrays; returns
// false as soon as one is invalid (Def. 2) or past the cost barrier.
bool EvaluateTrial(const Mesh& mesh, NodeId node, PolishState& state, double& cost, double& q_min) {
  cost = 0.0;
  q_min = std::numeric_limits<double>::infinity();
  for (ElementId e : mesh.node_elements(node)) {
    const NodeId* ids = mesh.element_nodes(e).data();
    const bool ok = DispatchElementType(mesh.type(e), [&]<ElementType kType>() {
      const ElementNodes<kType> p = GatherNodes<kType>(mesh, ids);
      const double c = InverseMeanRatioCost<kType>(p);
      const double q = MeanRatioOrInvalid<kType>(p);
      if (!std::isfinite(c) || q == kInvalidQuality) return false;
      state.trial_cost[e] = c;
      state.trial_quality[e] = q;
      cost += c;
      q_min = std::min(q_min, q);
      return true;
    });
    if (!ok) return false;
  }
  return true;
}

// One damped Newton step of one node. Reads and writes only the node's coordinates and its
// elements' entries, so nodes of one colour may run concurrently. Returns whether it moved.
bool PolishNode(SmoothingContext& context, NodeId node, PolishState& state) {
  Mesh& mesh = context.mesh;
  const std::span<const ElementId> elements = mesh.node_elements(node);
  if (elements.empty()) return false;
  double old_cost = 0.0;
  Vec3 g;
  Eigen::Matrix3d h;
  if (!NodeDerivatives(mesh, node, old_cost, g, h)) return false;
  if (!g.allFinite() || g.squaredNorm() == 0.0) return false;

  // Newton direction from the summed 3×3 Hessian (positive semi-definite where the elements are
  // valid, mean_ratio_derivatives.h); where it is singular or the solve is no descent direction,
  // the Cauchy point along the steepest descent (exact minimiser of the quadratic model along −g).
  Vec3 d = Vec3::Zero();
  bool have_direction = false;
  const Eigen::LLT<Eigen::Matrix3d> llt(h);
  if (llt.info() == Eigen::Success) {
    d = llt.solve(-g);
    have_direction = d.allFinite() && g.dot(d) < 0.0;
  }
  if (!have_direction) {
    const double curvature = g.dot(h * g);
    if (!(curvature > 0.0) || !std::isfinite(curvature)) return false;
    d = -(g.squaredNorm() / curvature) * g;
    if (!d.allFinite()) return false;
  }

  double old_q_min = std::numeric_limits<double>::infinity();
  for (ElementId e : elements) old_q_min = std::min(old_q_min, context.quality[e]);

  auto x = mesh.x();
  auto y = mesh.y();
  auto z = mesh.z();
  const Vec3 start(x[node], y[node], z[node]);
  double alpha = 1.0;
  for (int attempt = 0; attempt <= context.params.polish_backtracking_steps; ++attempt) {
    const Vec3 trial = start + alpha * d;
    x[node] = trial[0];
    y[node] = trial[1];
    z[node] = trial[2];
    double cost = 0.0;
    double q_min = 0.0;
    // Accept only a strict cost decrease that keeps every element valid and the node's smallest
    // mean ratio: the mesh's q_min can then never fall (issue 14: "q_min of the result never
    // below q_min before the stage").
    if (EvaluateTrial(mesh, node, state, cost, q_min) && cost < old_cost && q_min >= old_q_min) {
      for (ElementId e : elements) {
        state.cost[e] = state.trial_cost[e];
        context.quality[e] = state.trial_quality[e];
      }
      return true;
    }
    alpha *= 0.5;
  }
  x[node] = start[0];
  y[node] = start[1];
  z[node] = start[2];
  return false;
}

}  // namespace

absl::StatusOr<PolishSummary> RunPolish(SmoothingContext& context) {
  const double phase_start = context.ElapsedSeconds();
  Mesh& mesh = context.mesh;
  const SmoothingParams& params = context.params;
  // Once per call, in a fixed order: the sets, and so the order of the node steps, depend on the
  // mesh and the free nodes only.
  const NodeColouring colouring = ColourNodes(mesh, context.movable);

  PolishState state;
  ComputeElementCosts(mesh, context.pool, state.cost);
  state.trial_cost.assign(mesh.element_count(), 0.0);
  state.trial_quality.assign(mesh.element_count(), 0.0);

  PolishSummary summary;
  summary.mean_cost_before = MeanCost(state.cost);
  double mean_cost = summary.mean_cost_before;
  // Accepted steps per chunk of a colour, summed after the ParallelFor: an integer, so any order
  // gives the same count, but the chunks' counters must not be shared.
  std::vector<std::int64_t> moved_per_chunk;
  bool cancelled = false;
  for (std::int64_t sweep = 1; sweep <= params.polish_max_sweeps && !cancelled; ++sweep) {
    for (int c = 0; c < colouring.colour_count(); ++c) {
      if (context.Cancelled()) {
        cancelled = true;
        break;
      }
      const std::span<const NodeId> nodes = colouring.Colour(c);
      const auto count = static_cast<std::int64_t>(nodes.size());
      moved_per_chunk.assign((count + kNodeGrain - 1) / kNodeGrain, 0);
      context.pool.ParallelFor(count, kNodeGrain, [&](std::int64_t begin, std::int64_t end) {
        std::int64_t moved = 0;
        for (std::int64_t i = begin; i < end; ++i) moved += PolishNode(context, nodes[i], state);
        moved_per_chunk[begin / kNodeGrain] += moved;
      });
      for (std::int64_t m : moved_per_chunk) summary.moved_nodes += m;
    }
    if (cancelled) break;
    summary.sweeps = sweep;
    const double previous = mean_cost;
    mean_cost = MeanCost(state.cost);
    if (!(previous - mean_cost >= params.polish_tolerance * previous)) break;
  }
  summary.mean_cost_after = MeanCost(state.cost);
  summary.seconds = context.ElapsedSeconds() - phase_start;
  if (cancelled) return absl::CancelledError("smoothing cancelled during the polish stage");
  return summary;
}

}  // namespace getme
