// The OpenFOAM reader on polyMesh cases written by OpenFOAM's own utilities (write_fixtures.py:
// blockMesh, gmshToFoam, foamFormatConvert, refineHexMesh): cell shapes as checkMesh counts
// them, patches as checkMesh lists them, the same mesh in every encoding, the same cells as
// foamToVTK's, every smoothable cell valid in getme's orientation, polyhedra kept fixed.

#include "formats/openfoam/openfoam_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "formats/grid_mesh.h"
#include "formats/vtk_cell_type.h"
#include "formats/vtk_reader.h"
#include "openfoam_test_util.h"

namespace getme::formats {
namespace {

using testing::CasePath;
using testing::CellTypeCounts;
using testing::CheckMeshCounts;
using testing::IntegerArray;

MeshDocument ReadCase(const std::string& name) {
  absl::StatusOr<MeshDocument> document = ReadOpenFoam(CasePath(name));
  EXPECT_TRUE(document.ok()) << document.status();
  return document.ok() ? *std::move(document) : MeshDocument{};
}

// Volume cells per shape as checkMesh counts them; surface cells per patch.
void ExpectCheckMeshCounts(const std::string& name, const MeshDocument& document) {
  const std::map<std::string, std::int64_t> expected = CheckMeshCounts(name);
  std::map<int, std::int64_t> counts = CellTypeCounts(document.grid);
  EXPECT_EQ(counts[kVtkHexahedron], expected.at("hexahedra")) << name;
  EXPECT_EQ(counts[kVtkWedge], expected.at("prisms")) << name;
  EXPECT_EQ(counts[kVtkPyramid], expected.at("pyramids")) << name;
  EXPECT_EQ(counts[kVtkTetra], expected.at("tetrahedra")) << name;
  EXPECT_EQ(expected.at("wedges") + expected.at("tet_wedges"), 0) << "not in these fixtures";
  ASSERT_TRUE(document.openfoam.has_value());
  EXPECT_EQ(document.openfoam->polyhedron_count, expected.at("polyhedra")) << name;
  EXPECT_EQ(document.openfoam->cell_count, expected.at("hexahedra") + expected.at("prisms") +
                                               expected.at("pyramids") + expected.at("tetrahedra") +
                                               expected.at("polyhedra"));
  // Patches: names, sizes, and that many surface cells tagged with each.
  const std::vector<std::int64_t> patch_of_cell =
      IntegerArray(document.grid.cell_data, "openfoam:patch");
  ASSERT_EQ(static_cast<std::int64_t>(patch_of_cell.size()), document.grid.cells.size());
  std::size_t patches_seen = 0;
  for (std::size_t patch = 0; patch < document.openfoam->patches.size(); ++patch) {
    const OpenFoamPatch& p = document.openfoam->patches[patch];
    const std::string key = "patch " + p.name;
    ASSERT_TRUE(expected.count(key)) << key;
    ++patches_seen;
    EXPECT_EQ(p.face_count, expected.at(key)) << key;
    EXPECT_EQ(std::count(patch_of_cell.begin(), patch_of_cell.end(),
                         static_cast<std::int64_t>(patch) + 1),
              expected.at(key))
        << key;
  }
  EXPECT_EQ(patches_seen, std::count_if(expected.begin(), expected.end(), [](const auto& entry) {
              return entry.first.rfind("patch ", 0) == 0;
            }));
}

// Every volume cell is valid in the engine's orientation test (Def. 2 of the paper).
void ExpectAllValid(const MeshDocument& document) {
  absl::StatusOr<GridMesh> mesh = GridToMesh(document.grid);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  UnstructuredGrid grid = document.grid;
  ASSERT_TRUE(UpdateGridFromMesh(mesh->mesh, mesh->cell_elements, grid).ok());
  const std::vector<std::int64_t> valid = IntegerArray(grid.cell_data, "valid");
  for (std::int64_t cell = 0; cell < grid.cells.size(); ++cell) {
    if (mesh->cell_elements[cell] < 0) continue;
    EXPECT_EQ(valid[cell], 1) << "cell " << cell << " type " << int(grid.cells.types[cell]);
  }
}

TEST(OpenFoamReader, BlockMeshBoxMatchesCheckMesh) {
  const MeshDocument document = ReadCase("box_ascii");
  ExpectCheckMeshCounts("box_ascii", document);
  EXPECT_EQ(document.grid.point_count(), 5 * 4 * 4);
  EXPECT_EQ(document.format, FileFormat::kOpenFoam);
  EXPECT_EQ(document.as_read.encoding, Encoding::kAscii);
  EXPECT_EQ(FindArray(document.grid.point_data, "fixed"), nullptr) << "no polyhedra";
  ExpectAllValid(document);
}

TEST(OpenFoamReader, BinaryAndGzippedBoxesHoldTheSameMesh) {
  const MeshDocument ascii = ReadCase("box_ascii");
  for (const char* name : {"box_binary", "box_binary_gz"}) {
    SCOPED_TRACE(name);
    const MeshDocument binary = ReadCase(name);
    ExpectCheckMeshCounts(name, binary);
    EXPECT_EQ(binary.as_read.encoding, Encoding::kBinary);
    // writePrecision 17: the ASCII coordinates are the binary doubles exactly.
    EXPECT_EQ(binary.grid.points.reals, ascii.grid.points.reals);
    EXPECT_EQ(binary.grid.cells.connectivity, ascii.grid.cells.connectivity);
    EXPECT_EQ(binary.grid.cells.types, ascii.grid.cells.types);
    EXPECT_EQ(binary.openfoam->patches, ascii.openfoam->patches);
  }
  EXPECT_TRUE(ReadCase("box_binary_gz").openfoam->points_gzipped);
}

TEST(OpenFoamReader, GmshToFoamHybridMatchesCheckMesh) {
  for (const char* name : {"mixed_ascii", "mixed_binary"}) {
    SCOPED_TRACE(name);
    const MeshDocument document = ReadCase(name);
    ExpectCheckMeshCounts(name, document);
    ExpectAllValid(document);
  }
  EXPECT_EQ(ReadCase("mixed_binary").grid.points.reals, ReadCase("mixed_ascii").grid.points.reals);
}

// foamToVTK (OpenFOAM's own cell-shape matching) lists the same cells with the same points.
TEST(OpenFoamReader, HybridCellsAreFoamToVtksCells) {
  const MeshDocument document = ReadCase("mixed_ascii");
  absl::StatusOr<UnstructuredGrid> vtk =
      ParseVtk(testing::ReadText(testing::FixturePath("mixed.vtk")));
  ASSERT_TRUE(vtk.ok()) << vtk.status();
  ASSERT_EQ(vtk->point_count(), document.grid.point_count());
  for (std::int64_t i = 0; i < 3 * vtk->point_count(); ++i) {
    // foamToVTK -ascii writes 6 significant digits.
    ASSERT_NEAR(vtk->points.AsDouble(i), document.grid.points.AsDouble(i), 1e-5) << i;
  }
  const std::int64_t volume_cells = document.openfoam->cell_count;
  ASSERT_EQ(vtk->cells.size(), volume_cells);
  for (std::int64_t cell = 0; cell < volume_cells; ++cell) {
    EXPECT_EQ(vtk->cells.types[cell], document.grid.cells.types[cell]) << cell;
    const std::int64_t* ours = document.grid.cells.nodes(cell);
    const std::int64_t* theirs = vtk->cells.nodes(cell);
    EXPECT_EQ(std::set<std::int64_t>(ours, ours + document.grid.cells.node_count(cell)),
              std::set<std::int64_t>(theirs, theirs + vtk->cells.node_count(cell)))
        << cell;
  }
}

TEST(OpenFoamReader, PolyhedraAreFixedWithAllTheirPoints) {
  const MeshDocument document = ReadCase("poly_ascii");
  ExpectCheckMeshCounts("poly_ascii", document);
  ExpectAllValid(document);
  const std::vector<std::int64_t> fixed = IntegerArray(document.grid.point_data, "fixed");
  ASSERT_EQ(static_cast<std::int64_t>(fixed.size()), document.grid.point_count());
  // Independently: the points of the cells that are not in the grid are those of the faces of
  // the refined block's neighbours; every one of them is fixed and at least one hexahedron's
  // point is free (the refined cell's centre).
  std::set<std::int64_t> in_hexahedra;
  for (std::int64_t cell = 0; cell < document.grid.cells.size(); ++cell) {
    if (document.grid.cells.types[cell] != kVtkHexahedron) continue;
    const std::int64_t* nodes = document.grid.cells.nodes(cell);
    in_hexahedra.insert(nodes, nodes + 8);
  }
  std::int64_t fixed_count = std::count(fixed.begin(), fixed.end(), 1);
  EXPECT_GT(fixed_count, 0);
  EXPECT_LT(fixed_count, document.grid.point_count());
  // Points used by no hexahedron belong to polyhedra only: all fixed.
  for (std::int64_t point = 0; point < document.grid.point_count(); ++point) {
    if (!in_hexahedra.count(point)) {
      EXPECT_EQ(fixed[point], 1) << point;
    }
  }
  // Boundary faces of the polyhedra that the refinement gave extra points are polygons (VTK 7)
  // of more than 4 points; every boundary face is a surface cell, none lost.
  std::int64_t polygons = 0;
  for (std::int64_t cell = 0; cell < document.grid.cells.size(); ++cell) {
    if (document.grid.cells.types[cell] != 7) continue;
    ++polygons;
    EXPECT_GT(document.grid.cells.node_count(cell), 4) << cell;
  }
  EXPECT_GT(polygons, 0);
  std::int64_t boundary_faces = 0;
  for (const OpenFoamPatch& patch : document.openfoam->patches) boundary_faces += patch.face_count;
  EXPECT_EQ(document.grid.cells.size() - CellTypeCounts(document.grid)[kVtkHexahedron],
            boundary_faces);
}

TEST(OpenFoamReader, FindsThePolyMeshOfACaseOrItself) {
  EXPECT_EQ(FindPolyMeshDirectory(CasePath("box_ascii")).value(),
            CasePath("box_ascii") + "/constant/polyMesh");
  EXPECT_EQ(FindPolyMeshDirectory(CasePath("box_ascii") + "/constant/polyMesh").value(),
            CasePath("box_ascii") + "/constant/polyMesh");
  const absl::StatusOr<std::string> missing = FindPolyMeshDirectory(CasePath("box_ascii/system"));
  EXPECT_EQ(missing.status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(missing.status().message(),
            CasePath("box_ascii/system") +
                ": not an OpenFOAM case or polyMesh directory: it has no constant/polyMesh, no "
                "polyMesh and no faces file");
  EXPECT_EQ(FindPolyMeshDirectory(CasePath("box_ascii") + "/constant").value(),
            CasePath("box_ascii") + "/constant/polyMesh");
  // Reading through the polyMesh directory gives the same document.
  absl::StatusOr<MeshDocument> direct = ReadOpenFoam(CasePath("box_ascii") + "/constant/polyMesh");
  ASSERT_TRUE(direct.ok()) << direct.status();
  EXPECT_EQ(direct->grid.points.reals, ReadCase("box_ascii").grid.points.reals);
}

}  // namespace
}  // namespace getme::formats
