#include "getme/meshgen/boundary_layers.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "absl/container/flat_hash_map.h"
#include "absl/container/flat_hash_set.h"
#include "absl/strings/str_cat.h"
#include "getme/elements/element_quality.h"

namespace getme::meshgen {
namespace {

constexpr int kNotOnCap = -1;

Vec3 Normalised(const Vec3& v) {
  const double length = v.norm();
  return length > 0.0 ? Vec3(v / length) : v;
}

// Removes the component along the unit `normal`: the vector then lies in the cap plane.
Vec3 InPlane(const Vec3& v, const Vec3& normal) { return v - v.dot(normal) * normal; }

// Node adjacency of the tetrahedra (edges), compressed rows.
struct Adjacency {
  std::vector<std::int64_t> offsets;
  std::vector<NodeId> neighbours;
};

Adjacency TetEdges(const MeshDraft& draft, std::int64_t nodes) {
  std::vector<std::pair<NodeId, NodeId>> edges;
  for (ElementId e = 0; e < draft.element_count(); ++e) {
    const auto n = draft.element_nodes(e);
    for (std::size_t i = 0; i < n.size(); ++i) {
      for (std::size_t j = 0; j < n.size(); ++j) {
        if (i != j) edges.emplace_back(n[i], n[j]);
      }
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  Adjacency adjacency;
  adjacency.offsets.assign(nodes + 1, 0);
  for (const auto& [a, b] : edges) ++adjacency.offsets[a + 1];
  for (std::int64_t i = 0; i < nodes; ++i) adjacency.offsets[i + 1] += adjacency.offsets[i];
  adjacency.neighbours.reserve(edges.size());
  for (const auto& edge : edges) adjacency.neighbours.push_back(edge.second);
  return adjacency;
}

}  // namespace

double LayerOffset(double first_layer_height, double growth_ratio, int k) {
  if (growth_ratio == 1.0) return first_layer_height * k;
  return first_layer_height * (std::pow(growth_ratio, k) - 1.0) / (growth_ratio - 1.0);
}

absl::StatusOr<BoundaryLayerReport> GrowBoundaryLayers(
    MeshDraft& draft, std::span<const std::array<NodeId, 3>> wall,
    std::span<const std::vector<std::array<NodeId, 3>>> caps, std::span<const CapPlane> planes,
    const BoundaryLayerOptions& options) {
  if (caps.size() != planes.size()) {
    return absl::InvalidArgumentError("GrowBoundaryLayers: one plane per cap");
  }
  if (options.inward_layers < 0 || options.outward_layers < 0 ||
      !(options.first_layer_height > 0.0) || !(options.growth_ratio > 0.0)) {
    return absl::InvalidArgumentError(
        "GrowBoundaryLayers: layers must be >= 0, first_layer_height and growth_ratio > 0");
  }
  const std::int64_t tet_nodes = draft.node_count();
  const std::int64_t tets = draft.element_count();

  // Wall vertices in order of first appearance, their neighbours on the wall, area-weighted
  // normals.
  absl::flat_hash_map<NodeId, int> vertex_index;
  std::vector<NodeId> vertices;
  std::vector<Vec3> normals;
  std::vector<std::pair<int, int>> wall_edges;
  for (const auto& triangle : wall) {
    const Vec3 a = draft.node(triangle[0]);
    const Vec3 weighted = (draft.node(triangle[1]) - a).cross(draft.node(triangle[2]) - a);
    std::array<int, 3> index;
    for (int k = 0; k < 3; ++k) {
      const auto [it, inserted] =
          vertex_index.try_emplace(triangle[k], static_cast<int>(vertices.size()));
      if (inserted) {
        vertices.push_back(triangle[k]);
        normals.push_back(Vec3::Zero());
      }
      normals[it->second] += weighted;
      index[k] = it->second;
    }
    for (int k = 0; k < 3; ++k) wall_edges.push_back(std::minmax(index[k], index[(k + 1) % 3]));
  }
  std::sort(wall_edges.begin(), wall_edges.end());
  wall_edges.erase(std::unique(wall_edges.begin(), wall_edges.end()), wall_edges.end());
  const std::size_t count = vertices.size();

  // Which cap plane each node lies on (rim vertices of the wall included).
  std::vector<int> cap_of(tet_nodes, kNotOnCap);
  for (std::size_t c = 0; c < caps.size(); ++c) {
    for (const auto& triangle : caps[c]) {
      for (const NodeId node : triangle) cap_of[node] = static_cast<int>(c);
    }
  }
  const auto keep_on_cap = [&](std::size_t v) {
    const int cap = cap_of[vertices[v]];
    if (cap != kNotOnCap) normals[v] = InPlane(normals[v], planes[cap].normal);
    normals[v] = Normalised(normals[v]);
  };
  for (std::size_t v = 0; v < count; ++v) keep_on_cap(v);
  const std::vector<Vec3> area_normals = normals;
  for (int sweep = 0; sweep < options.normal_smoothing_iterations; ++sweep) {
    std::vector<Vec3> sum = normals;
    for (const auto& [a, b] : wall_edges) {
      sum[a] += normals[b];
      sum[b] += normals[a];
    }
    normals = std::move(sum);
    for (std::size_t v = 0; v < count; ++v) keep_on_cap(v);
  }
  // Smoothing can tilt a normal past a face it belongs to (at a branch junction's crease, on a
  // coarse wall): then no layer height gives a valid prism over that face. Such a normal is
  // blended back towards the area-weighted one, and if even that is not enough, tilted towards
  // the worst face's normal until it sees every face at kMinNormalDot or more.
  std::vector<std::vector<Vec3>> face_normals(count);
  for (const auto& triangle : wall) {
    const Vec3 a = draft.node(triangle[0]);
    const Vec3 n = Normalised((draft.node(triangle[1]) - a).cross(draft.node(triangle[2]) - a));
    for (const NodeId node : triangle) face_normals[vertex_index.at(node)].push_back(n);
  }
  const auto worst_face = [&](std::size_t v, const Vec3& normal) {
    std::size_t worst = 0;
    for (std::size_t f = 1; f < face_normals[v].size(); ++f) {
      if (face_normals[v][f].dot(normal) < face_normals[v][worst].dot(normal)) worst = f;
    }
    return face_normals[v][worst];
  };
  constexpr double kMinNormalDot = 0.2;
  for (std::size_t v = 0; v < count; ++v) {
    if (worst_face(v, normals[v]).dot(normals[v]) >= kMinNormalDot) continue;
    const Vec3 smoothed = normals[v];
    for (const double w : {0.25, 0.5, 0.75, 1.0}) {
      normals[v] = (1.0 - w) * smoothed + w * area_normals[v];
      keep_on_cap(v);
      if (worst_face(v, normals[v]).dot(normals[v]) >= kMinNormalDot) break;
    }
    for (int step = 0; step < 50; ++step) {
      const Vec3 face = worst_face(v, normals[v]);
      const double dot = face.dot(normals[v]);
      if (dot >= kMinNormalDot) break;
      normals[v] += (kMinNormalDot - dot + 0.05) * face;
      keep_on_cap(v);
    }
  }
  for (std::size_t v = 0; v < count; ++v) {
    if (!(normals[v].norm() > 0.5)) {
      return absl::InternalError(absl::StrCat("GrowBoundaryLayers: wall node ", vertices[v],
                                              " has no normal (its triangles cancel out)"));
    }
  }

  const int inward = options.inward_layers, outward = options.outward_layers;
  const double first = options.first_layer_height, growth = options.growth_ratio;
  std::vector<Vec3> wall_position(count);
  for (std::size_t v = 0; v < count; ++v) wall_position[v] = draft.node(vertices[v]);
  std::vector<Vec3> original(tet_nodes);
  for (NodeId node = 0; node < tet_nodes; ++node) original[node] = draft.node(node);
  std::vector<char> on_wall(tet_nodes, 0);
  for (const NodeId node : vertices) on_wall[node] = 1;
  const Adjacency adjacency = TetEdges(draft, tet_nodes);

  // Stack scales: 1 as requested, halved where something came out invalid.
  std::vector<double> inward_scale(count, 1.0), outward_scale(count, 1.0);
  // Position of vertex v's node on inward layer boundary j (0: the pushed tetrahedra's wall,
  // `inward`: the original wall) and on outward boundary k (0: the wall).
  const auto inward_node = [&](std::size_t v, int j) -> Vec3 {
    return wall_position[v] - inward_scale[v] * LayerOffset(first, growth, inward - j) * normals[v];
  };
  const auto outward_node = [&](std::size_t v, int k) -> Vec3 {
    return wall_position[v] + outward_scale[v] * LayerOffset(first, growth, k) * normals[v];
  };

  BoundaryLayerReport report;
  report.wall_vertices = static_cast<std::int64_t>(count);
  std::vector<Vec3> move(tet_nodes), next(tet_nodes);
  for (int round = 0;; ++round) {
    // Push the wall in and spread the push into the tetrahedra.
    std::fill(move.begin(), move.end(), Vec3::Zero());
    for (std::size_t v = 0; v < count; ++v) {
      move[vertices[v]] = inward_node(v, 0) - wall_position[v];
    }
    for (int sweep = 0; sweep < options.displacement_iterations && inward > 0; ++sweep) {
      for (NodeId node = 0; node < tet_nodes; ++node) {
        if (on_wall[node]) {
          next[node] = move[node];
          continue;
        }
        Vec3 sum = Vec3::Zero();
        const std::int64_t begin = adjacency.offsets[node], end = adjacency.offsets[node + 1];
        for (std::int64_t i = begin; i < end; ++i) sum += move[adjacency.neighbours[i]];
        next[node] = end > begin ? Vec3(sum / static_cast<double>(end - begin)) : Vec3::Zero();
        if (cap_of[node] != kNotOnCap) {
          next[node] = InPlane(next[node], planes[cap_of[node]].normal);
        }
      }
      std::swap(move, next);
    }
    for (NodeId node = 0; node < tet_nodes; ++node)
      draft.set_node(node, original[node] + move[node]);

    // Check the moved tetrahedra and the prisms to be built; thin the stacks at invalid ones.
    std::vector<char> thin_inward(count, 0), thin_outward(count, 0);
    bool any_invalid = false;
    std::int64_t invalid_tets = 0, invalid_inward = 0, invalid_outward = 0;
    for (ElementId e = 0; e < tets; ++e) {
      if (draft.IsElementValid(e)) continue;
      any_invalid = true;
      ++invalid_tets;
      bool marked = false;
      for (const NodeId node : draft.element_nodes(e)) {
        if (on_wall[node]) {
          thin_inward[vertex_index.at(node)] = 1;
          marked = true;
        }
      }
      if (marked) continue;
      // No wall node: the push reached it through its neighbours, from wall nodes at most
      // displacement_iterations edges away; thin all of those.
      std::vector<NodeId> front(draft.element_nodes(e).begin(), draft.element_nodes(e).end());
      absl::flat_hash_set<NodeId> seen(front.begin(), front.end());
      for (int hop = 0; hop < options.displacement_iterations && !front.empty(); ++hop) {
        std::vector<NodeId> next_front;
        for (const NodeId node : front) {
          for (std::int64_t i = adjacency.offsets[node]; i < adjacency.offsets[node + 1]; ++i) {
            const NodeId neighbour = adjacency.neighbours[i];
            if (!seen.insert(neighbour).second) continue;
            if (on_wall[neighbour]) {
              thin_inward[vertex_index.at(neighbour)] = 1;
            } else {
              next_front.push_back(neighbour);
            }
          }
        }
        front = std::move(next_front);
      }
    }
    for (const auto& triangle : wall) {
      const std::array<std::size_t, 3> v = {static_cast<std::size_t>(vertex_index.at(triangle[0])),
                                            static_cast<std::size_t>(vertex_index.at(triangle[1])),
                                            static_cast<std::size_t>(vertex_index.at(triangle[2]))};
      for (int j = 0; j < inward; ++j) {
        const ElementNodes<ElementType::kPrism> prism = {
            inward_node(v[0], j),     inward_node(v[1], j),     inward_node(v[2], j),
            inward_node(v[0], j + 1), inward_node(v[1], j + 1), inward_node(v[2], j + 1)};
        if (!IsValid<ElementType::kPrism>(prism)) {
          any_invalid = true;
          ++invalid_inward;
          for (const std::size_t w : v) thin_inward[w] = 1;
        }
      }
      for (int k = 0; k < outward; ++k) {
        const ElementNodes<ElementType::kPrism> prism = {
            outward_node(v[0], k),     outward_node(v[1], k),     outward_node(v[2], k),
            outward_node(v[0], k + 1), outward_node(v[1], k + 1), outward_node(v[2], k + 1)};
        if (!IsValid<ElementType::kPrism>(prism)) {
          any_invalid = true;
          ++invalid_outward;
          for (const std::size_t w : v) thin_outward[w] = 1;
        }
      }
    }
    if (!any_invalid) {
      report.shrink_rounds = round;
      break;
    }
    if (round + 1 >= options.max_shrink_rounds) {
      return absl::InternalError(absl::StrCat(
          "GrowBoundaryLayers: elements still invalid after ", options.max_shrink_rounds,
          " rounds of thinning the layers (", invalid_tets, " tetrahedra, ", invalid_inward,
          " inward and ", invalid_outward,
          " outward prisms): the layers are too thick for the wall's curvature or mesh"));
    }
    for (std::size_t v = 0; v < count; ++v) {
      if (thin_inward[v]) inward_scale[v] *= 0.5;
      if (thin_outward[v]) outward_scale[v] *= 0.5;
    }
  }
  for (std::size_t v = 0; v < count; ++v) {
    report.thinned_inward += inward_scale[v] < 1.0;
    report.thinned_outward += outward_scale[v] < 1.0;
    report.min_inward_scale = std::min(report.min_inward_scale, inward_scale[v]);
    report.min_outward_scale = std::min(report.min_outward_scale, outward_scale[v]);
  }

  // Layer nodes: boundary 0 of the inward stack is the tetrahedra's (pushed) wall node; the
  // inward stack's last boundary is the original wall, which is also boundary 0 of the outward
  // stack.
  const int boundaries = inward + outward + 1;
  std::vector<std::vector<NodeId>> node_of(boundaries, std::vector<NodeId>(count));
  for (std::size_t v = 0; v < count; ++v) node_of[0][v] = vertices[v];
  for (int b = 1; b < boundaries; ++b) {
    for (std::size_t v = 0; v < count; ++v) {
      node_of[b][v] = draft.AddNode(b <= inward ? inward_node(v, b) : outward_node(v, b - inward));
    }
  }
  for (int b = 0; b + 1 < boundaries; ++b) {
    for (const auto& triangle : wall) {
      const int a = vertex_index.at(triangle[0]);
      const int c1 = vertex_index.at(triangle[1]);
      const int c2 = vertex_index.at(triangle[2]);
      const ElementId prism = draft.AddElement(
          ElementType::kPrism, {node_of[b][a], node_of[b][c1], node_of[b][c2], node_of[b + 1][a],
                                node_of[b + 1][c1], node_of[b + 1][c2]});
      if (!draft.IsElementValid(prism)) {
        return absl::InternalError(absl::StrCat("GrowBoundaryLayers: prism ", prism,
                                                " between layer boundaries ", b, " and ", b + 1,
                                                " is invalid"));
      }
    }
  }
  return report;
}

}  // namespace getme::meshgen
