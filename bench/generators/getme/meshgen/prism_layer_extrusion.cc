#include "getme/meshgen/prism_layer_extrusion.h"

#include <algorithm>
#include <utility>
#include <vector>

#include "absl/container/flat_hash_map.h"
#include "absl/container/flat_hash_set.h"
#include "absl/strings/str_cat.h"

namespace getme::meshgen {

absl::Status ExtrudePrismLayers(MeshDraft& draft, std::span<const std::array<NodeId, 3>> triangles,
                                int layers, double layer_height) {
  // Surface vertices in order of first appearance, with their area-weighted normals: the cross
  // product of a triangle's edges is twice its area times its unit normal.
  absl::flat_hash_map<NodeId, int> vertex_index;
  std::vector<NodeId> vertices;
  std::vector<Vec3> normals;
  for (const auto& triangle : triangles) {
    const Vec3 a = draft.node(triangle[0]);
    const Vec3 weighted_normal = (draft.node(triangle[1]) - a).cross(draft.node(triangle[2]) - a);
    for (const NodeId node : triangle) {
      const auto [it, inserted] = vertex_index.try_emplace(node, static_cast<int>(vertices.size()));
      if (inserted) {
        vertices.push_back(node);
        normals.push_back(Vec3::Zero());
      }
      normals[it->second] += weighted_normal;
    }
  }
  for (std::size_t v = 0; v < normals.size(); ++v) {
    const double length = normals[v].norm();
    if (!(length > 0.0)) {
      return absl::InternalError(absl::StrCat("ExtrudePrismLayers: surface node ", vertices[v],
                                              " has no normal (its triangles cancel out)"));
    }
    normals[v] /= length;
  }

  // below[v] / above[v]: vertex v's node under and on the layer being built.
  std::vector<NodeId> below = vertices;
  std::vector<NodeId> above(vertices.size());
  for (int layer = 1; layer <= layers; ++layer) {
    for (std::size_t v = 0; v < vertices.size(); ++v) {
      above[v] = draft.AddNode(draft.node(vertices[v]) + (layer * layer_height) * normals[v]);
    }
    for (const auto& triangle : triangles) {
      const int a = vertex_index.at(triangle[0]);
      const int b = vertex_index.at(triangle[1]);
      const int c = vertex_index.at(triangle[2]);
      const ElementId prism = draft.AddElement(
          ElementType::kPrism, {below[a], below[b], below[c], above[a], above[b], above[c]});
      if (!draft.IsElementValid(prism)) {
        return absl::InternalError(absl::StrCat(
            "ExtrudePrismLayers: the prism of layer ", layer, " over surface triangle (",
            triangle[0], ", ", triangle[1], ", ", triangle[2], ") is invalid; the layer height ",
            layer_height, " is too large for the surface"));
      }
    }
    std::swap(below, above);
  }
  return absl::OkStatus();
}

double MeanEdgeLength(const MeshDraft& draft, std::span<const std::array<NodeId, 3>> triangles) {
  absl::flat_hash_set<std::pair<NodeId, NodeId>> edges;
  double total = 0.0;
  for (const auto& triangle : triangles) {
    for (int k = 0; k < 3; ++k) {
      const NodeId a = triangle[k], b = triangle[(k + 1) % 3];
      if (edges.insert(std::minmax(a, b)).second) total += (draft.node(a) - draft.node(b)).norm();
    }
  }
  return edges.empty() ? 0.0 : total / static_cast<double>(edges.size());
}

}  // namespace getme::meshgen
