#pragma once

// Boundary-layer stacks found by topology (issue 15, item 2; docs/boundary.md#layers): columns
// of prisms or hexahedra grown from a wall face, element on element through their opposite faces,
// as a CFD mesher extrudes them. Each column node is tied to the node one layer below it, down to
// its wall node, so a layer's height at a node is the node's distance from the wall minus that of
// the node below.
//
// A column starts at a boundary face of a prism (one of its two triangles) or a hexahedron whose
// element is at most half as high as wide (kLayerStartAspect) and goes on, through the face
// opposite the one it came in by, while the next element is a prism entered by a triangle or a
// hexahedron, still thinner than wide (kLayerAspect) and in no other column. So a hexahedral
// block's side faces, whose first element is as high as wide, start none, and where two walls'
// layers meet (a concave corner, two walls facing each other) the thinner wall's columns are
// grown first and keep their elements.

#include <array>
#include <cstdint>
#include <vector>

#include "absl/status/statusor.h"
#include "getme/mesh/mesh.h"

namespace getme::surface {

// An element is layer-like while its height (the mean length of its column edges) is below this
// times the square root of the area of the face it is entered by.
inline constexpr double kLayerAspect = 1.0;
// A column starts only at an element below this aspect. An isotropic mesh, even one distorted by
// a third of its edge length, has its elements' aspects between about 0.6 and 1.5, so none of its
// boundary elements starts a column; a CFD mesh's first layer is 10 to 1000 times thinner than
// wide.
inline constexpr double kLayerStartAspect = 0.5;

// Why a column stops growing, one count per column.
struct ColumnEnds {
  std::int64_t tetrahedron = 0;  // the next element is a tetrahedron
  std::int64_t pyramid = 0;      // ... a pyramid
  std::int64_t prism_side = 0;   // ... a prism entered by a quad (its side, not a layer)
  std::int64_t isotropic = 0;    // ... a prism or hexahedron no longer thinner than wide
  std::int64_t taken = 0;        // ... an element of another column
  std::int64_t boundary = 0;     // the column reaches the boundary (it spans the domain)
};

struct LayerColumns {
  // Per node: -1 in no column, 0 a wall node, k ≥ 1 the node k layers above its wall node.
  std::vector<std::int32_t> level;
  // Per node with level ≥ 1: the node one level below it.
  std::vector<NodeId> below;
  // Per node: 1 where two columns disagree on the node's level or the node below it (colliding
  // layers); such a node belongs to no column.
  std::vector<std::uint8_t> conflict;
  // The faces the columns start at, each turned so that its normal points into its column.
  std::vector<std::array<NodeId, 4>> wall_faces;
  std::vector<int> wall_face_sizes;
  std::vector<ElementId> elements;  // the columns' elements, ascending
  int layers = 0;                   // the highest level
  ColumnEnds ends;
  std::int64_t conflicting_nodes = 0;

  std::int64_t column_count() const { return static_cast<std::int64_t>(wall_faces.size()); }
  std::int64_t column_elements() const { return static_cast<std::int64_t>(elements.size()); }
  // A node whose position the layers govern: above the wall, in one column only.
  bool InLayer(NodeId node) const { return level[node] >= 1 && conflict[node] == 0; }
};

// Finds the columns of `mesh` at its current coordinates (the thinness test is geometric, the
// columns are topological). A mesh without prisms or hexahedra on its boundary has none.
LayerColumns FindLayerColumns(const Mesh& mesh);

}  // namespace getme::surface
