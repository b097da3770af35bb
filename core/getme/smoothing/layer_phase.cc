#include "getme/smoothing/layer_phase.h"

#include <algorithm>
#include <vector>

#include "absl/status/status.h"
#include "getme/elements/element_quality.h"
#include "getme/elements/vec3.h"

namespace getme {
namespace {

// Follow-wall sweeps stop as the polish does, when a sweep raises q_mean by less than
// polish_tolerance and q_min not at all, or after kMaxFollowSweeps: each sweep costs about one
// polish sweep over the column nodes, so the cap bounds the phase at a small part of a run.
constexpr int kMaxFollowSweeps = 30;

void Place(Mesh& mesh, NodeId node, const Vec3& p) {
  mesh.x()[node] = p[0];
  mesh.y()[node] = p[1];
  mesh.z()[node] = p[2];
}

enum class ColumnMove {
  kHeld,     // no node of the column may move (fixed, or on a held boundary)
  kMoved,    // a move, full or halved, was kept
  kRefused,  // every move tried lowered the quality around it or could not keep the heights
};

struct LocalQuality {
  double q_min = 1.0;
  double q_sum = 0.0;
  bool valid = true;
};

// Moves one column at a time and judges the move on the elements around it.
class ColumnMover {
 public:
  explicit ColumnMover(SmoothingContext& context)
      : context_(context), mesh_(context.mesh), layers_(*context.slide->kept_layers()) {}

  // Tries to put column `c`'s wall node at `wall_target` (itself, when it stays) and its nodes on
  // the straight line above it, halving the move on failure. A move must keep the elements
  // around the column valid, their q_min, and their q_mean (need_mean_gain: raise one of the
  // two).
  ColumnMove TryMove(std::int64_t c, const Vec3& wall_target, bool need_mean_gain) {
    const NodeId wall = layers_.wall[c];
    const BoundarySlide& slide = *context_.slide;
    moved_.clear();
    old_.clear();
    kept_index_.clear();
    // The wall node first (kept index -1), then the column nodes by their index in the
    // description: their line is known only once the wall node has landed.
    const auto add = [&](NodeId node, std::int64_t index) {
      if (!context_.column_movable[node]) return;
      moved_.push_back(node);
      old_.push_back(NodePosition(mesh_, node));
      kept_index_.push_back(index);
    };
    add(wall, -1);
    for (std::int64_t index = layers_.offsets[c]; index < layers_.offsets[c + 1]; ++index) {
      add(layers_.nodes[index], index);
    }
    if (moved_.empty()) return ColumnMove::kHeld;
    CollectElements();
    const LocalQuality before = Measure();
    double step = 1.0;
    for (int attempt = 0; attempt <= kLayerBacktrackingSteps; ++attempt, step *= 0.5) {
      const Vec3 wall_start = NodePosition(mesh_, wall);
      Vec3 wall_now = wall_start;
      Vec3 normal = ColumnNormal(c);
      bool kept_heights = true;
      for (std::size_t i = 0; i < moved_.size(); ++i) {
        const NodeId node = moved_[i];
        if (kept_index_[i] < 0) {
          wall_now = slide.Project(node, old_[i] + step * (wall_target - old_[i]), &old_[i]);
          Place(mesh_, node, wall_now);
          normal = ColumnNormal(c);
          continue;
        }
        // A halved move turns the node's ray only part of the way from where it leans now to
        // the normal; the node is still put at its wall distance on it.
        const Vec3 lean = old_[i] - wall_start;
        Vec3 ray = normal;
        if (step < 1.0 && lean.norm() > 0.0) {
          ray = lean.normalized() + step * (normal - lean.normalized());
          ray = ray.norm() > 0.0 ? Vec3(ray.normalized()) : normal;
        }
        const std::optional<Vec3> target = slide.OnColumn(kept_index_[i], wall_now, ray);
        if (!target) {
          kept_heights = false;
          break;
        }
        Place(mesh_, node, *target);
      }
      if (!kept_heights) {
        for (std::size_t i = 0; i < moved_.size(); ++i) Place(mesh_, moved_[i], old_[i]);
        continue;
      }
      const LocalQuality after = Measure();
      const bool q_min_held = after.valid && after.q_min >= before.q_min;
      const bool q_mean_held =
          need_mean_gain ? after.q_min > before.q_min || after.q_sum > before.q_sum * (1.0 + 1e-12)
                         : after.q_sum >= before.q_sum;
      if (q_min_held && q_mean_held) {
        for (ElementId e : elements_) context_.quality[e] = ElementQualityOrInvalid(mesh_, e);
        return ColumnMove::kMoved;
      }
    }
    for (std::size_t i = 0; i < moved_.size(); ++i) Place(mesh_, moved_[i], old_[i]);
    return ColumnMove::kRefused;
  }

