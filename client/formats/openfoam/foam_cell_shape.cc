#include "formats/openfoam/foam_cell_shape.h"

#include <algorithm>

#include "absl/strings/str_cat.h"
#include "formats/vtk_cell_type.h"

namespace getme::formats {
namespace {

using Edge = std::array<std::int64_t, 3>;

// The edges of each shape in VTK node order (vtkTetra, vtkPyramid, vtkWedge, vtkHexahedron).
constexpr int kTetraEdges[][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
constexpr int kPyramidEdges[][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 4}, {2, 4}, {3, 4}};
constexpr int kWedgeEdges[][2] = {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5},
                                  {5, 3}, {0, 3}, {1, 4}, {2, 5}};
constexpr int kHexahedronEdges[][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                       {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

bool EdgeLess(const Edge& x, const Edge& y) { return x[0] != y[0] ? x[0] < y[0] : x[1] < y[1]; }

bool HasEdge(const std::vector<Edge>& edges, std::int64_t from, std::int64_t to) {
  return std::binary_search(edges.begin(), edges.end(), Edge{from, to, 0}, EdgeLess);
}

// The one point joined to `point` by an edge of the cell that is not among `base`; -1 if there
// is none or more than one.
std::int64_t PointAbove(const std::vector<Edge>& edges, std::int64_t point,
                        std::span<const std::int64_t> base) {
  const auto first =
      std::lower_bound(edges.begin(), edges.end(), Edge{point, INT64_MIN, 0}, EdgeLess);
  std::int64_t above = -1;
  for (auto edge = first; edge != edges.end() && (*edge)[0] == point; ++edge) {
    if (std::find(base.begin(), base.end(), (*edge)[1]) != base.end()) continue;
    if (above >= 0) return -1;
    above = (*edge)[1];
  }
  return above;
}

// Whether `shape` uses exactly the cell's edges: its own edge count equals the cell's and each
// of its edges is one of the cell's.
template <std::size_t N>
bool UsesCellEdges(const std::vector<Edge>& edges, const CellShape& shape,
                   const int (&shape_edges)[N][2]) {
  if (edges.size() != 2 * N) return false;
  for (const auto& edge : shape_edges) {
    if (!HasEdge(edges, shape.nodes[edge[0]], shape.nodes[edge[1]])) return false;
  }
  return true;
}

}  // namespace

std::string MatchCellShape(std::span<const CellFace> faces, const std::int64_t* face_ids,
                           CellShapeScratch& scratch, CellShape& shape) {
  std::vector<Edge>& edges = scratch.edges;
  edges.clear();
  int triangles = 0;
  int quads = 0;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const CellFace& face = faces[i];
    triangles += face.size == 3;
    quads += face.size == 4;
    for (int k = 0; k < face.size; ++k) {
      edges.push_back(
          {face.outward(k), face.outward((k + 1) % face.size), static_cast<std::int64_t>(i)});
    }
  }
  std::sort(edges.begin(), edges.end(), EdgeLess);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const Edge& edge = edges[e];
    if (e + 1 < edges.size() && edges[e + 1][0] == edge[0] && edges[e + 1][1] == edge[1]) {
      return absl::StrCat("faces ", face_ids[edge[2]], " and ", face_ids[edges[e + 1][2]],
                          " both run along the edge ", edge[0], "->", edge[1],
                          " seen from the cell: one of them is oriented against the others "
                          "(owner and neighbour swapped, or its points reversed)");
    }
    if (!HasEdge(edges, edge[1], edge[0])) {
      return absl::StrCat("the cell is not closed: the edge ", edge[0], "->", edge[1], " of face ",
                          face_ids[edge[2]], " is on no other face of the cell");
    }
  }

  shape = CellShape{};
  std::vector<std::int64_t>& points = scratch.points;
  points.clear();
  for (const Edge& edge : edges) {
    if (points.empty() || points.back() != edge[0]) points.push_back(edge[0]);
  }
  const std::size_t face_count = faces.size();
  const std::size_t point_count = points.size();
  // Builds the shape from its base face (`base_size` points, `reversed` or as the outward face
  // runs), then the apex (pyramid, tetrahedron) or the points above the base (wedge, hexahedron).
  const auto build = [&](const CellFace& base_face, bool reversed, int vtk_type,
                         int node_count) -> bool {
    const int base_size = base_face.size;
    for (int k = 0; k < base_size; ++k) {
      shape.nodes[k] = base_face.outward(reversed ? (base_size - k) % base_size : k);
    }
    const std::span<const std::int64_t> base(shape.nodes.data(), base_size);
    if (node_count == base_size + 1) {
      for (const std::int64_t point : points) {
        if (std::find(base.begin(), base.end(), point) == base.end())
          shape.nodes[base_size] = point;
      }
    } else {
      for (int k = 0; k < base_size; ++k) {
        shape.nodes[base_size + k] = PointAbove(edges, shape.nodes[k], base);
        if (shape.nodes[base_size + k] < 0) return false;
      }
    }
    shape.vtk_type = vtk_type;
    shape.node_count = node_count;
    return true;
  };
  const auto first_face_of_size = [&](int size) -> const CellFace& {
    return *std::find_if(faces.begin(), faces.end(),
                         [size](const CellFace& face) { return face.size == size; });
  };
  bool matched = false;
  if (face_count == 4 && triangles == 4 && point_count == 4) {
    matched = build(faces[0], true, kVtkTetra, 4) && UsesCellEdges(edges, shape, kTetraEdges);
  } else if (face_count == 5 && triangles == 4 && quads == 1 && point_count == 5) {
    matched = build(first_face_of_size(4), true, kVtkPyramid, 5) &&
              UsesCellEdges(edges, shape, kPyramidEdges);
  } else if (face_count == 5 && triangles == 2 && quads == 3 && point_count == 6) {
    matched = build(first_face_of_size(3), false, kVtkWedge, 6) &&
              UsesCellEdges(edges, shape, kWedgeEdges);
  } else if (face_count == 6 && quads == 6 && point_count == 8) {
    matched =
        build(faces[0], true, kVtkHexahedron, 8) && UsesCellEdges(edges, shape, kHexahedronEdges);
  }
  if (!matched) shape = CellShape{};
  return {};
}

}  // namespace getme::formats
