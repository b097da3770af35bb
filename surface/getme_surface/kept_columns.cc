#include "getme_surface/kept_columns.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "getme/elements/vec3.h"

namespace getme::surface {
namespace {

// Rounds of the correction of a node's distance along its column: where the ray leans from the
// nearest wall face's normal by θ, the wall distance grows as cos θ times the distance along it,
// which the first round matches exactly while the nearest face stays the same; the second
// catches a nearest face that changed with it.
constexpr int kDistanceRounds = 2;

}  // namespace

Vec3 AlongToWallDistance(const WallDistance& walls, const Vec3& from, const Vec3& direction,
                         double along, double distance) {
  for (int round = 0; round < kDistanceRounds; ++round) {
    const double reached = walls.Distance(from + along * direction);
    if (!(reached > 0.0)) break;
    along *= distance / reached;
  }
  return from + along * direction;
}

KeptLayers DescribeKeptLayers(const Mesh& mesh, const LayerColumns& layers,
                              const WallDistance& walls) {
  const std::int64_t node_count = mesh.node_count();
  // Each node's wall node, through nodes that are all in one column only; -1 otherwise.
  std::vector<NodeId> root(node_count, -1);
  std::vector<std::pair<std::int32_t, NodeId>> by_level;
  for (NodeId node = 0; node < node_count; ++node) {
    if (layers.level[node] >= 0) by_level.emplace_back(layers.level[node], node);
  }
  std::sort(by_level.begin(), by_level.end());
  for (const auto& [level, node] : by_level) {
    if (layers.conflict[node]) continue;
    root[node] = level == 0 ? node : root[layers.below[node]];
  }
  // Columns by wall node, nodes by level.
  std::vector<std::pair<NodeId, std::pair<std::int32_t, NodeId>>> chains;
  for (const auto& [level, node] : by_level) {
    if (level >= 1 && root[node] >= 0) chains.push_back({root[node], {level, node}});
  }
  std::sort(chains.begin(), chains.end());

  // Per wall node: its wall faces and its neighbours along their edges.
  std::vector<std::vector<std::size_t>> faces_at(node_count);
  std::vector<std::vector<NodeId>> neighbours(node_count);
  for (std::size_t f = 0; f < layers.wall_faces.size(); ++f) {
    const std::array<NodeId, 4>& face = layers.wall_faces[f];
    const int size = layers.wall_face_sizes[f];
    for (int k = 0; k < size; ++k) {
      faces_at[face[k]].push_back(f);
      neighbours[face[k]].push_back(face[(k + 1) % size]);
      neighbours[face[k]].push_back(face[(k + size - 1) % size]);
    }
  }

  KeptLayers kept;
  for (std::size_t i = 0; i < chains.size();) {
    const NodeId wall = chains[i].first;
    const Vec3 base = NodePosition(mesh, wall);
    const Vec3 first_up = NodePosition(mesh, chains[i].second.second) - base;
    for (const std::size_t f : faces_at[wall]) {
      const std::array<NodeId, 4>& face = layers.wall_faces[f];
      kept.wall_faces.insert(kept.wall_faces.end(), face.begin(), face.end());
      if (layers.wall_face_sizes[f] == 3) kept.wall_faces.back() = -1;
    }
    kept.face_offsets.push_back(static_cast<std::int64_t>(kept.wall_faces.size() / 4));
    Vec3 direction = SummedFaceNormal(mesh, kept.WallFaces(kept.column_count()));
    if (direction.dot(first_up) < 0.0) direction = -direction;
    direction = direction.norm() > 0.0 ? Vec3(direction.normalized()) : Vec3(first_up.normalized());
    kept.wall.push_back(wall);
    kept.direction.push_back(direction);
    for (; i < chains.size() && chains[i].first == wall; ++i) {
      const NodeId node = chains[i].second.second;
      const double target = walls.Distance(NodePosition(mesh, node));
      kept.nodes.push_back(node);
      kept.distance.push_back(
          (AlongToWallDistance(walls, base, direction, target, target) - base).dot(direction));
    }
    kept.offsets.push_back(static_cast<std::int64_t>(kept.nodes.size()));
    std::vector<NodeId>& around = neighbours[wall];
    std::sort(around.begin(), around.end());
    around.erase(std::unique(around.begin(), around.end()), around.end());
    kept.wall_neighbours.insert(kept.wall_neighbours.end(), around.begin(), around.end());
    kept.wall_offsets.push_back(static_cast<std::int64_t>(kept.wall_neighbours.size()));
  }
  return kept;
}

}  // namespace getme::surface