 private:
  void CollectElements() {
    elements_.clear();
    for (NodeId node : moved_) {
      for (ElementId e : mesh_.node_elements(node)) elements_.push_back(e);
    }
    std::sort(elements_.begin(), elements_.end());
    elements_.erase(std::unique(elements_.begin(), elements_.end()), elements_.end());
  }

  // The unit normal of column c's wall faces where they are now, turned into the layers.
  Vec3 ColumnNormal(std::int64_t c) const {
    Vec3 normal = SummedFaceNormal(mesh_, layers_.WallFaces(c));
    if (normal.dot(layers_.direction[c]) < 0.0) normal = -normal;
    const double length = normal.norm();
    return length > 0.0 ? Vec3(normal / length) : layers_.direction[c];
  }

  LocalQuality Measure() const {
    LocalQuality local;
    for (ElementId e : elements_) {
      const double q = ElementQualityOrInvalid(mesh_, e);
      if (q == kInvalidQuality) local.valid = false;
      local.q_min = std::min(local.q_min, q);
      local.q_sum += q;
    }
    return local;
  }

  SmoothingContext& context_;
  Mesh& mesh_;
  const KeptLayers& layers_;
  std::vector<NodeId> moved_;
  std::vector<Vec3> old_;
  std::vector<std::int64_t> kept_index_;
  std::vector<ElementId> elements_;
};

}  // namespace

absl::StatusOr<PhaseSummary> RunLayers(SmoothingContext& context, LayerStage stage) {
  const double phase_start = context.ElapsedSeconds();
  const KeptLayers& layers = *context.slide->kept_layers();
  Mesh& mesh = context.mesh;
  ColumnMover mover(context);
  PhaseSummary summary{Phase::kLayers, 0, 0.0, 0.0, 0.0, 0};
  SmoothingContext::Summary state = context.Summarize();
  // One pass over the columns; returns how many moved.
  const auto pass = [&](bool follow_wall) -> absl::StatusOr<std::int64_t> {
    std::int64_t moved = 0;
    std::int64_t refused = 0;
    for (std::int64_t c = 0; c < layers.column_count(); ++c) {
      if (context.Cancelled()) return absl::CancelledError("smoothing cancelled");
      const NodeId wall = layers.wall[c];
      Vec3 target = NodePosition(mesh, wall);
      if (follow_wall) {
        const std::span<const NodeId> neighbours = layers.WallNeighbours(c);
        if (!context.column_movable[wall] || neighbours.empty()) continue;
        target = Vec3::Zero();
        for (NodeId n : neighbours) target += NodePosition(mesh, n);
        target /= static_cast<double>(neighbours.size());
      }
      const ColumnMove move = mover.TryMove(c, target, follow_wall);
      moved += move == ColumnMove::kMoved ? 1 : 0;
      refused += move == ColumnMove::kRefused ? 1 : 0;
    }
    ++summary.iterations;
    summary.reverted_nodes += refused;
    state = context.Summarize();
    context.Report({Phase::kLayers, summary.iterations, state.q_min, state.q_mean, state.invalid,
                    refused, context.ElapsedSeconds(), false});
    return moved;
  };
  if (stage == LayerStage::kStraighten) {
    // One pass: measured on the artery and the hexahedral layer block, more passes straighten
    // nothing more (a column refused once is refused again) and cost a pass each.
    if (absl::StatusOr<std::int64_t> moved = pass(false); !moved.ok()) return moved.status();
  } else {
    for (int sweep = 0; sweep < kMaxFollowSweeps; ++sweep) {
      const SmoothingContext::Summary last = state;
      absl::StatusOr<std::int64_t> moved = pass(true);
      if (!moved.ok()) return moved.status();
      if (*moved == 0 || (state.q_min <= last.q_min &&
                          state.q_mean - last.q_mean < context.params.polish_tolerance)) {
        break;
      }
    }
  }
  context.FinishPhase(summary, state, phase_start);
  return summary;
}

}  // namespace getme
