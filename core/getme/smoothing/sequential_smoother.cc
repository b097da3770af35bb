#include "getme/smoothing/sequential_smoother.h"

#include <algorithm>
#include <array>
#include <vector>

#include "getme/elements/element_quality.h"
#include "getme/elements/transform.h"
#include "getme/elements/vec3.h"
#include "getme/mesh/element_neighbours.h"
#include "getme/parallel/indexed_min_heap.h"

namespace getme {
namespace {

// Picks between two looks at the cancellation token: a pick costs about a microsecond.
constexpr std::int64_t kCancelCheckInterval = 256;

struct NodeBackup {
  NodeId node;
  double x, y, z;
};

class SequentialSubstep {
 public:
  SequentialSubstep(SmoothingContext& context, SelectionCriterion criterion, SequentialStop stop)
      : context_(context),
        mesh_(context.mesh),
        params_(context.params),
        criterion_(criterion),
        stop_(stop),
        phase_(criterion == SelectionCriterion::kMeanRatio ? Phase::kSequential : Phase::kWarpage),
        penalty_(mesh_.element_count(), 0.0),
        criterion_value_(mesh_.element_count()),
        selection_(mesh_.element_count()),
        quality_min_(mesh_.element_count()),
        criterion_min_(criterion == SelectionCriterion::kMeanRatio ? 0 : mesh_.element_count()) {}

  absl::StatusOr<PhaseSummary> Run();

 private:
  double Criterion(ElementId element, double quality) const;
  bool HasMovableNode(ElementId element) const;
  double CriterionMinimum() const {
    return criterion_ == SelectionCriterion::kMeanRatio ? quality_min_.top_key()
                                                        : criterion_min_.top_key();
  }
  // One pick of Steps 1–3; returns the number of nodes reverted (0 when it was applied).
  std::int64_t TransformWorst();
  void RestoreBest();

