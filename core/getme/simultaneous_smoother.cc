#include "getme/simultaneous_smoother.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "getme/block_loops.h"
#include "getme/transform.h"
#include "getme/vec3.h"

namespace getme {
namespace {

constexpr std::int64_t kNodeGrain = 4096;

struct Coordinates {
  std::vector<double> x, y, z;

  void CopyFrom(const Mesh& mesh) {
    x.assign(mesh.x().begin(), mesh.x().end());
    y.assign(mesh.y().begin(), mesh.y().end());
    z.assign(mesh.z().begin(), mesh.z().end());
  }
  void CopyTo(Mesh& mesh) const {
    std::copy(x.begin(), x.end(), mesh.x().begin());
    std::copy(y.begin(), y.end(), mesh.y().begin());
    std::copy(z.begin(), z.end(), mesh.z().begin());
  }
};

// Step 1: transform every element (eq. 4 with the quality-dependent σ_j of Step 1.1), scale and
// relax it (Step 1.2), and store its weighted new nodes w_j·p'_{i,j} per corner and w_j.
void TransformAll(const SmoothingContext& context, std::vector<double>& corner_xyz,
                  std::vector<double>& element_weight) {
  const Mesh& mesh = context.mesh;
  const SmoothingParams& params = context.params;
  ParallelForEachBlock(
      mesh, context.pool,
      [&]<ElementType kType>(const ElementBlock& block, std::int64_t begin, std::int64_t end) {
        constexpr int kNodes = ElementTable<kType>::kNodes;
        const int t = TypeIndex(kType);
        const double sigma_min = params.simultaneous_sigma_min[t];
        const double sigma_span = params.simultaneous_sigma_max[t] - sigma_min;
        const std::int64_t corner_base = mesh.corner_offset(kType);
        for (std::int64_t i = begin; i < end; ++i) {
          const ElementId element = block.elements[i];
          const double q = std::max(0.0, context.quality[element]);
          const auto nodes = GatherNodes<kType>(mesh, block.nodes.data() + i * kNodes);
          const auto moved = RegularizingStep<kType>(nodes, sigma_min + sigma_span * (1.0 - q),
                                                     params.simultaneous_rho);
          const double weight = std::pow(1.0 - q, params.simultaneous_eta);
          element_weight[element] = weight;
          double* out = corner_xyz.data() + 3 * (corner_base + i * kNodes);
          for (int k = 0; k < kNodes; ++k) {
            out[3 * k + 0] = weight * moved[k].x();
            out[3 * k + 1] = weight * moved[k].y();
            out[3 * k + 2] = weight * moved[k].z();
          }
        }
      });
}

// The element owning a corner (corner numbering of Mesh::node_corners).
ElementId CornerElement(const Mesh& mesh, std::int64_t corner) {
  for (int t = kElementTypeCount - 1; t >= 0; --t) {
    const auto type = static_cast<ElementType>(t);
    const std::int64_t offset = mesh.corner_offset(type);
    if (corner >= offset && mesh.element_count(type) > 0) {
      return mesh.block(type).elements[(corner - offset) / NodeCount(type)];
    }
  }
  return 0;
}

// Step 2: p'_i = Σ w_j p'_{i,j} / Σ w_j over the node's elements, summed in the fixed corner
// order of the node's row so the result does not depend on the thread count.
void UpdateNodes(SmoothingContext& context, const std::vector<double>& corner_xyz,
                 const std::vector<double>& element_weight) {
  Mesh& mesh = context.mesh;
  const CompressedRows& rows = mesh.node_corners();
  auto x = mesh.x();
  auto y = mesh.y();
  auto z = mesh.z();
  context.pool.ParallelFor(mesh.node_count(), kNodeGrain,
                           [&](std::int64_t begin, std::int64_t end) {
                             for (std::int64_t node = begin; node < end; ++node) {
                               if (!context.movable[node]) continue;
                               double sx = 0.0, sy = 0.0, sz = 0.0, sw = 0.0;
                               for (std::int32_t corner : rows.Row(node)) {
                                 sw += element_weight[CornerElement(mesh, corner)];
                                 sx += corner_xyz[3 * static_cast<std::int64_t>(corner) + 0];
                                 sy += corner_xyz[3 * static_cast<std::int64_t>(corner) + 1];
                                 sz += corner_xyz[3 * static_cast<std::int64_t>(corner) + 2];
                               }
                               // Σ w_j = 0: all adjacent elements are regular, the node is already
                               // optimal (Sec. 3.1).
                               if (sw > 0.0) {
                                 x[node] = sx / sw;
                                 y[node] = sy / sw;
                                 z[node] = sz / sw;
                               }
                             }
                           });
}

// Step 3: while elements are invalid, move their nodes back. With backtracking (the thin-layer
// safeguard, docs/thin-layers.md) a node first retreats to half its step, then a quarter, ...,
// and only after `backtracking_steps` halvings all the way to p_old (the paper's literal rule).
// Terminates: an element whose nodes are all back at p_old is the previous, valid element.
std::int64_t RepairInvalid(SmoothingContext& context, const Coordinates& old_position,
                           const Coordinates& new_position, std::vector<std::uint8_t>& halvings,
                           std::vector<std::uint8_t>& element_mark) {
  Mesh& mesh = context.mesh;
  auto x = mesh.x();
  auto y = mesh.y();
  auto z = mesh.z();
  const int max_halvings = context.params.simultaneous_backtracking_steps;
  std::vector<ElementId> invalid;
  for (std::int64_t e = 0; e < mesh.element_count(); ++e) {
    if (context.quality[e] < 0.0) invalid.push_back(static_cast<ElementId>(e));
  }
  std::fill(halvings.begin(), halvings.end(), 0);
  std::int64_t reverted = 0;
  std::vector<NodeId> moved_back;
  std::vector<ElementId> recheck;
  while (!invalid.empty()) {
    moved_back.clear();
    for (ElementId element : invalid) {
      for (NodeId node : mesh.element_nodes(element)) {
        if (!context.movable[node] || halvings[node] > max_halvings) continue;
        if (halvings[node] == 0) ++reverted;
        halvings[node] = static_cast<std::uint8_t>(halvings[node] + 1);
        moved_back.push_back(node);
      }
    }
    std::sort(moved_back.begin(), moved_back.end());
    moved_back.erase(std::unique(moved_back.begin(), moved_back.end()), moved_back.end());
    recheck.clear();
    for (NodeId node : moved_back) {
      // halvings h ≤ max: keep 2^-h of the step; h = max + 1: back to p_old.
      const double keep =
          halvings[node] > max_halvings ? 0.0 : std::ldexp(1.0, -static_cast<int>(halvings[node]));
      x[node] = old_position.x[node] + keep * (new_position.x[node] - old_position.x[node]);
      y[node] = old_position.y[node] + keep * (new_position.y[node] - old_position.y[node]);
      z[node] = old_position.z[node] + keep * (new_position.z[node] - old_position.z[node]);
      if (keep == 0.0) halvings[node] = static_cast<std::uint8_t>(max_halvings + 1);
      for (ElementId element : mesh.node_elements(node)) {
        if (!element_mark[element]) {
          element_mark[element] = 1;
          recheck.push_back(element);
        }
      }
    }
    invalid.clear();
    for (ElementId element : recheck) {
      element_mark[element] = 0;
      context.quality[element] = ElementQualityOrInvalid(mesh, element);
      if (context.quality[element] < 0.0) invalid.push_back(element);
    }
    std::sort(invalid.begin(), invalid.end());
  }
  return reverted;
}

}  // namespace

absl::StatusOr<PhaseSummary> RunSimultaneous(SmoothingContext& context) {
  Mesh& mesh = context.mesh;
  const SmoothingParams& params = context.params;
  const double phase_start = context.ElapsedSeconds();
  std::vector<double> corner_xyz(3 * mesh.corner_count());
  std::vector<double> element_weight(mesh.element_count());
  std::vector<std::uint8_t> halvings(mesh.node_count());
  std::vector<std::uint8_t> element_mark(mesh.element_count());
  Coordinates old_position, new_position, best_position;

  SmoothingContext::Summary current = context.Summarize();
  PhaseSummary summary{Phase::kSimultaneous, 0, 0.0, current.q_min, current.q_mean, 0};
  double best_q_mean = current.q_mean;
  std::int64_t best_iteration = 0;
  best_position.CopyFrom(mesh);
  bool cancelled = false;

  for (std::int64_t iteration = 1; iteration <= params.simultaneous_max_iterations; ++iteration) {
    if (context.Cancelled()) {
      cancelled = true;
      break;
    }
    old_position.CopyFrom(mesh);
    TransformAll(context, corner_xyz, element_weight);
    UpdateNodes(context, corner_xyz, element_weight);
    new_position.CopyFrom(mesh);
    context.RefreshQuality();
    const std::int64_t reverted =
        RepairInvalid(context, old_position, new_position, halvings, element_mark);
    summary.reverted_nodes += reverted;

    const double previous_q_mean = current.q_mean;
    current = context.Summarize();
    summary.iterations = iteration;
    if (current.q_mean > best_q_mean) {
      best_q_mean = current.q_mean;
      best_iteration = iteration;
      best_position.CopyFrom(mesh);
    }
    const bool converged =
        std::abs(current.q_mean - previous_q_mean) < params.simultaneous_tolerance;
    const bool last = converged || iteration == params.simultaneous_max_iterations;
    context.Report({Phase::kSimultaneous, iteration, current.q_min, current.q_mean, current.invalid,
                    reverted, context.ElapsedSeconds(), false});
    if (last) break;
  }

  // Hand on the best-q_mean state, not merely the last one (NOTES.md §5).
  if (best_iteration != summary.iterations) {
    best_position.CopyTo(mesh);
    context.RefreshQuality();
    current = context.Summarize();
  }
  context.FinishPhase(summary, current, phase_start);
  if (cancelled) return absl::CancelledError("smoothing cancelled during the simultaneous substep");
  return summary;
}

}  // namespace getme
