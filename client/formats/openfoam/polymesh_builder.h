#pragma once

#include "absl/status/statusor.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// The polyMesh of a document that was not read from one (a .vtk, .msh, … converted to
// OpenFOAM), as OpenFoamExtras whose files SerializeOpenFoam writes with the points:
// - faces: every face of every volume cell (tetrahedron, pyramid, wedge, hexahedron), its points
//   ordered so that its normal points out of its owner (User Guide §4.1.2); a face shared by two
//   cells is internal, owned by the lower cell index, its neighbour the higher one;
// - internal faces first, in upper-triangular order (by owner, then neighbour: what OpenFOAM's
//   solvers and checkMesh expect), then the boundary faces grouped by patch;
// - patches: a boundary face matching a triangle or quad cell of the grid with a surface group
//   (the cell array gmsh:physical, else medit:ref, su2:tag, cgns:bc, as TaggedSurfaceFaces)
//   goes to the patch of that group (named as the Gmsh physical surface if the file names it,
//   else "group<N>"), in ascending N; the rest to "defaultFaces";
// - files in `encoding` (binary: faceCompactList faces, 32-bit labels, 64-bit scalars).
// The grid's points are all kept, in order. InvalidArgument for a grid without volume cells, for
// cells OpenFOAM cannot take as one of the four shapes (polyhedra, quadratic cells, …; lines and
// vertices are left out), a cell listing a point twice, a face shared by more than two cells, and
// two cells oriented against each other (one inverted: OpenFOAM has no way to store that).
absl::StatusOr<OpenFoamExtras> BuildPolyMesh(const MeshDocument& document, Encoding encoding);

}  // namespace getme::formats
