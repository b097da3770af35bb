#pragma once

// Boundary-layer columns whose layer heights a run keeps (SmoothingParams::keep_layers, issue 15,
// docs/boundary.md#layers). Whoever builds the BoundarySlide finds them (surface/: prisms or
// hexahedra stacked on a wall face) and hands the engine this plain description; the engine
// holds every column node out of the ordinary phases and moves a column only as a whole
// (layer_phase.h): its nodes on the straight line from the wall node along the wall's normal
// there, each at its own distance, so every layer keeps its height.

#include <cstdint>
#include <span>
#include <vector>

#include "getme/elements/vec3.h"
#include "getme/mesh/mesh.h"

namespace getme {

struct KeptLayers {
  // Per column: its wall node and the unit direction from the wall into the layers in the input
  // (the wall's normal at the wall node), which tells which way a normal turns.
  std::vector<NodeId> wall;
  std::vector<Vec3> direction;
  // Column c's nodes above its wall node are nodes[offsets[c] .. offsets[c + 1]), lowest first,
  // each at distance[k] from the wall node along the direction (chosen so that the node's
  // distance from the input's wall is its input distance).
  std::vector<std::int64_t> offsets{0};
  std::vector<NodeId> nodes;
  std::vector<double> distance;
  // Per column: the wall nodes its wall node shares a wall face edge with,
  // wall_neighbours[wall_offsets[c] .. wall_offsets[c + 1]).
  std::vector<std::int64_t> wall_offsets{0};
  std::vector<NodeId> wall_neighbours;
  // Per column: the wall faces around its wall node, whose area-weighted normal is the column's
  // direction wherever the wall node goes, four ids a face (-1 after a triangle's three),
  // wall_faces[4 * face_offsets[c] .. 4 * face_offsets[c + 1]).
  std::vector<std::int64_t> face_offsets{0};
  std::vector<NodeId> wall_faces;

  std::int64_t column_count() const { return static_cast<std::int64_t>(wall.size()); }
  std::span<const NodeId> Nodes(std::int64_t column) const {
    return {nodes.data() + offsets[column],
            static_cast<std::size_t>(offsets[column + 1] - offsets[column])};
  }
  std::span<const double> Distances(std::int64_t column) const {
    return {distance.data() + offsets[column],
            static_cast<std::size_t>(offsets[column + 1] - offsets[column])};
  }
  std::span<const NodeId> WallNeighbours(std::int64_t column) const {
    return {wall_neighbours.data() + wall_offsets[column],
            static_cast<std::size_t>(wall_offsets[column + 1] - wall_offsets[column])};
  }
  std::span<const NodeId> WallFaces(std::int64_t column) const {
    return {wall_faces.data() + 4 * face_offsets[column],
            static_cast<std::size_t>(4 * (face_offsets[column + 1] - face_offsets[column]))};
  }
};

// The sum of the normals of `faces` (four ids a face, -1 after a triangle's three) at the mesh's
// current coordinates, each as long as twice its face's area: a triangle's edge cross product, a
// quad's diagonals' (the mean normal of a warped quad). Its direction is the faces'
// area-weighted normal, turned as the faces' node order turns.
inline Vec3 SummedFaceNormal(const Mesh& mesh, std::span<const NodeId> faces) {
  const auto at = [&](NodeId node) { return Vec3(mesh.x()[node], mesh.y()[node], mesh.z()[node]); };
  Vec3 sum = Vec3::Zero();
  for (std::size_t f = 0; f + 4 <= faces.size(); f += 4) {
    const Vec3 a = at(faces[f]);
    const Vec3 b = at(faces[f + 1]);
    const Vec3 c = at(faces[f + 2]);
    sum +=
        faces[f + 3] < 0 ? Vec3((b - a).cross(c - a)) : Vec3((c - a).cross(at(faces[f + 3]) - b));
  }
  return sum;
}

}  // namespace getme
