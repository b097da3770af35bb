#include "getme_surface/layer_heights.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "getme/elements/vec3.h"

namespace getme::surface {
namespace {}  // namespace

LayerHeights MeasureLayerHeights(const Mesh& mesh, const LayerColumns& columns,
                                 const WallDistance& walls, const KeptLayers& kept,
                                 std::span<const double> quality) {
  LayerHeights heights;
  heights.layers = columns.layers;
  heights.height.assign(mesh.node_count(), 0.0);
  std::vector<double> distance(mesh.node_count(), 0.0);
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    if (columns.level[node] >= 1) distance[node] = walls.Distance(NodePosition(mesh, node));
  }
  double first_sum = 0.0;
  double lean_sum = 0.0;
  std::int64_t leaning_edges = 0;
  heights.first_min = HUGE_VAL;
  heights.first_max = 0.0;
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    if (!columns.InLayer(node)) continue;
    const NodeId below = columns.below[node];
    const double height = distance[node] - distance[below];
    heights.height[node] = height;
    if (columns.level[node] == 1) {
      ++heights.columns;
      first_sum += height;
      heights.first_min = std::min(heights.first_min, height);
      heights.first_max = std::max(heights.first_max, height);
    }
  }
  for (std::int64_t c = 0; c < kept.column_count(); ++c) {
    Vec3 normal = SummedFaceNormal(mesh, kept.WallFaces(c));
    if (normal.dot(kept.direction[c]) < 0.0) normal = -normal;
    NodeId below = kept.wall[c];
    for (const NodeId node : kept.Nodes(c)) {
      const Vec3 up = NodePosition(mesh, node) - NodePosition(mesh, below);
      below = node;
      if (!(up.norm() > 0.0 && normal.norm() > 0.0)) continue;
      const double cosine = std::clamp(up.dot(normal) / (up.norm() * normal.norm()), -1.0, 1.0);
      lean_sum += std::acos(cosine) * 180.0 / std::numbers::pi;
      ++leaning_edges;
    }
  }
  if (heights.columns == 0) heights.first_min = 0.0;
  heights.first_mean = heights.columns > 0 ? first_sum / static_cast<double>(heights.columns) : 0.0;
  if (!columns.elements.empty()) {
    heights.q_min = 1.0;
    double sum = 0.0;
    for (const ElementId element : columns.elements) {
      const double q = std::max(quality[element], 0.0);
      heights.q_min = std::min(heights.q_min, q);
      sum += q;
    }
    heights.q_mean = sum / static_cast<double>(columns.elements.size());
  }
  heights.mean_lean_degrees =
      leaning_edges > 0 ? lean_sum / static_cast<double>(leaning_edges) : 0.0;
  return heights;
}

double MaxRelativeHeightChange(const LayerHeights& before, const LayerHeights& after) {
  double change = 0.0;
  for (std::size_t node = 0; node < before.height.size() && node < after.height.size(); ++node) {
    if (before.height[node] > 0.0) {
      change = std::max(change, std::abs(after.height[node] / before.height[node] - 1.0));
    }
  }
  return change;
}

}  // namespace getme::surface
