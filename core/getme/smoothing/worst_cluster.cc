#include "getme/smoothing/worst_cluster.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <numeric>
#include <span>
#include <utility>
#include <vector>

#include "getme/elements/vec3.h"
#include "getme/mesh/node_neighbours.h"
#include "getme/mesh/type_runs.h"
#include "getme/smoothing/element_passes.h"
#include "getme/smoothing/min_norm_point.h"
#include "getme/smoothing/whole_power.h"

namespace getme {
namespace {

// Limited-memory BFGS: pairs kept, Armijo constant, shortenings of a step before the round ends.
constexpr int kHistory = 8;
constexpr double kArmijo = 1e-4;
constexpr int kMaxBacktracks = 30;
// A line search starts at this many times the step the previous one accepted (at most the full
// step). On the pinned arteries the full L-BFGS step inverts a thin-layer element in most
// iterations, and the step taken is mostly 10⁻¹–10⁻⁸ of it, of a similar size from one iteration
// to the next: started at the full step every time, four of five trial points inverted an element
// and were only shrunk tenfold (docs/thin-layers.md, "The line search").
constexpr double kStepMemory = 10.0;
// A round ends after this many iterations without a new highest min q over the cluster: f can
// keep falling by lifting elements above the minimum, which is not what the stage is for.
constexpr int kPatience = 40;
// A round ends once f falls by less than this share of itself in an iteration.
constexpr double kConverged = 1e-10;
// The first step moves no node by more than this share of its scale (Cluster::scale2): L-BFGS
// has no curvature yet, and the thin layers this stage is for invert under larger steps.
constexpr double kFirstStepShare = 0.02;
// The max-min ascent after L-BFGS (AscendMinimum): the elements it treats as
// active, those within a share of the minimum that starts at kActiveShare and widens fourfold
// up to kMaxActiveShare while no step helps; at most kMaxActive of them, the lowest; and the
// first trial step, as a share of the largest node's scale.
constexpr double kActiveShare = 1e-4;
constexpr double kMaxActiveShare = 0.03;
constexpr std::size_t kMaxActive = 48;
constexpr double kAscentFirstShare = 0.01;
// A round that stalls is tried once more with the band above q_min this many times wider.
constexpr double kWidenedBand = 2.0;
// Elements per ParallelFor chunk of an evaluation: each costs a few hundred nanoseconds.
constexpr std::int64_t kClusterElementGrain = 64;

struct Cluster {
  std::vector<NodeId> nodes;        // V: the worst elements' free nodes, ascending
  std::vector<ElementId> elements;  // B: every element with a node in V, ascending
  // Per node of V: the squared distance to its nearest neighbour in its elements, the scale in
  // which L-BFGS measures the node's moves.
  std::vector<double> scale2;
};

// Per element of B, what one evaluation computed: written in parallel, summed in B's order, so
// the sums have the same bits for every thread count. Of the gradient, only the element's nodes in
// V are read.
using ElementTerm = MeanRatioAndGradient;

// out[i] = the mean ratio and gradient of elements[i], whose node ids are node_lists[i], by the
// list passes within each run of one type.
void MeanRatiosAndGradientsOf(const SmoothingContext& context, std::span<const ElementId> elements,
                              std::span<const NodeId* const> node_lists,
                              std::span<ElementTerm> out) {
  const Mesh& mesh = context.mesh;
  ForEachTypeRun(mesh, elements, [&](ElementType type, std::int64_t begin, std::int64_t end) {
    context.passes.mean_ratio_gradient_list[TypeIndex(type)](
        {mesh.x(), mesh.y(), mesh.z(), node_lists.data() + begin, end - begin}, out.data() + begin);
  });
}

// (q_ref / q)^p: by repeated squaring for a whole exponent (the default 20), else std::pow.
double Term(double ratio, double exponent, int whole_exponent) {
  return whole_exponent < 0 ? std::pow(ratio, exponent) : WholePower(ratio, whole_exponent);
}

class ClusterObjective {
 public:
  ClusterObjective(SmoothingContext& context, const Cluster& cluster,
                   const std::vector<int>& variable_of, double q_ref)
      : context_(context),
        cluster_(cluster),
        variable_of_(variable_of),
        q_ref_(q_ref),
        exponent_(context.params.polish_cluster_exponent),
        whole_exponent_(std::floor(exponent_) == exponent_ && exponent_ <= 64.0
                            ? static_cast<int>(exponent_)
                            : -1),
        terms_(cluster.elements.size()) {
    context.NodeListsOf(cluster.elements, node_lists_);
  }

