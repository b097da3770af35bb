#include "getme_surface/layer_columns.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "absl/container/flat_hash_map.h"
#include "getme/elements/element_tables.h"
#include "getme/elements/vec3.h"
#include "getme_surface/face_keys.h"

namespace getme::surface {
namespace {

// An element entered by one of its faces: the face's nodes and, for each, the node at the other
// end of its column edge (the element's one edge from it that leaves the face). Only prisms
// entered by a triangle and hexahedra have such a pairing.
struct Crossing {
  ElementId element = -1;
  int size = 0;
  std::array<NodeId, 4> entry{-1, -1, -1, -1};
  std::array<NodeId, 4> exit{-1, -1, -1, -1};
};

template <ElementType kType>
Crossing Cross(const Mesh& mesh, ElementId element, int local_face) {
  using Table = ElementTable<kType>;
  const std::span<const NodeId> ids = mesh.element_nodes(element);
  const FaceIndices& face = Table::kFaces[local_face];
  Crossing crossing;
  crossing.element = element;
  crossing.size = face.size;
  const auto in_face = [&](int local) {
    return std::find(face.nodes.begin(), face.nodes.begin() + face.size, local) !=
           face.nodes.begin() + face.size;
  };
  for (int k = 0; k < face.size; ++k) {
    const int a = face.nodes[k];
    crossing.entry[k] = ids[a];
    for (const EdgeIndices& edge : Table::kEdges) {
      const int other = edge[0] == a ? edge[1] : edge[1] == a ? edge[0] : -1;
      if (other >= 0 && !in_face(other)) crossing.exit[k] = ids[other];
    }
  }
  return crossing;
}

// Height over width of a crossing: the mean column edge length over the square root of the
// entry face's area.
double Aspect(const Mesh& mesh, const Crossing& crossing) {
  double height = 0.0;
  for (int k = 0; k < crossing.size; ++k) {
    height += (NodePosition(mesh, crossing.exit[k]) - NodePosition(mesh, crossing.entry[k])).norm();
  }
  height /= crossing.size;
  const Vec3 a = NodePosition(mesh, crossing.entry[0]);
  const Vec3 b = NodePosition(mesh, crossing.entry[1]);
  const Vec3 c = NodePosition(mesh, crossing.entry[2]);
  const double area = crossing.size == 3
                          ? 0.5 * (b - a).cross(c - a).norm()
                          : 0.5 * (c - a).cross(NodePosition(mesh, crossing.entry[3]) - b).norm();
  return area > 0.0 ? height / std::sqrt(area) : HUGE_VAL;
}

// Whether local face `local_face` of an element of type `type` can start or continue a column.
bool IsLayerFace(ElementType type, int local_face) {
  if (type == ElementType::kHexahedron) return true;
  return type == ElementType::kPrism && (local_face == 0 || local_face == 4);
}

struct FaceUse {
  ElementId element[2] = {-1, -1};
  std::int8_t local_face[2] = {-1, -1};
  int count = 0;
};

class ColumnFinder {
 public:
  explicit ColumnFinder(const Mesh& mesh) : mesh_(mesh) {
    uses_.reserve(static_cast<std::size_t>(mesh.corner_count()));
    for (ElementId e = 0; e < mesh.element_count(); ++e) {
      const std::span<const NodeId> ids = mesh.element_nodes(e);
      DispatchElementType(mesh.type(e), [&]<ElementType kType>() {
        for (int f = 0; f < static_cast<int>(ElementTable<kType>::kFaces.size()); ++f) {
          const FaceIndices& face = ElementTable<kType>::kFaces[f];
          std::array<NodeId, 4> nodes{-1, -1, -1, -1};
          for (int k = 0; k < face.size; ++k) nodes[k] = ids[face.nodes[k]];
          FaceUse& use = uses_[Sorted(nodes, face.size)];
          if (use.count < 2) {
            use.element[use.count] = e;
            use.local_face[use.count] = static_cast<std::int8_t>(f);
          }
          ++use.count;
        }
      });
    }
    columns_.level.assign(mesh.node_count(), -1);
    columns_.below.assign(mesh.node_count(), -1);
    columns_.conflict.assign(mesh.node_count(), 0);
    taken_.assign(mesh.element_count(), 0);
  }

