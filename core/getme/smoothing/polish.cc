#include "getme/smoothing/polish.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "getme/elements/element_quality.h"
#include "getme/elements/mean_ratio_derivatives.h"
#include "getme/elements/vec3.h"
#include "getme/mesh/local_index.h"
#include "getme/mesh/node_colouring.h"
#include "getme/mesh/node_positions.h"
#include "getme/mesh/type_runs.h"
#include "getme/parallel/block_loops.h"
#include "getme/smoothing/whole_power.h"
#include "getme/smoothing/worst_cluster.h"

namespace getme {
namespace {

// Nodes per ParallelFor chunk within one colour: at most 64, which amortise the scheduling of
// node steps of a few dozen element evaluations each, but small enough for 8 chunks a thread,
// and at least 8 nodes. A colour of at most one chunk runs on the calling thread alone, and a
// colour of a few chunks splits unevenly: on meshes of about ten thousand elements most colours
// hold 100–800 nodes (tire.vtk: 249, 239, …, 28, 9), which chunks of 64 left to one or a few.
// The chunks change no result: nodes of one colour share no element.
std::int64_t PolishNodeGrain(std::int64_t nodes, int threads) {
  return std::clamp<std::int64_t>(nodes / (8 * std::int64_t{threads}), 8, 64);
}

// Share of the step to the floor that the next trial takes after a step below it (PolishNode).
constexpr double kFloorSafety = 0.9;

// Gains of successive sweeps that shrink by less than this factor count as shrinking by it in the
// stop rule's extrapolation, which stays finite (a ratio of 1 would predict endless gain).
constexpr double kMaxGainRatio = 0.95;

// The mean stage stops once the q_mean still to gain is below this share of 1 − q_mean (or below
// polish_tolerance, whichever is smaller).
constexpr double kDefectShare = 0.01;

// The per-element qualities one node step writes before it is accepted. Nodes of one colour share
// no element, so their writes never meet: no allocation per node.
struct PolishState {
  // Every stage starts by marking all nodes stale (RunStage).
  explicit PolishState(std::int64_t nodes) : stale(static_cast<std::size_t>(nodes)) {}

  // The stage's cost per element is c(E)^exponent (mean_ratio_derivatives.h for c): 1 for the
  // mean stage, larger for the worst-element stage, where it weights the worst elements most.
  double exponent = 1.0;
  // No accepted step leaves an element below this: the mesh's q_min when the mean stage began
  // (the worst-element stage has no floor: it hands on its best-q_min state instead).
  double q_floor = 0.0;
  // The mean stage's stop tolerance (RunPolish chooses it: polish_tolerance or
  // polish_final_tolerance); the worst-element stage has its own, relative to q_min.
  double mean_tolerance = 0.0;
  std::vector<double> trial_quality;
  // 1 while something in the node's elements moved since its last step was tried. A node whose
  // neighbourhood is unchanged would compute the same refused (or converged) step again, so
  // skipping it changes no bit of the result, only the time. Atomic because two nodes of one
  // colour may share a neighbour and both mark it; they only ever store 1, so the order of the
  // stores does not matter.
  std::vector<std::atomic<std::uint8_t>> stale;

  void MarkNeighbourhood(const Mesh& mesh, NodeId node) {
    for (ElementId e : mesh.node_elements(node)) {
      for (NodeId other : mesh.element_nodes(e)) stale[other].store(1, std::memory_order_relaxed);
    }
  }
};

enum class NodeStep { kSkipped, kConverged, kRefused, kMoved };

// Software prefetch for the node steps to come. A colour's nodes lie scattered over the mesh, so
// each step starts with cache misses on the node's element row, its elements' node lists and
// their coordinates: on cub_wedge_like.vtk the first read of an element's node list was an eighth
// of the whole run. Two steps ahead the row is fetched, one step ahead the node lists it names.
void PrefetchElementRow(const Mesh& mesh, NodeId node) {
  const std::span<const ElementId> row = mesh.node_elements(node);
  if (row.empty()) return;
  __builtin_prefetch(row.data());
  __builtin_prefetch(row.data() + row.size() - 1);
}

void PrefetchElementNodes(const Mesh& mesh, NodeId node) {
  for (ElementId e : mesh.node_elements(node)) __builtin_prefetch(mesh.element_nodes(e).data());
}

// Per element around the node being stepped, in its node_elements row's order: its node ids, the
// node's position in it, its derivatives at the step's start, and a trial's cost and quality.
struct NodeStepScratch {
  std::vector<const NodeId*> node_lists;
  std::vector<int> local;  // the node's position in the element
  std::vector<InverseMeanRatioHessianOf<double>> derivatives;
  std::vector<double> cost;
  std::vector<double> quality;