  // f = Σ_{e∈B} (q_ref / q_e)^p at the mesh's coordinates, +∞ if an element of B is invalid;
  // the lowest q_e in `min_q`; with `gradient`, ∇f over V (3 entries per node, V's order).
  double Evaluate(double& min_q, std::vector<double>* gradient) {
    const Mesh& mesh = context_.mesh;
    EvaluateElements(gradient != nullptr);
    double f = 0.0;
    min_q = std::numeric_limits<double>::infinity();
    if (gradient) gradient->assign(3 * cluster_.nodes.size(), 0.0);
    for (std::size_t i = 0; i < terms_.size(); ++i) {
      const double q = terms_[i].quality;
      if (!(q > 0.0)) return std::numeric_limits<double>::infinity();
      min_q = std::min(min_q, q);
      const double term = Term(q_ref_ / q, exponent_, whole_exponent_);
      f += term;
      if (!gradient) continue;
      // d/dq (q_ref / q)^p = −p (q_ref / q)^p / q.
      const double df_dq = -exponent_ * term / q;
      const std::span<const NodeId> ids = mesh.element_nodes(cluster_.elements[i]);
      for (std::size_t k = 0; k < ids.size(); ++k) {
        const int v = variable_of_[ids[k]];
        if (v < 0) continue;
        for (int c = 0; c < 3; ++c) (*gradient)[3 * v + c] += df_dq * terms_[i].gradient[k][c];
      }
    }
    return f;
  }

  // Every element of B's quality and, with_gradient, its gradient over its nodes in V, into
  // terms(); returns the lowest quality, 0 if an element is invalid.
  double EvaluateElements(bool with_gradient) {
    const std::int64_t count = static_cast<std::int64_t>(cluster_.elements.size());
    // Both evaluations go through the list passes: several elements of a type per vector
    // instruction, with the same bits as one at a time. The line search's trial points need
    // qualities alone, and are most of the stage's evaluations.
    if (!with_gradient) qualities_.resize(cluster_.elements.size());
    context_.pool.ParallelFor(
        count, kClusterElementGrain, [&](std::int64_t begin, std::int64_t end) {
          const auto offset = static_cast<std::size_t>(begin);
          const auto length = static_cast<std::size_t>(end - begin);
          const auto elements =
              std::span<const ElementId>(cluster_.elements).subspan(offset, length);
          const auto lists = std::span<const NodeId* const>(node_lists_).subspan(offset, length);
          if (with_gradient) {
            MeanRatiosAndGradientsOf(context_, elements, lists,
                                     std::span<ElementTerm>(terms_).subspan(offset, length));
            return;
          }
          context_.QualitiesOf(elements, lists,
                               std::span<double>(qualities_).subspan(offset, length));
          for (std::size_t i = offset; i < offset + length; ++i) terms_[i].quality = qualities_[i];
        });
    double min_q = std::numeric_limits<double>::infinity();
    for (const ElementTerm& term : terms_) {
      if (!(term.quality > 0.0)) return 0.0;
      min_q = std::min(min_q, term.quality);
    }
    return min_q;
  }
  // Only the elements of B at `indices` (positions in B): their terms with gradients, or, with
  // `qualities`, just their qualities into it (one per index) and terms() left as it was.
  void EvaluateSubset(std::span<const std::uint32_t> indices, std::vector<double>* qualities) {
    const std::int64_t count = static_cast<std::int64_t>(indices.size());
    subset_elements_.resize(indices.size());
    subset_lists_.resize(indices.size());
    for (std::size_t j = 0; j < indices.size(); ++j) {
      subset_elements_[j] = cluster_.elements[indices[j]];
      subset_lists_[j] = node_lists_[indices[j]];
    }
    if (qualities != nullptr) {
      qualities->resize(indices.size());
    } else {
      subset_terms_.resize(indices.size());
    }
    context_.pool.ParallelFor(
        count, kClusterElementGrain, [&](std::int64_t begin, std::int64_t end) {
          const auto offset = static_cast<std::size_t>(begin);
          const auto length = static_cast<std::size_t>(end - begin);
          const auto elements =
              std::span<const ElementId>(subset_elements_).subspan(offset, length);
          const auto lists = std::span<const NodeId* const>(subset_lists_).subspan(offset, length);
          if (qualities != nullptr) {
            context_.QualitiesOf(elements, lists,
                                 std::span<double>(*qualities).subspan(offset, length));
            return;
          }
          MeanRatiosAndGradientsOf(context_, elements, lists,
                                   std::span<ElementTerm>(subset_terms_).subspan(offset, length));
          for (std::size_t j = offset; j < offset + length; ++j) {
            terms_[indices[j]] = subset_terms_[j];
          }
        });
  }
  const std::vector<ElementTerm>& terms() const { return terms_; }

