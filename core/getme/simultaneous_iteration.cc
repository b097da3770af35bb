#include "getme/simultaneous_iteration.h"

#include <algorithm>
#include <cmath>

#include "getme/block_loops.h"
#include "getme/transform.h"
#include "getme/vec3.h"

namespace getme {
namespace {

constexpr std::int64_t kNodeGrain = 4096;

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

}  // namespace

void SimultaneousIteration::Coordinates::CopyFrom(const Mesh& mesh) {
  x.assign(mesh.x().begin(), mesh.x().end());
  y.assign(mesh.y().begin(), mesh.y().end());
  z.assign(mesh.z().begin(), mesh.z().end());
}

SimultaneousIteration::SimultaneousIteration(const Mesh& mesh)
    : corner_xyz_(3 * mesh.corner_count()),
      element_weight_(mesh.element_count()),
      halvings_(mesh.node_count()),
      element_mark_(mesh.element_count()) {}

SimultaneousIteration::Outcome SimultaneousIteration::Run(SmoothingContext& context) {
  old_position_.CopyFrom(context.mesh);
  TransformAll(context);
  UpdateNodes(context);
  new_position_.CopyFrom(context.mesh);
  context.RefreshQuality();
  const std::int64_t reverted = RepairInvalid(context);
  return {context.Summarize(), reverted};
}

// Step 1: transform every element (eq. 4 with the quality-dependent σ_j of Step 1.1), scale and
// relax it (Step 1.2), and store its weighted new nodes w_j·p'_{i,j} per corner and w_j.
void SimultaneousIteration::TransformAll(const SmoothingContext& context) {
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
          element_weight_[element] = weight;
          double* out = corner_xyz_.data() + 3 * (corner_base + i * kNodes);
          for (int k = 0; k < kNodes; ++k) {
            out[3 * k + 0] = weight * moved[k].x();
            out[3 * k + 1] = weight * moved[k].y();
            out[3 * k + 2] = weight * moved[k].z();
          }
        }
      });
}

// Step 2: p'_i = Σ w_j p'_{i,j} / Σ w_j over the node's elements, summed in the fixed corner
// order of the node's row so the result does not depend on the thread count.
void SimultaneousIteration::UpdateNodes(SmoothingContext& context) {
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
                                 sw += element_weight_[CornerElement(mesh, corner)];
                                 sx += corner_xyz_[3 * static_cast<std::int64_t>(corner) + 0];
                                 sy += corner_xyz_[3 * static_cast<std::int64_t>(corner) + 1];
                                 sz += corner_xyz_[3 * static_cast<std::int64_t>(corner) + 2];
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
std::int64_t SimultaneousIteration::RepairInvalid(SmoothingContext& context) {
  Mesh& mesh = context.mesh;
  auto x = mesh.x();
  auto y = mesh.y();
  auto z = mesh.z();
  const int max_halvings = context.params.simultaneous_backtracking_steps;
  std::vector<ElementId> invalid;
  for (std::int64_t e = 0; e < mesh.element_count(); ++e) {
    if (context.quality[e] < 0.0) invalid.push_back(static_cast<ElementId>(e));
  }
  std::fill(halvings_.begin(), halvings_.end(), 0);
  std::int64_t reverted = 0;
  std::vector<NodeId> moved_back;
  std::vector<ElementId> recheck;
  while (!invalid.empty()) {
    moved_back.clear();
    for (ElementId element : invalid) {
      for (NodeId node : mesh.element_nodes(element)) {
        if (!context.movable[node] || halvings_[node] > max_halvings) continue;
        if (halvings_[node] == 0) ++reverted;
        halvings_[node] = static_cast<std::uint8_t>(halvings_[node] + 1);
        moved_back.push_back(node);
      }
    }
    std::sort(moved_back.begin(), moved_back.end());
    moved_back.erase(std::unique(moved_back.begin(), moved_back.end()), moved_back.end());
    recheck.clear();
    for (NodeId node : moved_back) {
      // halvings h ≤ max: keep 2^-h of the step; h = max + 1: back to p_old.
      const double keep = halvings_[node] > max_halvings
                              ? 0.0
                              : std::ldexp(1.0, -static_cast<int>(halvings_[node]));
      x[node] = old_position_.x[node] + keep * (new_position_.x[node] - old_position_.x[node]);
      y[node] = old_position_.y[node] + keep * (new_position_.y[node] - old_position_.y[node]);
      z[node] = old_position_.z[node] + keep * (new_position_.z[node] - old_position_.z[node]);
      if (keep == 0.0) halvings_[node] = static_cast<std::uint8_t>(max_halvings + 1);
      for (ElementId element : mesh.node_elements(node)) {
        if (!element_mark_[element]) {
          element_mark_[element] = 1;
          recheck.push_back(element);
        }
      }
    }
    invalid.clear();
    for (ElementId element : recheck) {
      element_mark_[element] = 0;
      context.quality[element] = ElementQualityOrInvalid(mesh, element);
      if (context.quality[element] < 0.0) invalid.push_back(element);
    }
    std::sort(invalid.begin(), invalid.end());
  }
  return reverted;
}

}  // namespace getme