  void Fit(std::size_t elements) {
    if (node_lists.size() >= elements) return;
    node_lists.resize(elements);
    local.resize(elements);
    derivatives.resize(elements);
    cost.resize(elements);
    quality.resize(elements);
  }
};

// One per thread, grown to the largest valence seen: a node step allocates nothing.
NodeStepScratch& StepScratch() {
  thread_local NodeStepScratch scratch;
  return scratch;
}

// c^p. Whole exponents (the default 6) by repeated squaring: std::pow was a tenth of a polish's
// time, and c^(p−1), c^(p−2) for the derivatives come from the same products. Other exponents
// fall back to std::pow; 1 returns c itself, so the mean stage never depends on either.
struct Powers {
  double p;        // c^p
  double p_less1;  // c^(p−1)
  double p_less2;  // c^(p−2)
};

Powers PowersOf(double cost, double exponent) {
  const double whole = std::floor(exponent);
  if (whole == exponent && exponent >= 2.0) {
    const double p_less2 = WholePower(cost, static_cast<int>(exponent) - 2);
    const double p_less1 = p_less2 * cost;
    return {p_less1 * cost, p_less1, p_less2};
  }
  return {std::pow(cost, exponent), std::pow(cost, exponent - 1.0), std::pow(cost, exponent - 2.0)};
}

double Powered(double cost, double exponent) {
  return exponent == 1.0 ? cost : PowersOf(cost, exponent).p;
}

// The summed cost Σ c(E)^p, gradient and Hessian of `node`'s elements with respect to the node,
// in the fixed order of its node_elements row. With p ≠ 1 by the chain rule:
// ∇c^p = p c^{p−1} ∇c, ∇²c^p = p c^{p−1} ∇²c + p (p − 1) c^{p−2} ∇c ∇cᵀ (positive semi-definite
// where ∇²c is, for p ≥ 1). Fills `scratch` (one entry per element) for the trials. False if an
// element is already past the barrier.
bool NodeDerivatives(const SmoothingContext& context, NodeId node, double exponent, double& cost,
                     Vec3& gradient, Eigen::Matrix3d& hessian, NodeStepScratch& scratch) {
  const Mesh& mesh = context.mesh;
  const std::span<const ElementId> elements = mesh.node_elements(node);
  const auto count = static_cast<std::int64_t>(elements.size());
  for (std::int64_t i = 0; i < count; ++i) {
    const std::span<const NodeId> ids = mesh.element_nodes(elements[i]);
    scratch.node_lists[i] = ids.data();
    scratch.local[i] = DispatchElementType(mesh.type(elements[i]), [&]<ElementType kType>() {
      return LocalIndex<kType>(ids.data(), node);
    });
  }
  // Several elements side by side, each with the one-element bits; summed below in the row's
  // order.
  ForEachTypeRun(mesh, elements, [&](ElementType type, std::int64_t begin, std::int64_t end) {
    context.passes.hessian_list[TypeIndex(type)](
        {mesh.x(), mesh.y(), mesh.z(), scratch.node_lists.data() + begin, end - begin},
        scratch.local.data() + begin, scratch.derivatives.data() + begin);
  });
  cost = 0.0;
  gradient.setZero();
  hessian.setZero();
  for (std::int64_t i = 0; i < count; ++i) {
    if (!std::isfinite(scratch.derivatives[i].cost)) return false;
    const InverseMeanRatioHessianResult r = ToHessianResult(scratch.derivatives[i]);
    if (exponent == 1.0) {
      cost += r.cost;
      gradient += r.gradient;
      hessian += r.hessian;
    } else {
      const Powers powers = PowersOf(r.cost, exponent);
      const double first = exponent * powers.p_less1;
      const double second = exponent * (exponent - 1.0) * powers.p_less2;
      cost += powers.p;
      gradient += first * r.gradient;
      hessian += first * r.hessian + second * (r.gradient * r.gradient.transpose());
    }
  }
  return true;
}

// Evaluates the node's elements at the node's current position into the trial arrays; returns
// false as soon as one is invalid (Def. 2), i.e. past the cost barrier. Only the node has moved
// since NodeDerivatives filled `scratch`.
bool EvaluateTrial(const SmoothingContext& context, NodeId node, NodeStepScratch& scratch,
                   PolishState& state, double& cost, double& q_min) {
  const Mesh& mesh = context.mesh;
  const std::span<const ElementId> elements = mesh.node_elements(node);
  const auto count = static_cast<std::int64_t>(elements.size());
  // Several elements side by side, each with CostAndQuality's bits; summed below in the row's
  // order.
  ForEachTypeRun(mesh, elements, [&](ElementType type, std::int64_t begin, std::int64_t end) {
    context.passes.cost_and_quality_list[TypeIndex(type)](
        {mesh.x(), mesh.y(), mesh.z(), scratch.node_lists.data() + begin, end - begin},
        scratch.cost.data() + begin, scratch.quality.data() + begin);
  });
  cost = 0.0;
  q_min = std::numeric_limits<double>::infinity();
  for (std::int64_t i = 0; i < count; ++i) {
    const double quality = scratch.quality[i];
    if (quality == kInvalidQuality) return false;
    state.trial_quality[elements[i]] = quality;
    cost += Powered(scratch.cost[i], state.exponent);
    q_min = std::min(q_min, quality);
  }
  return true;
}

// A sliding node moves within its surface, or along its feature curve: its Newton step is the
// one of the cost restricted to that tangent space (BoundarySlide::TangentSpace). The free 3-D
// step, projected afterwards, loses its normal part and with it the Hessian's coupling to the
// normal: measured on the pinned thin-layer arteries, the sliding polish then ended below the
// held one on three of eight (docs/boundary.md#when-nodes-slide).
// Replaces `g` and `h` by their restrictions to the tangent space written back in 3-D (with
// P = BBᵀ, B the tangent basis: g ← Pg, h ← PhP + (I − P)), so the caller's Newton solve gives a
// tangential step.
void RestrictToTangent(const SmoothingContext& context, NodeId node, Vec3& g, Eigen::Matrix3d& h) {
  std::array<Vec3, 2> basis;
  const int count = context.slide->TangentSpace(context.mesh, node, basis);
  Eigen::Matrix3d projector = Eigen::Matrix3d::Zero();
  for (int k = 0; k < count; ++k) projector += basis[k] * basis[k].transpose();
  g = projector * g;
  h = projector * h * projector + (Eigen::Matrix3d::Identity() - projector);
}

// One damped Newton step of one node. Reads and writes only the node's coordinates and its
// elements' entries (and marks its neighbours stale), so nodes of one colour may run
// concurrently.
NodeStep PolishNode(SmoothingContext& context, NodeId node, PolishState& state) {
  if (state.stale[node].load(std::memory_order_relaxed) == 0) return NodeStep::kSkipped;
  state.stale[node].store(0, std::memory_order_relaxed);
  Mesh& mesh = context.mesh;
  const std::span<const ElementId> elements = mesh.node_elements(node);
  if (elements.empty()) return NodeStep::kConverged;
  NodeStepScratch& scratch = StepScratch();
  scratch.Fit(elements.size());
  double old_cost = 0.0;
  Vec3 g;
  Eigen::Matrix3d h;
  if (!NodeDerivatives(context, node, state.exponent, old_cost, g, h, scratch)) {
    return NodeStep::kRefused;
  }
  if (context.sliding[node]) {
    RestrictToTangent(context, node, g, h);
  }
  if (!g.allFinite() || g.squaredNorm() == 0.0) return NodeStep::kConverged;

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
    if (!(curvature > 0.0) || !std::isfinite(curvature)) return NodeStep::kRefused;
    d = -(g.squaredNorm() / curvature) * g;
    if (!d.allFinite()) return NodeStep::kRefused;
  }
  // The quadratic model's decrease along d, −g·d/2, is what a full step would buy: below this
  // fraction of the node's cost the node counts as converged, so converged regions stop costing
  // sweeps (and stop waking their neighbours).
  if (-0.5 * g.dot(d) < context.params.polish_node_tolerance * old_cost) {
    return NodeStep::kConverged;
  }