 private:
  SmoothingContext& context_;
  const Cluster& cluster_;
  const std::vector<int>& variable_of_;
  const double q_ref_;
  const double exponent_;
  const int whole_exponent_;
  std::vector<ElementTerm> terms_;
  // node_lists_[i]: the node ids of B's element i, for the list passes.
  std::vector<const NodeId*> node_lists_;
  // Scratch of the list passes: qualities of all of B, and the subset EvaluateSubset was given
  // with its terms.
  std::vector<double> qualities_;
  std::vector<ElementId> subset_elements_;
  std::vector<const NodeId*> subset_lists_;
  std::vector<ElementTerm> subset_terms_;
};

void ReadCoordinates(const Mesh& mesh, const Cluster& cluster, std::vector<double>& values) {
  values.resize(3 * cluster.nodes.size());
  for (std::size_t i = 0; i < cluster.nodes.size(); ++i) {
    values[3 * i] = mesh.x()[cluster.nodes[i]];
    values[3 * i + 1] = mesh.y()[cluster.nodes[i]];
    values[3 * i + 2] = mesh.z()[cluster.nodes[i]];
  }
}

void WriteCoordinates(Mesh& mesh, const Cluster& cluster, const std::vector<double>& values) {
  auto x = mesh.x();
  auto y = mesh.y();
  auto z = mesh.z();
  for (std::size_t i = 0; i < cluster.nodes.size(); ++i) {
    x[cluster.nodes[i]] = values[3 * i];
    y[cluster.nodes[i]] = values[3 * i + 1];
    z[cluster.nodes[i]] = values[3 * i + 2];
  }
}

// A sliding node's share of the gradient turned into its surface (or curve): the move the
// projection keeps of a small step along it, so that the search directions, and with them the
// line search's slope, are ones the node can follow. Exact on a flat face or a straight edge.
Vec3 TangentialNodeGradient(const SmoothingContext& context, const Cluster& cluster, std::size_t i,
                            const Vec3& at, const Vec3& gradient) {
  const double length = gradient.norm();
  if (!(length > 0.0)) return gradient;
  // A step of a thousandth of the node's own length scale.
  const double epsilon = 1e-3 * std::sqrt(cluster.scale2[i]) / length;
  return (context.Placed(cluster.nodes[i], at + epsilon * gradient, at) - at) / epsilon;
}

void TangentialGradient(const SmoothingContext& context, const Cluster& cluster,
                        const std::vector<double>& x, std::vector<double>& g) {
  for (std::size_t i = 0; i < cluster.nodes.size(); ++i) {
    if (!context.sliding[cluster.nodes[i]]) continue;
    const Vec3 along =
        TangentialNodeGradient(context, cluster, i, Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]),
                               Vec3(g[3 * i], g[3 * i + 1], g[3 * i + 2]));
    for (int k = 0; k < 3; ++k) g[3 * i + k] = along[k];
  }
}

// The trial point of the line search with every sliding node put back onto its surface.
void PlaceTrial(const SmoothingContext& context, const Cluster& cluster,
                const std::vector<double>& x, std::vector<double>& trial) {
  for (std::size_t i = 0; i < cluster.nodes.size(); ++i) {
    const NodeId node = cluster.nodes[i];
    if (!context.sliding[node]) continue;
    const Vec3 placed = context.Placed(node, Vec3(trial[3 * i], trial[3 * i + 1], trial[3 * i + 2]),
                                       Vec3(x[3 * i], x[3 * i + 1], x[3 * i + 2]));
    for (int k = 0; k < 3; ++k) trial[3 * i + k] = placed[k];
  }
}

