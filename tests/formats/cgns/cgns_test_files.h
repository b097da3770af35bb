#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "formats/unstructured_grid.h"

namespace getme::formats::testing {

// Path of a file in the fixture directory (write_fixtures.py's output, CGNS_FIXTURES).
std::string FixturePath(const std::string& name);

// What a fixture must read as (NAME.json beside it, written by write_fixtures.py).
struct ExpectedBc {
  std::string name;
  std::string type;  // "BCWallViscous", …
  std::vector<std::int64_t> cells;
};
struct ExpectedMesh {
  std::vector<double> points;
  GridCells cells;  // VTK codes and order
  std::vector<ExpectedBc> bcs;
};
ExpectedMesh ReadExpected(const std::string& path);

// Small CGNS files written here directly with the CGNS library's own calls (cg_section_write,
// cg_boco_write, …), for what no other tool writes: MIXED sections, families, vertex boundary
// conditions, and the cases the reader must refuse. Each returns the path written.
struct LibraryFileOptions {
  std::string path;
  int file_type = 2;  // CG_FILE_HDF5; 1 = CG_FILE_ADF
  int cell_dimension = 3;
  bool structured = false;
  int zones = 1;
  int element_type = 20;            // MIXED (TETRA_4 + PENTA_6, prism in PENTA_6 order)
  bool prism_in_vtk_order = false;  // the mixed section's prism written mirrored
  bool with_family_and_vertex_bc = true;
  int bc_element = 3;  // the face BC's element (1-based): the triangle
};
// Two elements (a tetrahedron, a prism next to it) and a triangle on the tetrahedron; a BC
// "inlet" (FaceCenter, PointList {bc_element}, FamilyName "Walls") and a BC "pins" (Vertex,
// PointList {1, 2}); family "Walls" with FamilyBC BCWall.
std::string WriteLibraryFile(const LibraryFileOptions& options);

// The points and cells (VTK order) WriteLibraryFile writes.
std::vector<double> LibraryFilePoints();
GridCells LibraryFileCells();

}  // namespace getme::formats::testing
