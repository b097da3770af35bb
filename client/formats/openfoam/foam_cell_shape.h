#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace getme::formats {

// One face of a cell as the polyMesh stores it: its point labels, and whether the cell is the
// face's neighbour. OpenFOAM orders a face's points so that its right-hand normal points out of
// its owner cell (User Guide §4.1.2 "Mesh description": "the face normal points out of the owner
// cell"), so for the neighbour the points run the other way round.
struct CellFace {
  const std::int64_t* points = nullptr;
  int size = 0;
  bool neighbour = false;

  // Point k of the face in the order that makes its normal point out of this cell.
  std::int64_t outward(int k) const { return neighbour ? points[(size - k) % size] : points[k]; }
};

// What a cell is: a tetrahedron, pyramid, wedge or hexahedron (vtk_type 10, 14, 13, 12) with its
// nodes in VTK order (docs/node-orders.md), or a polyhedron (vtk_type 0: any other face set).
struct CellShape {
  int vtk_type = 0;
  int node_count = 0;
  std::array<std::int64_t, 8> nodes{};
};

// Scratch buffers, reused from cell to cell.
struct CellShapeScratch {
  std::vector<std::array<std::int64_t, 3>> edges;  // from, to, face (index in the cell)
  std::vector<std::int64_t> points;
};

// Matches a cell's faces against the four shapes, as OpenFOAM's cellMatcher does (checkMesh's
// "Cell shapes" counts): by the number of faces and their sizes, and then by connectivity — the
// element built from one face and the edges leaving it must use exactly the cell's edges.
// The node order follows from the outward faces: a hexahedron's bottom is its first face reversed
// (counter-clockwise seen from the top, as VTK and the paper want), a wedge's first triangle is an
// outward triangle as is (VTK's wedge: the right-hand normal of 0, 1, 2 points away from 3, 4, 5),
// a pyramid's base is its quad reversed, a tetrahedron's base its first triangle reversed.
//
// Before matching, checks that the faces close the cell consistently: every directed edge of the
// outward faces is met once in the opposite direction by another face (checkMesh's "closed
// cells" and "face orientation"). On failure returns a message ("the edge 3→8 of face 12 …") and
// leaves `shape` alone; the caller names the cell.
std::string MatchCellShape(std::span<const CellFace> faces, const std::int64_t* face_ids,
                           CellShapeScratch& scratch, CellShape& shape);

}  // namespace getme::formats