double Dot(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += a[i] * b[i];
  return sum;
}

// L-BFGS (two-loop recursion) on the cluster's f from the mesh's coordinates, with a
// backtracking line search on which an invalid element counts as f = +∞. Leaves the iterate
// with the highest min q over B in the mesh (the start if none beat it).
void Minimise(SmoothingContext& context, const Cluster& cluster,
              const std::vector<int>& variable_of, double q_ref) {
  Mesh& mesh = context.mesh;
  ClusterObjective objective(context, cluster, variable_of, q_ref);
  const std::size_t n = 3 * cluster.nodes.size();
  std::vector<double> x;
  ReadCoordinates(mesh, cluster, x);
  std::vector<double> g;
  double min_q = 0.0;
  double f = objective.Evaluate(min_q, &g);
  if (!std::isfinite(f)) return;
  TangentialGradient(context, cluster, x, g);
  double best_min_q = min_q;
  std::vector<double> best_x = x;
  int best_iteration = 0;
  std::deque<std::vector<double>> s_history;
  std::deque<std::vector<double>> y_history;
  std::deque<double> rho_history;
  std::vector<double> d(n), trial(n), g_new, alpha;
  // The step the last line search accepted, as a share of its L-BFGS step.
  double last_step = 1.0;
  for (int iteration = 1; iteration <= context.params.polish_cluster_iterations; ++iteration) {
    // d = −H g by the two-loop recursion.
    d = g;
    alpha.assign(s_history.size(), 0.0);
    for (int k = static_cast<int>(s_history.size()) - 1; k >= 0; --k) {
      alpha[k] = rho_history[k] * Dot(s_history[k], d);
      for (std::size_t i = 0; i < n; ++i) d[i] -= alpha[k] * y_history[k][i];
    }
    // H₀ = γ D with D = diag(h_i²): each node's moves measured in its own length scale h_i
    // (Cluster::scale2). A scalar H₀ would take the thin layers' nodes, a hundredth of a wall
    // edge apart, at the scale of the interior's, and every step would end in a backtrack; with D
    // the arteries' rounds lift q_min further in fewer evaluations (docs/thin-layers.md).
    for (std::size_t i = 0; i < n; ++i) d[i] *= cluster.scale2[i / 3];
    if (!s_history.empty()) {
      const std::vector<double>& y_last = y_history.back();
      double y_d_y = 0.0;
      for (std::size_t i = 0; i < n; ++i) y_d_y += y_last[i] * y_last[i] * cluster.scale2[i / 3];
      const double gamma = Dot(s_history.back(), y_last) / y_d_y;
      for (double& v : d) v *= gamma;
    } else {
      // No curvature yet: no node moves by more than kFirstStepShare of its scale.
      double largest = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        largest = std::max(largest, std::abs(d[i]) / std::sqrt(cluster.scale2[i / 3]));
      }
      if (!(largest > 0.0)) break;
      for (double& v : d) v *= kFirstStepShare / largest;
    }
    for (std::size_t k = 0; k < s_history.size(); ++k) {
      const double beta = rho_history[k] * Dot(y_history[k], d);
      for (std::size_t i = 0; i < n; ++i) d[i] += s_history[k][i] * (alpha[k] - beta);
    }
    for (double& v : d) v = -v;
    const double slope = Dot(g, d);
    if (!(slope < 0.0)) {
      if (s_history.empty()) break;
      // Curvature pairs that no longer describe f: start again from steepest descent.
      s_history.clear();
      y_history.clear();
      rho_history.clear();
      continue;
    }
    double step = std::min(1.0, kStepMemory * last_step);
    double f_trial = std::numeric_limits<double>::infinity();
    bool accepted = false;
    for (int backtrack = 0; backtrack < kMaxBacktracks; ++backtrack) {
      for (std::size_t i = 0; i < n; ++i) trial[i] = x[i] + step * d[i];
      PlaceTrial(context, cluster, x, trial);
      WriteCoordinates(mesh, cluster, trial);
      f_trial = objective.Evaluate(min_q, nullptr);
      if (f_trial <= f + kArmijo * step * slope) {
        accepted = true;
        break;
      }
      // The minimiser of the quadratic through f(x), the slope and f(x + step d), kept within
      // [0.1, 0.5] of the step: f grows like q^−p towards a flattening element, so a halving
      // at a time takes many evaluations to come back from a step that overshot by orders of
      // magnitude. An invalid element (f = +∞) shrinks the step tenfold.
      double next = 0.1 * step;
      if (std::isfinite(f_trial)) {
        const double curvature = f_trial - f - slope * step;
        if (curvature > 0.0)
          next = std::clamp(-slope * step * step / (2.0 * curvature), 0.1 * step, 0.5 * step);
      }
      step = next;
    }
    if (!accepted) break;
    last_step = step;
    if (min_q > best_min_q) {
      best_min_q = min_q;
      best_x = trial;
      best_iteration = iteration;
    }
    const bool converged = f - f_trial <= kConverged * f;
    objective.Evaluate(min_q, &g_new);
    TangentialGradient(context, cluster, trial, g_new);
    std::vector<double> s(n);
    std::vector<double> y(n);
    for (std::size_t i = 0; i < n; ++i) {
      s[i] = trial[i] - x[i];
      y[i] = g_new[i] - g[i];
    }
    const double sy = Dot(s, y);
    x.swap(trial);
    g.swap(g_new);
    f = f_trial;
    if (converged || iteration - best_iteration >= kPatience || context.Cancelled()) break;
    if (sy > 0.0) {
      s_history.push_back(std::move(s));
      y_history.push_back(std::move(y));
      rho_history.push_back(1.0 / sy);
      if (static_cast<int>(s_history.size()) > kHistory) {
        s_history.pop_front();
        y_history.pop_front();
        rho_history.pop_front();
      }
    }
  }
  WriteCoordinates(mesh, cluster, best_x);
}