  auto x = mesh.x();
  auto y = mesh.y();
  auto z = mesh.z();
  const Vec3 start(x[node], y[node], z[node]);
  // Over-relaxed first (successive over-relaxation of the Gauss–Seidel sweep: the node-local
  // Newton step undershoots where neighbours will move the same way next, as across the layers
  // of a thin stack), then the plain step, then halvings.
  double alpha = context.params.polish_over_relaxation;
  for (int attempt = -1; attempt <= context.params.polish_backtracking_steps; ++attempt) {
    // A sliding boundary node's step goes back onto its surface before it is judged.
    const Vec3 trial = context.Placed(node, start + alpha * d, start);
    x[node] = trial[0];
    y[node] = trial[1];
    z[node] = trial[2];
    double cost = 0.0;
    double q_min = 0.0;
    // Accept only a strict cost decrease that keeps every element valid and at or above the
    // mesh's q_min when the stage began: q_min can then never fall (issue 14: "q_min of the
    // result never below q_min before the stage"). The floor is the mesh's, not the node's own
    // worst element: holding every node's worst element would freeze the nodes around each
    // locally worst element, and measured on mixed-hex-pyr-tet.vtk that keeps q_mean 0.003 below
    // the optimiser's.
    if (EvaluateTrial(context, node, scratch, state, cost, q_min) && cost < old_cost) {
      if (q_min >= state.q_floor) {
        for (ElementId e : elements) {
          context.quality[e] = state.trial_quality[e];
        }
        state.MarkNeighbourhood(mesh, node);
        return NodeStep::kMoved;
      }
      // A valid step that lowers the cost but takes an element below the floor. Along the line,
      // an element's quality is close to linear over a short step, so the step that would bring
      // it back to the floor is about α (q(0) − floor) / (q(0) − q(α)); the next trial is at most
      // a safety share of that (if shorter than a halving). An element that starts at the floor
      // leaves no room: the node stays, where halvings would have tried ten more steps that all
      // fall below the floor too (half the mean stage's trials on knowles-mixed-beam.vtk).
      double room = 1.0;
      for (ElementId e : elements) {
        const double trial_q = state.trial_quality[e];
        if (trial_q >= state.q_floor) continue;
        const double start_q = context.quality[e];
        room = std::min(room, (start_q - state.q_floor) / (start_q - trial_q));
      }
      if (!(room > 0.0)) break;
      alpha *= std::min(0.5, kFloorSafety * room);
      continue;
    }
    alpha = attempt < 0 ? 1.0 : 0.5 * alpha;
  }
  x[node] = start[0];
  y[node] = start[1];
  z[node] = start[2];
  return NodeStep::kRefused;
}

// What a stage of the polish keeps and hands on.
enum class StageGoal {
  // Worst-element stage: the best-q_min state (ties: the higher q_mean); no floor while it runs.
  kQMin,
  // Mean stage: the best-q_mean state, never an element below the floor.
  kQMean,
};

// Sweeps of one stage over the colours; adds its sweeps and refusals to `summary` and reports a
// progress event per sweep, numbered on from summary.iterations. Leaves the handed-on state in
// the mesh, context.quality and `current`. Returns false if cancelled. `final_after_colour`
// (ElementsByLastColour) lets the worst-element stage stop a first sweep it would drop; the
// mean stage passes none.
bool RunStage(SmoothingContext& context, const NodeColouring& colouring,
              const CompressedRows* final_after_colour, PolishState& state, StageGoal goal,
              std::int64_t max_sweeps, SmoothingContext::Summary& current, PhaseSummary& summary) {
  Mesh& mesh = context.mesh;
  const SmoothingParams& params = context.params;
  for (auto& flag : state.stale) flag.store(1, std::memory_order_relaxed);
  // Refused and moved steps per chunk of a colour, summed after the ParallelFor: integers, so any
  // order gives the same counts, but the chunks' counters must not be shared.
  std::vector<std::int64_t> refused_per_chunk;
  std::vector<std::int64_t> moved_per_chunk;
  // The best state so far: the cost falls with every accepted step, but neither q_mean nor q_min,
  // the measures that count, need rise with it (over-relaxed steps trade a little of q_mean early
  // on; the worst-element stage lets q_min dip on its way up). Copied before a sweep only while
  // the mesh itself is the best state.
  auto better = [goal](const SmoothingContext::Summary& a, const SmoothingContext::Summary& b) {
    if (goal == StageGoal::kQMean) return a.q_mean > b.q_mean;
    return a.q_min > b.q_min || (a.q_min == b.q_min && a.q_mean > b.q_mean);
  };
  SmoothingContext::Summary best = current;
  std::int64_t best_sweep = 0;
  NodePositions best_positions;
  double previous_gain = 0.0;
  bool cancelled = false;
  std::int64_t done = 0;  // complete sweeps of this stage
  for (std::int64_t sweep = 1; sweep <= max_sweeps; ++sweep) {
    if (best_sweep == sweep - 1) best_positions.CopyFrom(mesh);
    std::int64_t refused = 0;
    std::int64_t moved = 0;
    for (int c = 0; c < colouring.colour_count() && !cancelled; ++c) {
      if (context.Cancelled()) {
        cancelled = true;
        break;
      }
      const std::span<const NodeId> nodes = colouring.Colour(c);
      const auto count = static_cast<std::int64_t>(nodes.size());
      const std::int64_t grain = PolishNodeGrain(count, context.pool.thread_count());
      const std::int64_t chunks = (count + grain - 1) / grain;
      refused_per_chunk.assign(chunks, 0);
      moved_per_chunk.assign(chunks, 0);
      context.pool.ParallelFor(count, grain, [&](std::int64_t begin, std::int64_t end) {
        std::int64_t chunk_refused = 0;
        std::int64_t chunk_moved = 0;
        for (std::int64_t i = begin; i < end; ++i) {
          if (i + 2 < end) PrefetchElementRow(mesh, nodes[i + 2]);
          if (i + 1 < end) PrefetchElementNodes(mesh, nodes[i + 1]);
          const NodeStep step = PolishNode(context, nodes[i], state);
          chunk_refused += step == NodeStep::kRefused;
          chunk_moved += step == NodeStep::kMoved;
        }
        refused_per_chunk[begin / grain] += chunk_refused;
        moved_per_chunk[begin / grain] += chunk_moved;
      });
      for (std::int64_t r : refused_per_chunk) refused += r;
      for (std::int64_t m : moved_per_chunk) moved += m;
      // The worst-element stage's first sweep is dropped as soon as it ends below the q_min it
      // started from (the rule below the sweep). An element whose last movable node has had its
      // turn keeps its quality for the rest of the sweep, so once one of them is below that
      // q_min the sweep's end is known: the rest of it would be spent for nothing (on
      // knowles-mixed-beam, cub_fru and cub_wedge_like this sweep is always dropped). The state
      // handed on is the same bits: the sweep's start is restored either way.
      if (goal == StageGoal::kQMin && sweep == 1 && final_after_colour != nullptr) {
        const std::span<const ElementId> final = final_after_colour->Row(c);
        if (std::any_of(final.begin(), final.end(),
                        [&](ElementId e) { return context.quality[e] < best.q_min; })) {
          break;
        }
      }
    }
    if (cancelled) break;
    const SmoothingContext::Summary previous = current;
    current = context.Summarize();
    done = sweep;
    ++summary.iterations;
    // A node whose step was refused stayed where it was: the polish's "reverted" nodes.
    summary.reverted_nodes += refused;
    context.Report({Phase::kPolish, summary.iterations, current.q_min, current.q_mean,
                    current.invalid, refused, context.ElapsedSeconds(), false});
    if (better(current, best)) {
      best = current;
      best_sweep = sweep;
    }
    // Stop rules (issue 14, item 2), on the measure the stage serves, not on the cost its steps
    // lower: after two sweeps without a new best, or when no node moved (nothing can change).
    if (moved == 0 || sweep - best_sweep >= 2) break;
    // The worst-element stage also ends when its first sweep lowered q_min: Σ c^p then trades
    // the worst element for its neighbours from the state GETMe handed on, and on every shared
    // and generator mesh where that happened (cub_fru, cub_wedge_like, knowles-mixed-beam, the
    // rounded arteries) no later sweep came back above the start, so the second sweep the rule
    // above waits for was a fifth to a quarter of the polish spent for nothing. Where the stage
    // helps (the sharp arteries) its first sweep already lifts q_min.
    if (goal == StageGoal::kQMin && sweep == 1 && current.q_min < best.q_min) break;
    // Once the sweeps settle, the gain of a sweep shrinks about geometrically (Gauss–Seidel on a
    // convex problem converges linearly), so what is still to come is about gain · r / (1 − r),
    // r = the ratio of the last two gains: stop when that is below the stage's tolerance.
    const double gain = goal == StageGoal::kQMean ? current.q_mean - previous.q_mean
                                                  : current.q_min - previous.q_min;
    // The mean stage's tolerance shrinks with what is left to a perfect mesh (1 − q_mean): on a
    // nearly regular mesh all of the remaining gain is below polish_tolerance, yet a regular grid
    // is the answer a user expects there (1000hex-block-internal-bias.vtk).
    const double tolerance =
        goal == StageGoal::kQMean
            ? std::min(state.mean_tolerance, kDefectShare * (1.0 - current.q_mean))
            : params.polish_worst_tolerance * current.q_min;
    if (gain > 0.0 && previous_gain > 0.0) {
      const double ratio = std::min(gain / previous_gain, kMaxGainRatio);
      if (gain * ratio / (1.0 - ratio) < tolerance) break;
    }
    previous_gain = gain;
  }
  // The mesh holds a later state than the best (or, cancelled, a partly swept one): the best's
  // snapshot was taken before the sweep that followed it.
  if (cancelled || best_sweep != done) {
    best_positions.CopyTo(mesh);
    context.RefreshQuality();
    current = context.Summarize();
  }
  return !cancelled;
}

// The lowest quality among elements with no movable node (+∞ if every element has one): no step
// of the polish changes them, so the mesh's q_min cannot rise above it.
double PinnedMinimum(const SmoothingContext& context) {
  const Mesh& mesh = context.mesh;
  double pinned = std::numeric_limits<double>::infinity();
  for (ElementId e = 0; e < mesh.element_count(); ++e) {
    if (!context.HasMovableNode(e)) pinned = std::min(pinned, context.quality[e]);
  }
  return pinned;
}

// The worst-cluster stage's rule: the worst elements lag far behind the rest.
bool WorstClusterTriggered(const SmoothingParams& params,
                           const SmoothingContext::Summary& current) {
  return params.polish_cluster_trigger > 0.0 &&
         current.q_min < params.polish_cluster_trigger * current.q_mean;
}

// Whether the worst-cluster stage may run after the mean stage, judged before it: its rule
// holds, and the worst element has a free node (where it has none, FindCluster finds no cluster
// and the stage ends at once: tire.vtk). `pinned_minimum` is PinnedMinimum(context).
bool WorstClusterMayFollow(const SmoothingParams& params, const SmoothingContext::Summary& current,
                           double pinned_minimum) {
  return WorstClusterTriggered(params, current) && current.q_min < pinned_minimum;
}

}  // namespace

