#include "getme/smoothing/simultaneous_iteration.h"

#include <algorithm>
#include <cmath>

#include "absl/container/flat_hash_map.h"
#include "getme/elements/transform.h"
#include "getme/elements/vec3.h"
#include "getme/parallel/block_loops.h"

namespace getme {
namespace {

// Nodes per ParallelFor chunk of the node pass: a node costs only its sums, so chunks are small
// enough that two threads get a dozen each on a 100k-element mesh (25k nodes).
constexpr std::int64_t kSimultaneousNodeGrain = 1024;

}  // namespace

SimultaneousIteration::SimultaneousIteration(const Mesh& mesh)
    : tiles_(mesh), node_sums_(mesh.node_count()) {
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

// Step 1 with Step 2's sums: transform every element (eq. 4 with the quality-dependent σ_j of
// Step 1.1), scale and relax it (Step 1.2), and add w_j·p'_{i,j} and w_j to its nodes' sums.
// Tiles of one colour share no node, so they run in parallel; colours run one after another, and
// the tiles that found no colour last, in order, on one thread. Every node so receives its
// contributions in the same order for every thread count (parallel/element_tiles.h).
void SimultaneousIteration::TransformAll(const SmoothingContext& context) {
  for (int c = 0; c < tiles_.colour_count(); ++c) {
    const std::span<const ElementTiles::Tile> tiles = tiles_.colour(c);
    context.pool.ParallelFor(static_cast<std::int64_t>(tiles.size()), 1,
                             [&](std::int64_t begin, std::int64_t end) {
                               for (std::int64_t t = begin; t < end; ++t) {
                                 TransformTile(context, tiles[t]);
                               }
                             });
  }
  for (const ElementTiles::Tile& tile : tiles_.serial()) TransformTile(context, tile);
}

// One tile, context.passes.lanes elements at a time (element_passes.h).
void SimultaneousIteration::TransformTile(const SmoothingContext& context,
                                          const ElementTiles::Tile& tile) {
  const Mesh& mesh = context.mesh;
  const SmoothingParams& params = context.params;
  const int type = TypeIndex(tile.type);
  TransformPassSettings settings;
  settings.sigma_min = params.simultaneous_sigma_min[type];
  settings.sigma_span = params.simultaneous_sigma_max[type] - settings.sigma_min;
  settings.rho = params.simultaneous_rho;
  settings.eta = params.simultaneous_eta;
  settings.quality = context.quality.data();
  // Written only at this tile's nodes, which no tile running meanwhile shares.
  settings.sums = node_sums_.data();
  context.passes.scatter_transform[type]({mesh.x(), mesh.y(), mesh.z(), tiles_.nodes(tile.type),
                                          tiles_.elements(tile.type), tile.begin, tile.end},
                                         settings);
}

// Step 2: p'_i = Σ w_j p'_{i,j} / Σ w_j, from the sums Step 1 left, which are then cleared for
// the next iteration. Every node's position is kept in previous_ on the way (Step 3 and the
// caller's best state need it).
void SimultaneousIteration::UpdateNodes(SmoothingContext& context) {
  context.pool.ParallelFor(
      context.mesh.node_count(), kSimultaneousNodeGrain,
      [&](std::int64_t begin, std::int64_t end) { UpdateNodeRange(context, begin, end); });
}

void SimultaneousIteration::UpdateNodeRange(SmoothingContext& context, std::int64_t begin,
                                            std::int64_t end) {
  Mesh& mesh = context.mesh;
  const auto x = mesh.x();
  const auto y = mesh.y();
  const auto z = mesh.z();
  for (std::int64_t node = begin; node < end; ++node) {
    previous_.x[node] = x[node];
    previous_.y[node] = y[node];
    previous_.z[node] = z[node];
    const NodeSum sum = node_sums_[node];
    node_sums_[node] = NodeSum{};
    // Σ w_j = 0: all adjacent elements are regular, the node is already optimal (Sec. 3.1).
    if (!context.movable[node] || !(sum.w > 0.0)) continue;
    const Vec3 placed =
        context.Placed(static_cast<NodeId>(node), Vec3(sum.x / sum.w, sum.y / sum.w, sum.z / sum.w),
                       Vec3(x[node], y[node], z[node]));
    x[node] = placed[0];
    y[node] = placed[1];
    z[node] = placed[2];
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