// After L-BFGS on the smooth stand-in f, the max-min problem itself: steepest ascent of
// min_{e∈B} q_e over V. The stand-in weighs every element near the minimum, so where many are
// near it its minimiser trades the lowest against the others and stops short of the highest
// reachable minimum. Each iteration takes the elements within a small share of the minimum (the
// active ones), the point of smallest norm in the convex hull of their gradients in the nodes'
// own metric D (min_norm_point.h) as the direction, d = D Σ λ_e ∇q_e, which raises every active
// element at the rate |d|²_{D⁻¹} or more, and the step along d that gives the highest minimum over
// all of B, found by doubling or halving. If no step raises the minimum the active set widens
// (an element just above the minimum may be what blocks the direction), until kMaxActiveShare.
// d moves only the active elements' nodes, so a step re-evaluates only the elements around them.
// Invalid elements count as q = 0, so the minimum never admits one. Every sum runs in a fixed
// order, so any thread count gives the same bits. Leaves the best iterate in the mesh.
void AscendMinimum(SmoothingContext& context, const Cluster& cluster,
                   const std::vector<int>& variable_of, ClusterObjective& objective) {
  Mesh& mesh = context.mesh;
  const std::size_t node_count = cluster.nodes.size();
  std::vector<double> x;
  ReadCoordinates(mesh, cluster, x);
  double min_q = objective.EvaluateElements(true);
  if (!(min_q > 0.0)) return;
  // Per node of V, the positions in B of its elements.
  std::vector<std::vector<std::uint32_t>> elements_of(node_count);
  for (std::size_t v = 0; v < node_count; ++v) {
    for (const ElementId e : mesh.node_elements(cluster.nodes[v])) {
      const auto at = std::lower_bound(cluster.elements.begin(), cluster.elements.end(), e);
      elements_of[v].push_back(static_cast<std::uint32_t>(at - cluster.elements.begin()));
    }
  }
  const auto position = [&](std::size_t v) { return Vec3(x[3 * v], x[3 * v + 1], x[3 * v + 2]); };
  const auto place = [&](std::size_t v, const Vec3& p) {
    mesh.x()[cluster.nodes[v]] = p[0];
    mesh.y()[cluster.nodes[v]] = p[1];
    mesh.z()[cluster.nodes[v]] = p[2];
  };
  // An active element's gradient: (node of V, ∂q/∂p) for each of its nodes in V.
  using SparseGradient = std::vector<std::pair<std::size_t, Vec3>>;
  std::vector<SparseGradient> gradients;
  std::vector<std::size_t> candidates;
  std::vector<std::size_t> moved;  // nodes of V the direction moves, ascending
  std::vector<std::uint8_t> is_moved(node_count, 0);
  std::vector<Vec3> direction(node_count, Vec3::Zero());
  std::vector<Vec3> trial(node_count), best_trial(node_count);
  std::vector<std::uint8_t> affected_mark(cluster.elements.size(), 0);
  std::vector<std::uint32_t> affected;
  std::vector<double> trial_quality;
  for (std::int64_t iteration = 0;
       iteration < context.params.polish_cluster_ascent_iterations && !context.Cancelled();
       ++iteration) {
    const std::vector<ElementTerm>& terms = objective.terms();
    candidates.clear();
    for (std::size_t i = 0; i < terms.size(); ++i) {
      if (terms[i].quality <= min_q * (1.0 + kMaxActiveShare)) candidates.push_back(i);
    }
    std::sort(candidates.begin(), candidates.end(), [&](std::size_t a, std::size_t b) {
      return terms[a].quality != terms[b].quality ? terms[a].quality < terms[b].quality : a < b;
    });
    bool stepped = false;
    for (double share = kActiveShare; share <= kMaxActiveShare && !stepped; share *= 4.0) {
      std::size_t active = 0;
      while (active < candidates.size() && active < kMaxActive &&
             terms[candidates[active]].quality <= min_q * (1.0 + share)) {
        ++active;
      }
      // The active elements' gradients over V, turned into the sliding nodes' surfaces.
      gradients.assign(active, {});
      for (std::size_t a = 0; a < active; ++a) {
        const std::size_t i = candidates[a];
        const std::span<const NodeId> ids = mesh.element_nodes(cluster.elements[i]);
        for (std::size_t k = 0; k < ids.size(); ++k) {
          const int v = variable_of[ids[k]];
          if (v < 0) continue;
          const std::size_t node = static_cast<std::size_t>(v);
          Vec3 gradient = terms[i].gradient[k];
          if (context.sliding[ids[k]]) {
            gradient = TangentialNodeGradient(context, cluster, node, position(node), gradient);
          }
          gradients[a].emplace_back(node, gradient);
        }
      }
      Eigen::MatrixXd gram(static_cast<Eigen::Index>(active), static_cast<Eigen::Index>(active));
      for (std::size_t a = 0; a < active; ++a) {
        for (std::size_t b = 0; b <= a; ++b) {
          double sum = 0.0;
          for (const auto& [u, gu] : gradients[a]) {
            for (const auto& [w, gw] : gradients[b]) {
              if (u == w) sum += gu.dot(gw) * cluster.scale2[u];
            }
          }
          gram(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) = sum;
          gram(static_cast<Eigen::Index>(b), static_cast<Eigen::Index>(a)) = sum;
        }
      }
      const MinNormPoint hull = MinNormPointOfHull(gram);
      if (!(hull.squared_norm > 0.0)) continue;  // a stationary point of this active set
      for (const std::size_t v : moved) {
        direction[v].setZero();
        is_moved[v] = 0;
      }
      moved.clear();
      for (std::size_t a = 0; a < active; ++a) {
        for (const auto& [v, gradient] : gradients[a]) {
          if (!is_moved[v]) {
            is_moved[v] = 1;
            moved.push_back(v);
          }
          direction[v] += hull.weights[static_cast<Eigen::Index>(a)] * gradient;
        }
      }
      std::sort(moved.begin(), moved.end());
      double largest = 0.0;
      for (const std::size_t v : moved) {
        direction[v] *= cluster.scale2[v];
        largest = std::max(largest, direction[v].norm() / std::sqrt(cluster.scale2[v]));
      }
      if (!(largest > 0.0)) continue;
      // The elements the move reaches, and the lowest quality of the rest, which stays.
      for (const std::uint32_t i : affected) affected_mark[i] = 0;
      affected.clear();
      for (const std::size_t v : moved) {
        for (const std::uint32_t i : elements_of[v]) {
          if (!affected_mark[i]) {
            affected_mark[i] = 1;
            affected.push_back(i);
          }
        }
      }
      std::sort(affected.begin(), affected.end());
      double unmoved_min = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < terms.size(); ++i) {
        if (!affected_mark[i]) unmoved_min = std::min(unmoved_min, terms[i].quality);
      }
      // Doubling while the minimum keeps rising, halving until it rises at all.
      double step = kAscentFirstShare / largest;
      double best_q = min_q;
      const auto try_step = [&](double length) {
        for (const std::size_t v : moved) {
          const Vec3 from = position(v);
          trial[v] = from + length * direction[v];
          if (context.sliding[cluster.nodes[v]]) {
            trial[v] = context.Placed(cluster.nodes[v], trial[v], from);
          }
          place(v, trial[v]);
        }
        objective.EvaluateSubset(affected, &trial_quality);
        double q = unmoved_min;
        for (const double quality : trial_quality) q = std::min(q, quality > 0.0 ? quality : 0.0);
        if (q > best_q) {
          best_q = q;
          for (const std::size_t v : moved) best_trial[v] = trial[v];
          return true;
        }
        return false;
      };
      if (try_step(step)) {
        for (int grow = 0; grow < 10 && try_step(step *= 2.0);) ++grow;
      } else {
        for (int shrink = 0; shrink < 20 && !try_step(step *= 0.5);) ++shrink;
      }
      if (best_q > min_q) {
        for (const std::size_t v : moved) {
          for (int c = 0; c < 3; ++c) x[3 * v + c] = best_trial[v][c];
        }
        stepped = true;
      }
      for (const std::size_t v : moved) place(v, position(v));
    }
    if (!stepped) break;
    const double previous = min_q;
    objective.EvaluateSubset(affected, nullptr);
    min_q = std::numeric_limits<double>::infinity();
    for (const ElementTerm& term : objective.terms()) min_q = std::min(min_q, term.quality);
    if (!(min_q > previous * (1.0 + 1e-9))) break;
  }
  WriteCoordinates(mesh, cluster, x);
}

