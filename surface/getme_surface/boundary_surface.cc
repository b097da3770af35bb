#include "getme_surface/boundary_surface.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

#include "absl/container/flat_hash_map.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"
#include "getme/elements/element_tables.h"
#include "getme/elements/vec3.h"
#include "getme_surface/face_keys.h"

namespace getme::surface {
namespace {

using Edge = std::array<NodeId, 2>;  // smaller id first

// Unit normal of a face in the turning sense of its nodes; a quad's from its diagonals, which is
// the mean normal of a non-planar quad. Zero for a face without area.
Vec3 UnitNormal(const Mesh& mesh, const BoundaryFace& face) {
  const Vec3 a = NodePosition(mesh, face.nodes[0]);
  const Vec3 b = NodePosition(mesh, face.nodes[1]);
  const Vec3 c = NodePosition(mesh, face.nodes[2]);
  const Vec3 normal =
      face.size == 3 ? (b - a).cross(c - a) : (c - a).cross(NodePosition(mesh, face.nodes[3]) - b);
  const double length = normal.norm();
  return length > 0.0 ? Vec3(normal / length) : Vec3(Vec3::Zero());
}

// The faces used by exactly one element, in ascending order of their sorted nodes.
std::vector<BoundaryFace> CollectBoundaryFaces(const Mesh& mesh) {
  struct Use {
    BoundaryFace face;
    ElementId element = -1;
    int count = 0;
  };
  absl::flat_hash_map<SortedFace, Use> uses;
  uses.reserve(static_cast<std::size_t>(mesh.corner_count()));
  for (ElementId e = 0; e < mesh.element_count(); ++e) {
    const std::span<const NodeId> ids = mesh.element_nodes(e);
    DispatchElementType(mesh.type(e), [&]<ElementType kType>() {
      for (const auto& table_face : ElementTable<kType>::kFaces) {
        BoundaryFace face{{-1, -1, -1, -1}, table_face.size, 0};
        for (int k = 0; k < table_face.size; ++k) face.nodes[k] = ids[table_face.nodes[k]];
        Use& use = uses[Sorted(face.nodes, face.size)];
        if (use.count++ == 0) {
          use.face = face;
          use.element = e;
        }
      }
    });
  }
  std::vector<std::pair<SortedFace, BoundaryFace>> boundary;
  for (const auto& [key, use] : uses) {
    if (use.count != 1) continue;
    // Turned out of its element: the element tables list some faces inward and some outward
    // (a tetrahedron's face 0, a hexahedron's faces 0 and 5), and faces whose normals are to be
    // compared across an edge must turn alike.
    BoundaryFace face = use.face;
    const std::span<const NodeId> ids = mesh.element_nodes(use.element);
    Vec3 element_centre = Vec3::Zero();
    for (const NodeId node : ids) element_centre += NodePosition(mesh, node);
    element_centre /= static_cast<double>(ids.size());
    Vec3 face_centre = Vec3::Zero();
    for (int k = 0; k < face.size; ++k) face_centre += NodePosition(mesh, face.nodes[k]);
    face_centre /= face.size;
    if (UnitNormal(mesh, face).dot(face_centre - element_centre) < 0.0) {
      ReverseFace(face.nodes, face.size);
    }
    boundary.emplace_back(key, face);
  }
  std::sort(boundary.begin(), boundary.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<BoundaryFace> faces;
  faces.reserve(boundary.size());
  for (const auto& entry : boundary) faces.push_back(entry.second);
  return faces;
}

absl::Status AssignGroups(std::span<const GroupedFace> groups, bool skip_interior,
                          std::int64_t& skipped, std::vector<BoundaryFace>& faces,
                          int& group_count) {
  absl::flat_hash_map<SortedFace, std::size_t> index;
  index.reserve(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) index[Sorted(faces[f].nodes, faces[f].size)] = f;
  group_count = 1;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const GroupedFace& grouped = groups[g];
    const std::span<const NodeId> nodes(grouped.nodes.data(),
                                        static_cast<std::size_t>(std::clamp(grouped.size, 0, 4)));
    if (grouped.size != 3 && grouped.size != 4) {
      return absl::InvalidArgumentError(absl::StrCat("grouped face ", g, " has ", grouped.size,
                                                     " nodes: a boundary face has 3 or 4"));
    }
    if (grouped.group < 0) {
      return absl::InvalidArgumentError(absl::StrCat("grouped face ", g, " {",
                                                     absl::StrJoin(nodes, ", "), "} has group ",
                                                     grouped.group, ": groups are 0 or more"));
    }
    const auto found = index.find(Sorted(grouped.nodes, grouped.size));
    if (found == index.end() && skip_interior) {
      ++skipped;
      continue;
    }
    if (found == index.end()) {
      return absl::InvalidArgumentError(
          absl::StrCat("grouped face ", g, " {", absl::StrJoin(nodes, ", "),
                       "} is not a boundary face of the mesh (no element has it as a face, or "
                       "two elements share it)"));
    }
    faces[found->second].group = grouped.group;
    group_count = std::max(group_count, grouped.group + 1);
  }
  return absl::OkStatus();
}

// Union–find over feature edges, with the smaller index as the root so that curve numbers follow
// the edges' order.
int Root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

void Join(std::vector<int>& parent, int a, int b) {
  a = Root(parent, a);
  b = Root(parent, b);
  if (a != b) parent[std::max(a, b)] = std::min(a, b);
}

}  // namespace

absl::StatusOr<BoundarySurface> ExtractBoundarySurface(const Mesh& mesh,
                                                       std::span<const GroupedFace> groups,
                                                       double feature_angle_degrees,
                                                       bool skip_interior_groups) {
  if (!(feature_angle_degrees >= 0.0 && feature_angle_degrees <= 180.0)) {
    return absl::InvalidArgumentError(absl::StrCat(
        "feature_angle_degrees is ", feature_angle_degrees, ": it must be in [0, 180]"));
  }
  BoundarySurface surface;
  surface.faces = CollectBoundaryFaces(mesh);
  if (absl::Status status =
          AssignGroups(groups, skip_interior_groups, surface.interior_grouped_faces, surface.faces,
                       surface.group_count);
      !status.ok()) {
    return status;
  }

  // Each edge of the boundary with the faces along it.
  absl::flat_hash_map<Edge, std::vector<int>> edge_faces;
  for (int f = 0; f < static_cast<int>(surface.faces.size()); ++f) {
    const BoundaryFace& face = surface.faces[f];
    for (int k = 0; k < face.size; ++k) {
      const NodeId a = face.nodes[k];
      const NodeId b = face.nodes[(k + 1) % face.size];
      edge_faces[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  }
  std::vector<Vec3> normals;
  normals.reserve(surface.faces.size());
  for (const BoundaryFace& face : surface.faces) normals.push_back(UnitNormal(mesh, face));
  // Two faces whose normals turn by more than the feature angle: cos below cos(angle).
  const double cos_limit = std::cos(feature_angle_degrees * std::numbers::pi / 180.0);
  for (const auto& [edge, faces] : edge_faces) {
    bool feature = faces.size() != 2;  // an open or non-manifold edge always splits the surface
    if (!feature) {
      const BoundaryFace& a = surface.faces[faces[0]];
      const BoundaryFace& b = surface.faces[faces[1]];
      const double cosine = normals[faces[0]].dot(normals[faces[1]]);
      const bool degenerate = normals[faces[0]].isZero() || normals[faces[1]].isZero();
      feature = a.group != b.group || degenerate || cosine < cos_limit;
    }
    if (feature) surface.feature_edges.push_back(edge);
  }
  std::sort(surface.feature_edges.begin(), surface.feature_edges.end());

  // Nodes: on the surface, with the number of feature edges at each.
  const auto node_count = static_cast<std::size_t>(mesh.node_count());
  surface.kind.assign(node_count, BoundaryNodeKind::kInterior);
  surface.support.assign(node_count, -1);
  std::vector<int> feature_degree(node_count, 0);
  for (const Edge& edge : surface.feature_edges) {
    ++feature_degree[edge[0]];
    ++feature_degree[edge[1]];
  }
  // The distinct groups of each node's faces (counted up to 3).
  std::vector<int> first_group(node_count, -1);
  std::vector<int> second_group(node_count, -1);
  std::vector<int> group_variety(node_count, 0);
  for (const BoundaryFace& face : surface.faces) {
    for (int k = 0; k < face.size; ++k) {
      const NodeId node = face.nodes[k];
      if (group_variety[node] == 0) {
        first_group[node] = face.group;
        group_variety[node] = 1;
      } else if (face.group != first_group[node] && face.group != second_group[node]) {
        if (group_variety[node] == 1) second_group[node] = face.group;
        group_variety[node] = std::min(group_variety[node] + 1, 3);
      }
    }
  }
  for (std::size_t node = 0; node < node_count; ++node) {
    if (group_variety[node] == 0) continue;
    if (feature_degree[node] == 0) {
      // Two groups that touch at this node only, with no feature edge between them: it can
      // slide on neither without leaving the other.
      surface.kind[node] =
          group_variety[node] == 1 ? BoundaryNodeKind::kSurface : BoundaryNodeKind::kCorner;
      if (group_variety[node] == 1) surface.support[node] = first_group[node];
    } else {
      // On a curve: two feature edges, and at most the two groups the curve separates.
      surface.kind[node] = feature_degree[node] == 2 && group_variety[node] <= 2
                               ? BoundaryNodeKind::kFeature
                               : BoundaryNodeKind::kCorner;
    }
  }

  // Curves: feature edges chained through feature (not corner) nodes.
  const int edges = static_cast<int>(surface.feature_edges.size());
  std::vector<int> parent(edges);
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<int> first_edge_at(node_count, -1);
  for (int i = 0; i < edges; ++i) {
    for (NodeId node : surface.feature_edges[i]) {
      if (surface.kind[node] != BoundaryNodeKind::kFeature) continue;
      if (first_edge_at[node] < 0) {
        first_edge_at[node] = i;
      } else {
        Join(parent, first_edge_at[node], i);
      }
    }
  }
  surface.edge_curve.assign(edges, -1);
  std::vector<int> curve_of_root(edges, -1);
  for (int i = 0; i < edges; ++i) {
    const int root = Root(parent, i);
    if (curve_of_root[root] < 0) curve_of_root[root] = surface.curve_count++;
    surface.edge_curve[i] = curve_of_root[root];
  }
  for (int i = 0; i < edges; ++i) {
    for (NodeId node : surface.feature_edges[i]) {
      if (surface.kind[node] == BoundaryNodeKind::kFeature) {
        surface.support[node] = surface.edge_curve[i];
      }
    }
  }
  for (BoundaryNodeKind kind : surface.kind) {
    surface.corner_count += kind == BoundaryNodeKind::kCorner ? 1 : 0;
  }
  return surface;
}

}  // namespace getme::surface