  LayerColumns Find() && {
    // Every boundary face that can start a column, thinnest first (ties by element and face, so
    // the result does not depend on the hash map's order).
    std::vector<std::tuple<double, ElementId, int>> starts;
    for (const auto& [key, use] : uses_) {
      if (use.count != 1 || !IsLayerFace(mesh_.type(use.element[0]), use.local_face[0])) continue;
      const double aspect = Aspect(mesh_, CrossAt(use.element[0], use.local_face[0]));
      if (aspect < kLayerStartAspect)
        starts.emplace_back(aspect, use.element[0], use.local_face[0]);
    }
    std::sort(starts.begin(), starts.end());
    for (const auto& [aspect, element, local_face] : starts) {
      if (!taken_[element]) Grow(CrossAt(element, local_face));
    }
    for (ElementId e = 0; e < mesh_.element_count(); ++e) {
      if (taken_[e]) columns_.elements.push_back(e);
    }
    for (std::int64_t node = 0; node < mesh_.node_count(); ++node) {
      columns_.conflicting_nodes += columns_.conflict[node];
      if (columns_.conflict[node] == 0) {
        columns_.layers = std::max(columns_.layers, columns_.level[node]);
      }
    }
    return std::move(columns_);
  }

 private:
  Crossing CrossAt(ElementId element, int local_face) const {
    return DispatchElementType(mesh_.type(element), [&]<ElementType kType>() {
      return Cross<kType>(mesh_, element, local_face);
    });
  }

  void Assign(NodeId node, std::int32_t level, NodeId below) {
    std::int32_t& current = columns_.level[node];
    if (current < 0) {
      current = level;
      columns_.below[node] = below;
    } else if (current != level || columns_.below[node] != below) {
      columns_.conflict[node] = 1;
    }
  }

  // Grows one column from the wall face `crossing` entered its first element by.
  void Grow(Crossing crossing) {
    // The wall face turned into the column, whatever way the element's table lists it, so that
    // the normals of the wall faces around a node add up (kept_columns.h).
    std::array<NodeId, 4> wall = crossing.entry;
    const auto centre = [&](const std::array<NodeId, 4>& nodes) {
      Vec3 sum = Vec3::Zero();
      for (int k = 0; k < crossing.size; ++k) sum += NodePosition(mesh_, nodes[k]);
      return Vec3(sum / crossing.size);
    };
    const Vec3 a = NodePosition(mesh_, wall[0]);
    const Vec3 b = NodePosition(mesh_, wall[1]);
    const Vec3 c = NodePosition(mesh_, wall[2]);
    const Vec3 normal = crossing.size == 3 ? Vec3((b - a).cross(c - a))
                                           : Vec3((c - a).cross(NodePosition(mesh_, wall[3]) - b));
    if (normal.dot(centre(crossing.exit) - centre(crossing.entry)) < 0.0) {
      ReverseFace(wall, crossing.size);
    }
    columns_.wall_faces.push_back(wall);
    columns_.wall_face_sizes.push_back(crossing.size);
    for (int k = 0; k < crossing.size; ++k) Assign(crossing.entry[k], 0, -1);
    while (true) {
      taken_[crossing.element] = 1;
      for (int k = 0; k < crossing.size; ++k) {
        const NodeId below = crossing.entry[k];
        const std::int32_t level = columns_.level[below];
        Assign(crossing.exit[k], level < 0 ? -1 : level + 1, below);
      }
      const auto found = uses_.find(Sorted(crossing.exit, crossing.size));
      const FaceUse& use = found->second;
      if (use.count != 2) {
        ++columns_.ends.boundary;
        return;
      }
      const int side = use.element[0] == crossing.element ? 1 : 0;
      const ElementId next = use.element[side];
      const int next_face = use.local_face[side];
      const ElementType type = mesh_.type(next);
      if (type == ElementType::kTetrahedron) {
        ++columns_.ends.tetrahedron;
        return;
      }
      if (type == ElementType::kPyramid) {
        ++columns_.ends.pyramid;
        return;
      }
      if (!IsLayerFace(type, next_face)) {
        ++columns_.ends.prism_side;
        return;
      }
      if (taken_[next]) {
        ++columns_.ends.taken;
        return;
      }
      Crossing next_crossing = CrossAt(next, next_face);
      if (!(Aspect(mesh_, next_crossing) < kLayerAspect)) {
        ++columns_.ends.isotropic;
        return;
      }
      crossing = next_crossing;
    }
  }

  const Mesh& mesh_;
  absl::flat_hash_map<SortedFace, FaceUse> uses_;
  LayerColumns columns_;
  std::vector<std::uint8_t> taken_;
};

}  // namespace

LayerColumns FindLayerColumns(const Mesh& mesh) { return ColumnFinder(mesh).Find(); }

}  // namespace getme::surface