// The round's cluster: the elements within the band above q_min (polish_cluster_band times
// band_factor), their free nodes, and every element around those nodes. Empty nodes if the worst
// element has no free node: then nothing can lift q_min.
Cluster FindCluster(const SmoothingContext& context, double q_min, double band_factor,
                    std::vector<int>& variable_of, std::vector<std::uint8_t>& in_cluster) {
  const Mesh& mesh = context.mesh;
  const double limit = q_min * (1.0 + band_factor * context.params.polish_cluster_band);
  Cluster cluster;
  for (ElementId e = 0; e < mesh.element_count(); ++e) {
    const double q = context.quality[e];
    if (q > limit) continue;
    bool any_free = false;
    for (NodeId node : mesh.element_nodes(e)) {
      if (!context.movable[node]) continue;
      any_free = true;
      if (variable_of[node] < 0) {
        variable_of[node] = 0;
        cluster.nodes.push_back(node);
      }
    }
    if (!any_free && q <= q_min) {
      for (NodeId node : cluster.nodes) variable_of[node] = -1;
      return {};
    }
  }
  std::sort(cluster.nodes.begin(), cluster.nodes.end());
  for (std::size_t i = 0; i < cluster.nodes.size(); ++i) {
    variable_of[cluster.nodes[i]] = static_cast<int>(i);
  }
  for (NodeId node : cluster.nodes) {
    for (ElementId e : mesh.node_elements(node)) {
      if (!in_cluster[e]) {
        in_cluster[e] = 1;
        cluster.elements.push_back(e);
      }
    }
  }
  std::sort(cluster.elements.begin(), cluster.elements.end());
  cluster.scale2.resize(cluster.nodes.size());
  for (std::size_t i = 0; i < cluster.nodes.size(); ++i) {
    // Nodes of a valid element are distinct, so the distance is positive; the floor only keeps a
    // degenerate input from dividing by zero.
    cluster.scale2[i] =
        std::max(NearestNodeDistance2(mesh, cluster.nodes[i]), std::numeric_limits<double>::min());
  }
  return cluster;
}

}  // namespace

