// CGNS → getme's writer → CGNS: points, cells, boundary conditions and families survive; a grid
// whose types alternate is written as MIXED sections; conditions derived from Gmsh physical
// groups when the document has no CGNS ones; what cannot be written is refused by name.

#include <cgnslib.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cgns_test_files.h"
#include "formats/cgns/cgns_reader.h"
#include "formats/cgns/cgns_writer.h"
#include "formats/mesh_file.h"

namespace getme::formats {
namespace {

using testing::FixturePath;
using testing::LibraryFileOptions;
using testing::WriteLibraryFile;

std::string OutputPath(const std::string& name) {
  // Kept in the fixture directory for check_with_cgns_tools.py (formats_cgns_tools_read_ours).
  return FixturePath("ours_" + name + ".cgns");
}

MeshDocument ReadOrDie(const std::string& path) {
  absl::StatusOr<MeshDocument> document = ReadCgnsFile(path);
  EXPECT_TRUE(document.ok()) << path << ": " << document.status();
  return document.ok() ? *std::move(document) : MeshDocument{};
}

TEST(CgnsRoundTrip, HybridFromAflr3ToCgnsSurvives) {
  const MeshDocument read = ReadOrDie(FixturePath("hybrid.cgns"));
  ASSERT_TRUE(WriteCgnsFile(OutputPath("hybrid"), read).ok());
  const MeshDocument again = ReadOrDie(OutputPath("hybrid"));
  EXPECT_EQ(again.grid.points.reals, read.grid.points.reals);
  EXPECT_EQ(again.grid.cells.types, read.grid.cells.types);
  EXPECT_EQ(again.grid.cells.connectivity, read.grid.cells.connectivity);
  ASSERT_TRUE(again.cgns.has_value());
  EXPECT_EQ(again.cgns->boundary_conditions, read.cgns->boundary_conditions);
  EXPECT_EQ(FindArray(again.grid.cell_data, kCgnsBcArray)->integers,
            FindArray(read.grid.cell_data, kCgnsBcArray)->integers);
  // The grid's typed runs stay typed sections: four volume types, triangles, quads.
  EXPECT_EQ(again.cgns->zone_name, "Zone");
}

TEST(CgnsRoundTrip, FamiliesVertexConditionsAndAdfInput) {
  LibraryFileOptions options;
  options.path = ::testing::TempDir() + "/round_trip_adf.cgns";
  options.file_type = CG_FILE_ADF;
  const MeshDocument read = ReadOrDie(WriteLibraryFile(options));
  ASSERT_EQ(read.cgns->file_type, "ADF");
  ASSERT_TRUE(WriteCgnsFile(OutputPath("families"), read).ok());
  const MeshDocument again = ReadOrDie(OutputPath("families"));
  EXPECT_EQ(again.cgns->file_type, "HDF5");  // written as HDF5 whatever was read
  EXPECT_EQ(again.grid.points.reals, read.grid.points.reals);
  EXPECT_EQ(again.grid.cells.connectivity, read.grid.cells.connectivity);
  EXPECT_EQ(again.cgns->families, read.cgns->families);
  EXPECT_EQ(again.cgns->boundary_conditions, read.cgns->boundary_conditions);
}

TEST(CgnsRoundTrip, AlternatingTypesBecomeMixedSectionsInGridOrder) {
  // 20 cells alternating tetrahedron / prism: 20 runs, more than typed sections are used for.
  MeshDocument document;
  document.grid.points.components = 3;
  const std::vector<double> points = testing::LibraryFilePoints();
  GridCells cells;
  for (int copy = 0; copy < 10; ++copy) {
    const std::int64_t first = copy * 10;
    for (std::size_t i = 0; i < points.size(); ++i) {
      document.grid.points.reals.push_back(points[i] + (i % 3 == 2 ? 2.0 * copy : 0.0));
    }
    cells.Add(10, {first, first + 1, first + 2, first + 3});
    cells.Add(13, {first + 4, first + 6, first + 5, first + 7, first + 9, first + 8});
  }
  document.grid.cells = cells;
  ASSERT_TRUE(WriteCgnsFile(OutputPath("mixed"), document).ok());
  const MeshDocument again = ReadOrDie(OutputPath("mixed"));
  EXPECT_EQ(again.grid.points.reals, document.grid.points.reals);
  EXPECT_EQ(again.grid.cells.types, cells.types);
  EXPECT_EQ(again.grid.cells.connectivity, cells.connectivity);
}

TEST(CgnsRoundTrip, GmshPhysicalGroupsBecomeBoundaryConditions) {
  LibraryFileOptions options;
  options.path = ::testing::TempDir() + "/physical.cgns";
  MeshDocument document = ReadOrDie(WriteLibraryFile(options));
  // As if read from a Gmsh file: no CGNS extras, the triangle in physical group 7 "top".
  document.cgns.reset();
  document.grid.cell_data.clear();
  VtkAttribute physical;
  physical.name = "gmsh:physical";
  DataArray tags;
  tags.name = "gmsh:physical";
  tags.type = VtkDataType::kInt32;
  tags.integers = {1, 1, 7};
  physical.arrays.push_back(tags);
  document.grid.cell_data.push_back(physical);
  document.gmsh.emplace();
  document.gmsh->physical_names.push_back({2, 7, "top"});
  ASSERT_TRUE(WriteCgnsFile(OutputPath("physical"), document).ok());
  const MeshDocument again = ReadOrDie(OutputPath("physical"));
  ASSERT_EQ(again.cgns->boundary_conditions.size(), 1u);
  EXPECT_EQ(again.cgns->boundary_conditions[0].name, "top");
  EXPECT_EQ(again.cgns->boundary_conditions[0].bc_type, BCTypeUserDefined);
  EXPECT_EQ(*GroupCells(again, "top"), (std::vector<std::int64_t>{2}));
}

TEST(CgnsRoundTrip, SurfaceCellsAreWrittenAfterTheVolumes) {
  LibraryFileOptions options;
  options.path = ::testing::TempDir() + "/reorder.cgns";
  MeshDocument document = ReadOrDie(WriteLibraryFile(options));
  // The triangle first, as Gmsh files list their surfaces before the volumes.
  GridCells reordered;
  reordered.Add(5, {0, 2, 1});
  reordered.Add(10, {0, 1, 2, 3});
  reordered.Add(13, {4, 6, 5, 7, 9, 8});
  document.grid.cells = reordered;
  FindArray(document.grid.cell_data, kCgnsBcArray)->integers = {1, 0, 0};
  ASSERT_TRUE(WriteCgnsFile(OutputPath("reordered"), document).ok());
  const MeshDocument again = ReadOrDie(OutputPath("reordered"));
  EXPECT_EQ(again.grid.cells.types, (std::vector<std::uint8_t>{10, 13, 5}));
  EXPECT_EQ(FindArray(again.grid.cell_data, kCgnsBcArray)->integers,
            (std::vector<std::int64_t>{0, 0, 1}));
}

TEST(CgnsRoundTrip, PointArraysSurviveAsVertexSolution) {
  LibraryFileOptions options;
  options.path = ::testing::TempDir() + "/fixed.cgns";
  MeshDocument document = ReadOrDie(WriteLibraryFile(options));
  VtkAttribute fixed;
  fixed.name = "fixed";
  DataArray flags;
  flags.name = "fixed";
  flags.type = VtkDataType::kInt32;
  flags.integers = {1, 0, 0, 1, 0, 0, 0, 0, 0, 1};
  fixed.arrays.push_back(flags);
  document.grid.point_data.push_back(fixed);
  ASSERT_TRUE(WriteCgnsFile(OutputPath("fixed"), document).ok());
  const MeshDocument again = ReadOrDie(OutputPath("fixed"));
  const DataArray* read = FindArray(again.grid.point_data, "fixed");
  ASSERT_NE(read, nullptr);
  EXPECT_EQ(read->integers, flags.integers);
}

TEST(CgnsRoundTrip, ConditionWithoutElementsIsLeftOut) {
  LibraryFileOptions options;
  options.path = ::testing::TempDir() + "/emptied.cgns";
  MeshDocument document = ReadOrDie(WriteLibraryFile(options));
  // 'inlet' loses its triangle: CGNS cannot store an empty point set.
  FindArray(document.grid.cell_data, kCgnsBcArray)->integers = {0, 0, 0};
  const std::string path = ::testing::TempDir() + "/emptied_out.cgns";
  ASSERT_TRUE(WriteCgnsFile(path, document).ok());
  const MeshDocument again = ReadOrDie(path);
  ASSERT_EQ(again.cgns->boundary_conditions.size(), 1u);
  EXPECT_EQ(again.cgns->boundary_conditions[0].name, "pins");
}

TEST(CgnsRoundTrip, MissingDirectoryIsNotFound) {
  const MeshDocument document = ReadOrDie(FixturePath("regular_tetra.cgns"));
  EXPECT_EQ(
      WriteCgnsFile("/nonexistent/out.cgns", document),
      absl::NotFoundError("cannot create '/nonexistent/out.cgns.tmp': No such file or directory"));
}

TEST(CgnsRoundTrip, CellsCgnsCannotHoldAreRefused) {
  MeshDocument document = ReadOrDie(FixturePath("regular_tetra.cgns"));
  document.grid.cells.Add(24, {0, 1, 2, 3, 0, 1, 2, 3, 0, 1});  // quadratic tetra
  EXPECT_EQ(WriteCgnsFile(::testing::TempDir() + "/refused.cgns", document),
            absl::InvalidArgumentError(
                "cell 1: VTK type 24 (quadratic_tetra) with 10 nodes cannot be written to CGNS "
                "(TETRA_4, PYRA_5, PENTA_6, HEXA_8, TRI_3, QUAD_4, BAR_2, NODE and MIXED sections "
                "of these)"));
  MeshDocument surface_only = ReadOrDie(FixturePath("regular_tetra.cgns"));
  surface_only.grid.cells = GridCells{};
  surface_only.grid.cells.Add(5, {0, 1, 2});
  EXPECT_EQ(WriteMeshDocument(::testing::TempDir() + "/surface.cgns", surface_only,
                              FileFormat::kCgns, WriteOptions{}),
            absl::InvalidArgumentError(
                absl::StrCat("cannot write '", ::testing::TempDir(),
                             "/surface.cgns': no volume cells: a CGNS zone of cell dimension 3 "
                             "needs tetrahedra, pyramids, prisms or hexahedra")));
}

}  // namespace
}  // namespace getme::formats