PolishColouring MakePolishColouring(const Mesh& mesh, std::span<const std::uint8_t> movable) {
  PolishColouring made{ColourNodes(mesh, movable), {}};
  made.final_after_colour = ElementsByLastColour(mesh, made.colouring);
  return made;
}

absl::StatusOr<PhaseSummary> RunPolish(SmoothingContext& context,
                                       std::optional<PolishColouring> colouring_made) {
  const double phase_start = context.ElapsedSeconds();
  Mesh& mesh = context.mesh;
  const SmoothingParams& params = context.params;
  // Once per call, in a fixed order: the sets, and so the order of the node steps, depend on the
  // mesh and the free nodes only.
  if (!colouring_made.has_value()) colouring_made = MakePolishColouring(mesh, context.movable);
  const NodeColouring& colouring = colouring_made->colouring;
  PolishState state(mesh.node_count());
  state.trial_quality.assign(mesh.element_count(), 0.0);

  SmoothingContext::Summary current = context.Summarize();
  PhaseSummary summary{Phase::kPolish, 0, 0.0, current.q_min, current.q_mean, 0};
  bool finished = true;
  // Elements with no movable node keep their quality through every stage.
  const double pinned_minimum = PinnedMinimum(context);
  // Worst elements first: the mean stage cannot lower q_min, so whatever q_min the polish is to
  // reach must come before it. Not where q_min is already the quality of an element with no
  // movable node: no step can raise it then, and the stage that serves q_min has nothing to do.
  if (params.polish_worst_exponent > 1.0 && params.polish_worst_max_sweeps > 0 &&
      current.q_min < pinned_minimum) {
    state.exponent = params.polish_worst_exponent;
    state.q_floor = 0.0;
    finished = RunStage(context, colouring, &colouring_made->final_after_colour, state,
                        StageGoal::kQMin, params.polish_worst_max_sweeps, current, summary);
  }
  // The mean stage's end is the polish's result unless the worst-cluster stage (below) starts
  // from it. Where it is the result, it stops at polish_final_tolerance: its stop rule then trades
  // the user's q_mean for time, and that much q_mean is a small share of what separates two
  // optimisers (issue 14 judges q_mean within 0.002 of Mesquite's). Where the cluster stage starts
  // from it, it runs on to polish_tolerance: that stage's end, a local max-min point of a
  // non-convex problem, moves with its start (measured on the pinned arteries: ±10 % of q_min
  // from a start 2 × 10⁻⁴ lower in q_mean), so the start is the converged state. Decided before
  // the stage, on what can change during it: the floor keeps q_min from falling and the stage
  // hands on its best q_mean, so the trigger rarely flips, and where it does the cluster stage
  // still runs as its rule says, only from the looser state.
  if (finished) {
    state.exponent = 1.0;
    state.q_floor = current.q_min;
    state.mean_tolerance = WorstClusterMayFollow(params, current, pinned_minimum)
                               ? params.polish_tolerance
                               : params.polish_final_tolerance;
    finished = RunStage(context, colouring, nullptr, state, StageGoal::kQMean,
                        params.polish_max_sweeps, current, summary);
  }
  // Worst elements that lag far behind the rest after both node-local stages are a coupled
  // plateau (worst_cluster.h): their free nodes move together, then the mean stage runs again
  // above the q_min that reached. After the mean stage, not before it: measured on the thin-layer
  // arteries, the mean stage itself lifts q_min on the sharp ones (0.035 to 0.094 on S sharp)
  // and the cluster starts from there; run first, it raised q_min less and left the mean stage a
  // higher floor to work under (S sharp ended at 0.048).
  if (finished && WorstClusterTriggered(params, current)) {
    const double q_min_before = current.q_min;
    finished = RunWorstCluster(context, current, summary).ok();
    if (finished && current.q_min > q_min_before) {
      state.q_floor = current.q_min;
      state.mean_tolerance = params.polish_final_tolerance;
      finished = RunStage(context, colouring, nullptr, state, StageGoal::kQMean,
                          params.polish_max_sweeps, current, summary);
    }
  }
  context.FinishPhase(summary, current, phase_start);
  if (!finished) return absl::CancelledError("smoothing cancelled during the polish stage");
  return summary;
}

}  // namespace getme
