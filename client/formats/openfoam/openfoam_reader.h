#pragma once

#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "formats/mesh_document.h"

namespace getme::formats {

// The files of a polyMesh directory as they are on disk (gzip compressed or not).
struct PolyMeshFiles {
  PolyMeshFile points;
  PolyMeshFile faces;
  PolyMeshFile owner;
  PolyMeshFile neighbour;
  PolyMeshFile boundary;
  std::vector<PolyMeshFile> zones;  // cellZones, faceZones, pointZones when present: kept only
};

// Parses an OpenFOAM polyMesh (User Guide §4.1.2 "Mesh description": points, faces, owner,
// neighbour, boundary; each with or without a FoamFile header, ASCII or binary, each possibly
// gzip compressed; faces as faceList or faceCompactList) into a MeshDocument:
// - points → grid points, in file order;
// - every cell that is a tetrahedron, pyramid, prism or hexahedron (foam_cell_shape.h) → a grid
//   cell in VTK order, in cell order; other cells (polyhedra) are not in the grid: their points
//   are marked in the point array "fixed" (Int32) so that they stay where they are;
// - every boundary face → a grid cell after the volume cells, in face order: triangle, quad, or
//   polygon (VTK 7) for larger faces, with its patch's 1-based position in the cell array
//   "openfoam:patch" (Int32, 0 for volume cells); the patches and the other files byte for byte
//   → OpenFoamExtras.
// The read summary (spdlog info) counts the cells of each shape and the polyhedra kept fixed.
//
// InvalidArgument naming the file, the line (ASCII) or byte (binary) where possible, and the
// face or cell, for: malformed lists, a face referring to a missing point or repeating one, an
// owner list whose size differs from the number of faces, a neighbour list longer than it, a
// face whose owner is its neighbour, cells that own no face, patches that do not cover the
// boundary faces exactly, a cell whose faces do not close it consistently; and for a mesh with no
// cell getme can smooth (all polyhedra).
absl::StatusOr<MeshDocument> ParseOpenFoam(const PolyMeshFiles& files);

// The polyMesh directory `path` means: path/constant/polyMesh if that exists (a case directory),
// else path/polyMesh (the case's constant directory), else path itself when it holds a faces file
// (a polyMesh directory). NotFound otherwise.
absl::StatusOr<std::string> FindPolyMeshDirectory(const std::string& path);

// Reads the polyMesh directory of `path` (FindPolyMeshDirectory): each file NAME or, if absent,
// NAME.gz. NotFound naming a missing file; errors of ParseOpenFoam prefixed with the directory.
absl::StatusOr<MeshDocument> ReadOpenFoam(const std::string& path);

}  // namespace getme::formats