  SmoothingContext& context_;
  Mesh& mesh_;
  const SmoothingParams& params_;
  const SelectionCriterion criterion_;
  const SequentialStop stop_;
  const Phase phase_;
  std::vector<double> penalty_;          // π_j ≥ 0
  std::vector<double> criterion_value_;  // q(E_j) or q_γ(E_j)
  // Keyed by criterion + π over elements with a movable node; items are canonical ranks, so ties
  // break in the canonical order (Mesh::canonical_order).
  IndexedMinHeap selection_;
  IndexedMinHeap quality_min_;  // keyed by q, every element: the mesh's q_min
  // Keyed by the criterion, every element; left empty for the mean-ratio criterion, whose key is
  // quality_min_'s (a valid element's q ≥ 0), so CriterionMinimum reads that heap instead.
  IndexedMinHeap criterion_min_;
  double quality_sum_ = 0.0;
  ElementId last_pick_ = -1;
  ElementId blocker_ = -1;  // a neighbour that a reverted step would have inverted
  std::vector<NodeBackup> undo_since_best_;
  std::vector<NodeBackup> pick_backup_;
  std::vector<NodeBackup> pick_target_;
  ElementNeighbourFinder neighbour_finder_;
  std::vector<ElementId> affected_;
  std::vector<double> affected_quality_;
  std::vector<double> affected_criterion_;
};

double SequentialSubstep::Criterion(ElementId element, double quality) const {
  const double q = std::max(0.0, quality);
  if (criterion_ == SelectionCriterion::kMeanRatio) return q;
  const NodeId* ids = mesh_.element_nodes(element).data();
  const double warpage = DispatchElementType(mesh_.type(element), [&]<ElementType kType>() {
    return Warpage<kType>(GatherNodes<kType>(mesh_, ids));
  });
  return std::min(q, params_.gamma * (1.0 - warpage / 2.0));
}

bool SequentialSubstep::HasMovableNode(ElementId element) const {
  for (NodeId node : mesh_.element_nodes(element)) {
    if (context_.movable[node]) return true;
  }
  return false;
}

std::int64_t SequentialSubstep::TransformWorst() {
  ElementId pick = mesh_.canonical_order()[selection_.top()];
  if (blocker_ >= 0) {
    pick = blocker_;
    blocker_ = -1;
  }
  // Δπ_r: the same element was picked in the previous step (Step 3.2).
  if (pick == last_pick_) penalty_[pick] += params_.penalty_repeat;
  last_pick_ = pick;

  // Steps 1.2, 1.3 and 2: transform with the fixed σ^type, scale, relax, set the free nodes.
  auto x = mesh_.x();
  auto y = mesh_.y();
  auto z = mesh_.z();
  const std::span<const NodeId> ids = mesh_.element_nodes(pick);
  const ElementType type = mesh_.type(pick);
  pick_backup_.clear();
  pick_target_.clear();
  DispatchElementType(type, [&]<ElementType kType>() {
    const auto moved =
        RegularizingStep<kType>(GatherNodes<kType>(mesh_, ids.data()),
                                params_.sequential_sigma[TypeIndex(kType)], params_.sequential_rho);
    for (int k = 0; k < ElementTable<kType>::kNodes; ++k) {
      const NodeId node = ids[k];
      if (!context_.movable[node]) continue;
      pick_backup_.push_back({node, x[node], y[node], z[node]});
      pick_target_.push_back({node, moved[k].x(), moved[k].y(), moved[k].z()});
    }
  });

  // Step 3.1: the element and its neighbours must stay valid. With backtracking (a safeguard,
  // docs/quality.md) a step that would invert a neighbour is retried at half the length. Only the
  // neighbours through a movable node change: the others keep their quality (and validity), so
  // they are not evaluated.
  affected_.assign(1, pick);
  const auto neighbours = neighbour_finder_.Find(mesh_, pick, context_.movable);
  affected_.insert(affected_.end(), neighbours.begin(), neighbours.end());
  affected_quality_.resize(affected_.size());
  affected_criterion_.resize(affected_.size());
  bool valid = false;
  double fraction = 1.0;
  for (int attempt = 0; attempt <= params_.sequential_backtracking_steps && !valid;
       ++attempt, fraction *= 0.5) {
    for (std::size_t i = 0; i < pick_target_.size(); ++i) {
      const NodeBackup& from = pick_backup_[i];
      const NodeBackup& to = pick_target_[i];
      const Vec3 placed = context_.Placed(
          from.node,
          Vec3(from.x + fraction * (to.x - from.x), from.y + fraction * (to.y - from.y),
               from.z + fraction * (to.z - from.z)),
          Vec3(from.x, from.y, from.z));
      x[from.node] = placed[0];
      y[from.node] = placed[1];
      z[from.node] = placed[2];
    }
    valid = true;
    for (std::size_t i = 0; i < affected_.size() && valid; ++i) {
      affected_quality_[i] = ElementQualityOrInvalid(mesh_, affected_[i]);
      valid = affected_quality_[i] >= 0.0;
      if (!valid && params_.sequential_transform_blockers &&
          selection_.contains(mesh_.canonical_rank(affected_[i]))) {
        blocker_ = affected_[i];
      }
    }
  }
  if (valid) {
    for (std::size_t i = 0; i < affected_.size(); ++i) {
      affected_criterion_[i] = Criterion(affected_[i], affected_quality_[i]);
    }
  }
  if (!valid) {
    for (const NodeBackup& b : pick_backup_) {
      x[b.node] = b.x;
      y[b.node] = b.y;
      z[b.node] = b.z;
    }
    penalty_[pick] += params_.penalty_invalid;  // Δπ_i
    selection_.Update(mesh_.canonical_rank(pick), criterion_value_[pick] + penalty_[pick]);
    return static_cast<std::int64_t>(pick_backup_.size());
  }
  penalty_[pick] = std::max(0.0, penalty_[pick] - params_.penalty_success);  // Δπ_s
  undo_since_best_.insert(undo_since_best_.end(), pick_backup_.begin(), pick_backup_.end());
  for (std::size_t i = 0; i < affected_.size(); ++i) {
    const ElementId element = affected_[i];
    const double q = affected_quality_[i];
    quality_sum_ += q - std::max(0.0, context_.quality[element]);
    context_.quality[element] = q;
    criterion_value_[element] = affected_criterion_[i];
    quality_min_.Update(element, q);
    if (criterion_ != SelectionCriterion::kMeanRatio) {
      criterion_min_.Update(element, criterion_value_[element]);
    }
    if (const std::int32_t rank = mesh_.canonical_rank(element); selection_.contains(rank)) {
      selection_.Update(rank, criterion_value_[element] + penalty_[element]);
    }
  }
  return 0;
}

void SequentialSubstep::RestoreBest() {
  auto x = mesh_.x();
  auto y = mesh_.y();
  auto z = mesh_.z();
  for (auto it = undo_since_best_.rbegin(); it != undo_since_best_.rend(); ++it) {
    x[it->node] = it->x;
    y[it->node] = it->y;
    z[it->node] = it->z;
  }
  undo_since_best_.clear();
  context_.RefreshQuality();
}

absl::StatusOr<PhaseSummary> SequentialSubstep::Run() {
  const double phase_start = context_.ElapsedSeconds();
  const std::int64_t elements = mesh_.element_count();
  const bool sliding = stop_ == SequentialStop::kHandOnToPolish;
  const std::int64_t window =
      sliding ? (params_.sequential_handoff_window > 0 ? params_.sequential_handoff_window
                                                       : std::max<std::int64_t>(1000, elements / 4))
              : (params_.sequential_stall_iterations > 0 ? params_.sequential_stall_iterations
                                                         : std::max<std::int64_t>(1000, elements));
  const std::int64_t cap =
      params_.sequential_max_iterations > 0 ? params_.sequential_max_iterations : 50 * elements;

  for (ElementId element : mesh_.canonical_order()) {  // the running sum's order matters
    const double q = std::max(0.0, context_.quality[element]);
    quality_sum_ += q;
    criterion_value_[element] = Criterion(element, q);
    quality_min_.Push(element, q);
    if (criterion_ != SelectionCriterion::kMeanRatio) {
      criterion_min_.Push(element, criterion_value_[element]);
    }
    if (HasMovableNode(element)) {
      selection_.Push(mesh_.canonical_rank(element), criterion_value_[element]);
    }
  }

  PhaseSummary summary{phase_, 0, 0.0, 0.0, 0.0, 0};
  double best_min = CriterionMinimum();
  double window_start_min = best_min;
  std::int64_t window_start = 0;
  // Sliding rule: the pick at which the best minimum last rose by the tolerance, and that value.
  double risen_min = best_min;
  std::int64_t risen_pick = 0;
  std::int64_t cycle_reverts = 0;
  bool cancelled = false;
  std::int64_t pick = 0;
  while (!selection_.empty() && pick < cap) {
    ++pick;
    cycle_reverts += TransformWorst();
    const double current_min = CriterionMinimum();
    if (current_min > best_min) {
      best_min = current_min;
      undo_since_best_.clear();
    }
    // Stop rule: the best minimum rose by less than the tolerance over the last window of picks.
    bool stalled = false;
    if (sliding) {
      if (best_min - risen_min >= params_.sequential_improvement_tolerance) {
        risen_min = best_min;
        risen_pick = pick;
      }
      stalled = pick - risen_pick >= window;
    } else if (pick - window_start >= window) {
      stalled = best_min - window_start_min < params_.sequential_improvement_tolerance;
      window_start_min = best_min;
      window_start = pick;
    }
    if (pick % params_.sequential_cycle == 0 || stalled || pick == cap) {
      summary.reverted_nodes += cycle_reverts;
      context_.Report({phase_, pick, quality_min_.top_key(),
                       quality_sum_ / static_cast<double>(elements), 0, cycle_reverts,
                       context_.ElapsedSeconds(), false});
      cycle_reverts = 0;
    }
    if (pick % kCancelCheckInterval == 0 && context_.Cancelled()) {
      cancelled = true;
      break;
    }
    if (stalled) break;
  }
  summary.reverted_nodes += cycle_reverts;
  summary.iterations = pick;
  RestoreBest();
  const SmoothingContext::Summary state = context_.Summarize();
  context_.FinishPhase(summary, state, phase_start);
  if (cancelled) return absl::CancelledError("smoothing cancelled during the sequential substep");
  return summary;
}

}  // namespace

absl::StatusOr<PhaseSummary> RunSequential(SmoothingContext& context, SelectionCriterion criterion,
                                           SequentialStop stop) {
  return SequentialSubstep(context, criterion, stop).Run();
}

}  // namespace getme
