#include "getme/smoothing/simultaneous_iteration.h"

#include <algorithm>
#include <cmath>

#include "absl/container/flat_hash_map.h"
#include "getme/elements/transform.h"
#include "getme/elements/vec3.h"
#include "getme/parallel/block_loops.h"

namespace getme {
namespace {

// Nodes per ParallelFor chunk of the node pass: a node costs only its corner sums, so chunks are
// small enough that two threads get a dozen each on a 100k-element mesh (25k nodes).
constexpr std::int64_t kNodeGrain = 1024;

// w_j = (1 − q_j)^η (Step 2.1). The paper's η = 1/4 (and 1/2, 1) as square roots, which act on
// whole lanes and are correctly rounded; other exponents through libm's pow, lane by lane.
Lanes WeightOfElement(Lanes defect, double eta) {
  if (eta == 0.25) return Sqrt(Sqrt(defect));
  if (eta == 0.5) return Sqrt(defect);
  if (eta == 1.0) return defect;
  Lanes weight;
  for (int l = 0; l < kLanes; ++l) weight[l] = std::pow(defect[l], eta);
  return weight;
}

}  // namespace

SimultaneousIteration::SimultaneousIteration(const Mesh& mesh)
    : corner_xyz_(3 * mesh.corner_count()), element_weight_(mesh.element_count()) {
  previous_.x.resize(mesh.node_count());
  previous_.y.resize(mesh.node_count());
  previous_.z.resize(mesh.node_count());
}

SimultaneousIteration::Outcome SimultaneousIteration::Run(SmoothingContext& context) {
  TransformAll(context);
  UpdateNodes(context);
  context.RefreshQuality();
  const SmoothingContext::Summary summary = context.Summarize();
  if (summary.invalid == 0) return {summary, 0};
  const std::int64_t reverted = RepairInvalid(context);
  return {context.Summarize(), reverted};
}

// Step 1: transform every element (eq. 4 with the quality-dependent σ_j of Step 1.1), scale and
// relax it (Step 1.2), and store its weighted new nodes w_j·p'_{i,j} per corner and w_j.
void SimultaneousIteration::TransformAll(const SmoothingContext& context) {
  ParallelForEachBlock(
      context.mesh, context.pool,
      [&]<ElementType kType>(const ElementBlock& block, std::int64_t begin, std::int64_t end) {
        TransformRange<kType>(context, block, begin, end);
      });
}

// Block entries [begin, end), kLanes elements at a time (lanes.h).
template <ElementType kType>
void SimultaneousIteration::TransformRange(const SmoothingContext& context,
                                           const ElementBlock& block, std::int64_t begin,
                                           std::int64_t end) {
  constexpr int kNodes = ElementTable<kType>::kNodes;
  const Mesh& mesh = context.mesh;
  const SmoothingParams& params = context.params;
  const double sigma_min = params.simultaneous_sigma_min[TypeIndex(kType)];
  const double sigma_span = params.simultaneous_sigma_max[TypeIndex(kType)] - sigma_min;
  const std::int64_t corner_base = mesh.corner_offset(kType);
  for (std::int64_t i = begin; i < end; i += kLanes) {
    const int count = static_cast<int>(std::min<std::int64_t>(kLanes, end - i));
    Lanes q{};
    for (int l = 0; l < kLanes; ++l) {
      q[l] = std::max(0.0, context.quality[block.elements[i + std::min(l, count - 1)]]);
    }
    const auto moved = RegularizingStep<kType, Lanes>(
        GatherLanes<kType>(mesh.x(), mesh.y(), mesh.z(), block.nodes.data() + i * kNodes, count),
        sigma_min + sigma_span * (1.0 - q), params.simultaneous_rho);
    const Lanes weights = WeightOfElement(1.0 - q, params.simultaneous_eta);
    for (int l = 0; l < count; ++l) {
      const double weight = weights[l];
      element_weight_[block.elements[i + l]] = weight;
      double* out = corner_xyz_.data() + 3 * (corner_base + (i + l) * kNodes);
      for (int k = 0; k < kNodes; ++k) {
        out[3 * k + 0] = weight * moved[k].x[l];
        out[3 * k + 1] = weight * moved[k].y[l];
        out[3 * k + 2] = weight * moved[k].z[l];
      }
    }
  }
}

// Step 2: p'_i = Σ w_j p'_{i,j} / Σ w_j over the node's elements, summed in the fixed corner
// order of the node's row so the result does not depend on the thread count. A node's corner row
// and element row list the same elements in the same (canonical) order, so the k-th corner
// belongs to the k-th element. Every node's position is kept in previous_ on the way (Step 3 and
// the caller's best state need it).
void SimultaneousIteration::UpdateNodes(SmoothingContext& context) {
  context.pool.ParallelFor(
      context.mesh.node_count(), kNodeGrain,
      [&](std::int64_t begin, std::int64_t end) { UpdateNodeRange(context, begin, end); });
}

void SimultaneousIteration::UpdateNodeRange(SmoothingContext& context, std::int64_t begin,
                                            std::int64_t end) {
  Mesh& mesh = context.mesh;
  const CompressedRows& corner_rows = mesh.node_corners();
  const auto x = mesh.x();
  const auto y = mesh.y();
  const auto z = mesh.z();
  for (std::int64_t node = begin; node < end; ++node) {
    previous_.x[node] = x[node];
    previous_.y[node] = y[node];
    previous_.z[node] = z[node];
    if (!context.movable[node]) continue;
    const std::span<const std::int32_t> corners = corner_rows.Row(node);
    const ElementId* elements = mesh.node_elements(node).data();
    double sx = 0.0, sy = 0.0, sz = 0.0, sw = 0.0;
    for (std::size_t k = 0; k < corners.size(); ++k) {
      const double* weighted = corner_xyz_.data() + 3 * static_cast<std::int64_t>(corners[k]);
      sw += element_weight_[elements[k]];
      sx += weighted[0];
      sy += weighted[1];
      sz += weighted[2];
    }
    // Σ w_j = 0: all adjacent elements are regular, the node is already optimal (Sec. 3.1).
    if (sw > 0.0) {
      const Vec3 placed = context.Placed(static_cast<NodeId>(node), Vec3(sx / sw, sy / sw, sz / sw),
                                         Vec3(x[node], y[node], z[node]));
      x[node] = placed[0];
      y[node] = placed[1];
      z[node] = placed[2];
    }
  }
}

// Step 3: while elements are invalid, move their nodes back. With backtracking (the thin-layer
// safeguard, docs/thin-layers.md) a node first retreats to half its step, then a quarter, ...,
// and only after `backtracking_steps` halvings all the way to p_old (the paper's literal rule).
// Terminates: an element whose nodes are all back at p_old is the previous, valid element.
// Invalid elements are rare, so the nodes it touches are kept in a map, not per-node arrays.
std::int64_t SimultaneousIteration::RepairInvalid(SmoothingContext& context) {
  Mesh& mesh = context.mesh;
  auto x = mesh.x();
  auto y = mesh.y();
  auto z = mesh.z();
  const int max_halvings = context.params.simultaneous_backtracking_steps;
  struct TouchedNode {
    int halvings = 0;
    double new_x = 0.0, new_y = 0.0, new_z = 0.0;  // p_new of Step 2
  };
  absl::flat_hash_map<NodeId, TouchedNode> touched;
  std::vector<ElementId> invalid;
  for (std::int64_t e = 0; e < mesh.element_count(); ++e) {
    if (context.quality[e] < 0.0) invalid.push_back(static_cast<ElementId>(e));
  }
  std::int64_t reverted = 0;
  std::vector<NodeId> moved_back;
  std::vector<ElementId> recheck;
  while (!invalid.empty()) {
    moved_back.clear();
    for (ElementId element : invalid) {
      for (NodeId node : mesh.element_nodes(element)) {
        if (!context.movable[node]) continue;
        // First touched: the node still stands where Step 2 put it.
        const auto [it, first] =
            touched.try_emplace(node, TouchedNode{0, x[node], y[node], z[node]});
        TouchedNode& state = it->second;
        if (state.halvings > max_halvings) continue;
        if (first) ++reverted;
        ++state.halvings;
        moved_back.push_back(node);
      }
    }
    std::sort(moved_back.begin(), moved_back.end());
    moved_back.erase(std::unique(moved_back.begin(), moved_back.end()), moved_back.end());
    recheck.clear();
    for (NodeId node : moved_back) {
      TouchedNode& state = touched.at(node);
      // halvings h ≤ max: keep 2^-h of the step; h = max + 1: back to p_old.
      const double keep = state.halvings > max_halvings ? 0.0 : std::ldexp(1.0, -state.halvings);
      x[node] = previous_.x[node] + keep * (state.new_x - previous_.x[node]);
      y[node] = previous_.y[node] + keep * (state.new_y - previous_.y[node]);
      z[node] = previous_.z[node] + keep * (state.new_z - previous_.z[node]);
      // A sliding node's part-way point is off a curved surface: back onto it. Not at keep = 0,
      // where the node must be exactly at p_old for the repair to end with a valid element.
      if (keep > 0.0 && context.sliding[node]) {
        const Vec3 placed =
            context.Placed(node, Vec3(x[node], y[node], z[node]),
                           Vec3(previous_.x[node], previous_.y[node], previous_.z[node]));
        x[node] = placed[0];
        y[node] = placed[1];
        z[node] = placed[2];
      }
      if (keep == 0.0) state.halvings = max_halvings + 1;
      const auto elements = mesh.node_elements(node);
      recheck.insert(recheck.end(), elements.begin(), elements.end());
    }
    std::sort(recheck.begin(), recheck.end());
    recheck.erase(std::unique(recheck.begin(), recheck.end()), recheck.end());
    invalid.clear();
    for (ElementId element : recheck) {
      context.quality[element] = ElementQualityOrInvalid(mesh, element);
      if (context.quality[element] < 0.0) invalid.push_back(element);
    }
  }
  return reverted;
}

}  // namespace getme
