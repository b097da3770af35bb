#pragma once

#include <string>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// Writes `document` as a CGNS file (HDF5 storage, CGNS library 3.4) at `path`, atomically (a
// temporary file beside it, renamed once the library has closed it):
// - one base (cell and physical dimension 3) and one Unstructured zone, named as read
//   (CgnsExtras) or "Base" / "Zone"; GridCoordinates CoordinateX/Y/Z as RealDouble;
// - element sections: the volume cells first (the zone's cells, which cell-centred data and
//   other tools number 1..N), then the triangles, quads, lines and vertices, each in grid order.
//   A run of cells of one type is one typed section (TETRA_4, PYRA_5, PENTA_6, HEXA_8, TRI_3,
//   QUAD_4, BAR_2, NODE); when the types alternate in more than 16 runs, the volumes and the
//   rest go to one MIXED section each instead. VTK's wedge is written in PENTA_6 order. Moving
//   the volume cells ahead renumbers cells (a warning says so);
// - boundary conditions: those of CgnsExtras with their BCType and FamilyName, their elements
//   from the cell array "cgns:bc" (PointRange if contiguous, else PointList, GridLocation
//   FaceCenter / EdgeCenter / Vertex after their cells), a vertex condition with its nodes.
//   Without CGNS extras, the triangles and quads of each value of "cgns:bc", else
//   "gmsh:physical" (named by the Gmsh physical name when there is one), else "medit:ref" become
//   a BCTypeUserDefined condition, so markers survive a conversion;
// - families (CgnsExtras) with their FamilyBC;
// - point arrays of one component → FlowSolution "PointData" (Vertex); cell arrays of one
//   component → FlowSolution "CellData" (CellCenter, the volume cells' values). Others are
//   named in a warning.
//
// InvalidArgument for cells CGNS cannot hold here (quadratic, polyhedra, voxels, …, naming the
// cell), a grid without volume cells, more than 2^31-1 nodes or entries (the library's cgsize_t
// is 32-bit in this build), an inconsistent document. Internal with the library's message if a
// cg_* call fails.
absl::Status WriteCgnsFile(const std::string& path, const MeshDocument& document);

// The bytes of the file WriteCgnsFile writes (through a temporary file).
absl::StatusOr<std::string> SerializeCgns(const MeshDocument& document);

}  // namespace getme::formats