absl::Status RunWorstCluster(SmoothingContext& context, SmoothingContext::Summary& current,
                             PhaseSummary& summary) {
  Mesh& mesh = context.mesh;
  const SmoothingParams& params = context.params;
  std::vector<int> variable_of(mesh.node_count(), -1);
  std::vector<std::uint8_t> in_cluster(mesh.element_count(), 0);
  std::vector<double> start;
  std::vector<double> start_quality;
  std::vector<const NodeId*> node_lists;
  std::vector<double> measured;
  // The rounds minimise the smooth stand-in until they stall. A stalled round is tried once more
  // with the band widened (kWidenedBand): the wider cluster can move what held the narrow one, and
  // where it gains, the rounds go on. Then a round ascends the minimum itself (AscendMinimum) from
  // where they stalled. Run from the start, the ascent settles on the first local max-min point,
  // which on the arteries is lower than where the stand-in's rounds, each re-centred on the new
  // worst elements, go on to (docs/thin-layers.md). Where the ascent gains, the stand-in's rounds
  // start again from its end; the stage ends at an ascent that gains less than the tolerance, or
  // after the last round, which is always an ascent.
  bool ascending = false;
  bool widened = false;
  for (std::int64_t round = 1; round <= params.polish_cluster_max_rounds + 1; ++round) {
    if (context.Cancelled()) {
      return absl::CancelledError("smoothing cancelled during the polish's worst-cluster stage");
    }
    if (round > params.polish_cluster_max_rounds) {
      if (params.polish_cluster_ascent_iterations == 0) break;
      ascending = true;
    }
    const double q_start = current.q_min;
    if (!(q_start > 0.0)) break;
    Cluster cluster =
        FindCluster(context, q_start, widened ? kWidenedBand : 1.0, variable_of, in_cluster);
    if (cluster.nodes.empty()) break;
    ReadCoordinates(mesh, cluster, start);
    start_quality.resize(cluster.elements.size());
    for (std::size_t i = 0; i < cluster.elements.size(); ++i) {
      start_quality[i] = context.quality[cluster.elements[i]];
    }
    if (ascending) {
      ClusterObjective objective(context, cluster, variable_of, q_start);
      AscendMinimum(context, cluster, variable_of, objective);
    } else {
      Minimise(context, cluster, variable_of, q_start);
    }
    // The stored qualities get MeanRatioOrInvalid's bits, as every other phase writes them.
    context.NodeListsOf(cluster.elements, node_lists);
    measured.resize(cluster.elements.size());
    context.QualitiesOf(cluster.elements, node_lists, measured);
    for (std::size_t i = 0; i < cluster.elements.size(); ++i) {
      context.quality[cluster.elements[i]] = measured[i];
    }
    const SmoothingContext::Summary after = context.Summarize();
    for (NodeId node : cluster.nodes) variable_of[node] = -1;
    for (ElementId e : cluster.elements) in_cluster[e] = 0;
    const bool kept = after.invalid == 0 && after.q_min > q_start;
    if (!kept) {
      WriteCoordinates(mesh, cluster, start);
      for (std::size_t i = 0; i < cluster.elements.size(); ++i) {
        context.quality[cluster.elements[i]] = start_quality[i];
      }
    } else {
      current = after;
      ++summary.iterations;
      context.Report({Phase::kPolish, summary.iterations, current.q_min, current.q_mean,
                      current.invalid, 0, context.ElapsedSeconds(), false});
    }
    const bool gained = kept && after.q_min >= q_start * (1.0 + params.polish_cluster_tolerance);
    if (ascending) {
      if (!gained || round > params.polish_cluster_max_rounds) break;
      // The ascent left the plateau the stand-in's rounds had stalled on: they go on from there.
      ascending = false;
      continue;
    }
    if (!gained && !widened) {
      widened = true;
      continue;
    }
    widened = false;
    if (!gained) {
      if (params.polish_cluster_ascent_iterations == 0) break;
      ascending = true;
    }
  }
  return absl::OkStatus();
}

}  // namespace getme
