// Reading CGNS files written by other tools: regular elements of each type through meshio's UGRID
// writer and the CGNS project's aflr3_to_cgns (node orders), a hybrid mesh with boundary
// conditions from aflr3_to_cgns, and files written here with the CGNS library's own calls
// (MIXED sections, families, vertex conditions, ADF storage).

#include <cgnslib.h>
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "cgns_test_files.h"
#include "formats/cgns/cgns_groups.h"
#include "formats/cgns/cgns_reader.h"
#include "formats/grid_mesh.h"
#include "formats/mesh_file.h"
#include "getme/elements/element_quality.h"
#include "getme/elements/element_tables.h"
#include "getme/elements/vec3.h"

namespace getme::formats {
namespace {

using testing::ExpectedMesh;
using testing::FixturePath;
using testing::LibraryFileOptions;
using testing::ReadExpected;
using testing::WriteLibraryFile;

std::vector<std::int64_t> CellArray(const UnstructuredGrid& grid, const char* name) {
  const DataArray* array = FindArray(grid.cell_data, name);
  return array == nullptr ? std::vector<std::int64_t>{} : array->integers;
}

void ExpectGrid(const ExpectedMesh& expected, const UnstructuredGrid& grid) {
  EXPECT_EQ(grid.points.reals, expected.points);
  EXPECT_EQ(grid.cells.types, expected.cells.types);
  EXPECT_EQ(grid.cells.offsets, expected.cells.offsets);
  EXPECT_EQ(grid.cells.connectivity, expected.cells.connectivity);
}

struct RegularCase {
  const char* file;
  ElementType element_type;
};

void PrintTo(const RegularCase& param, std::ostream* out) { *out << param.file; }

class CgnsRegularElementTest : public ::testing::TestWithParam<RegularCase> {};

TEST_P(CgnsRegularElementTest, ReadsBackValidWithMeanRatioOne) {
  const RegularCase& param = GetParam();
  const absl::StatusOr<MeshDocument> document =
      ReadCgnsFile(FixturePath(std::string(param.file) + ".cgns"));
  ASSERT_TRUE(document.ok()) << document.status();
  ExpectGrid(ReadExpected(FixturePath(std::string(param.file) + ".json")), document->grid);

  const absl::StatusOr<GridMesh> mesh = GridToMesh(document->grid);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  ASSERT_EQ(mesh->mesh.element_count(), 1);
  EXPECT_EQ(mesh->mesh.type(0), param.element_type);
  DispatchElementType(mesh->mesh.type(0), [&]<ElementType kType>() {
    const auto nodes = GatherNodes<kType>(mesh->mesh, mesh->mesh.element_nodes(0).data());
    EXPECT_TRUE(IsValid<kType>(nodes));
    EXPECT_NEAR(MeanRatio<kType>(nodes), 1.0, 1e-12);
  });
}

INSTANTIATE_TEST_SUITE_P(
    WrittenByMeshioUgridAndAflr3ToCgns, CgnsRegularElementTest,
    ::testing::Values(RegularCase{"regular_tetra", ElementType::kTetrahedron},
                      RegularCase{"regular_pyramid", ElementType::kPyramid},
                      RegularCase{"regular_wedge", ElementType::kPrism},
                      RegularCase{"regular_hexahedron", ElementType::kHexahedron}),
    [](const ::testing::TestParamInfo<RegularCase>& info) { return std::string(info.param.file); });

TEST(CgnsRead, HybridFromAflr3ToCgnsWithBoundaryConditions) {
  const absl::StatusOr<MeshDocument> document = ReadMeshDocument(FixturePath("hybrid.cgns"));
  ASSERT_TRUE(document.ok()) << document.status();
  EXPECT_EQ(document->format, FileFormat::kCgns);
  const ExpectedMesh expected = ReadExpected(FixturePath("hybrid.json"));
  ExpectGrid(expected, document->grid);
  ASSERT_TRUE(document->cgns.has_value());
  EXPECT_EQ(document->cgns->file_type, "HDF5");
  EXPECT_EQ(document->cgns->base_name, "Base");
  EXPECT_EQ(document->cgns->zone_name, "Zone");
  const std::vector<CgnsBoundaryCondition>& bcs = document->cgns->boundary_conditions;
  ASSERT_EQ(bcs.size(), expected.bcs.size());
  std::vector<std::int64_t> owner(expected.cells.size(), 0);
  for (std::size_t i = 0; i < bcs.size(); ++i) {
    EXPECT_EQ(bcs[i].name, expected.bcs[i].name);
    EXPECT_EQ(cg_BCTypeName(static_cast<BCType_t>(bcs[i].bc_type)), expected.bcs[i].type);
    EXPECT_FALSE(bcs[i].on_nodes);
    for (const std::int64_t cell : expected.bcs[i].cells) owner[cell] = i + 1;
    // Found by name, as --fix-physical does.
    const absl::StatusOr<std::vector<std::int64_t>> cells =
        GroupCells(*document, expected.bcs[i].name);
    ASSERT_TRUE(cells.ok()) << cells.status();
    EXPECT_EQ(*cells, expected.bcs[i].cells) << bcs[i].name;
  }
  EXPECT_EQ(CellArray(document->grid, kCgnsBcArray), owner);
}

TEST(CgnsRead, MixedSectionFamiliesAndVertexConditionWrittenByTheLibrary) {
  for (const int file_type : {CG_FILE_HDF5, CG_FILE_ADF}) {
    LibraryFileOptions options;
    options.path = ::testing::TempDir() + "/library_mixed.cgns";
    options.file_type = file_type;
    const absl::StatusOr<MeshDocument> document = ReadCgnsFile(WriteLibraryFile(options));
    ASSERT_TRUE(document.ok()) << document.status();
    EXPECT_EQ(document->cgns->file_type, file_type == CG_FILE_HDF5 ? "HDF5" : "ADF");
    EXPECT_EQ(document->grid.points.reals, testing::LibraryFilePoints());
    EXPECT_EQ(document->grid.cells.connectivity, testing::LibraryFileCells().connectivity);
    EXPECT_EQ(document->grid.cells.types, testing::LibraryFileCells().types);
    EXPECT_EQ(document->cgns->families,
              (std::vector<CgnsFamily>{{"Walls", true, static_cast<int>(BCWall)}}));
    const std::vector<CgnsBoundaryCondition>& bcs = document->cgns->boundary_conditions;
    ASSERT_EQ(bcs.size(), 2u);
    EXPECT_EQ(bcs[0], (CgnsBoundaryCondition{"inlet", FamilySpecified, "Walls", false, {}}));
    EXPECT_EQ(bcs[1], (CgnsBoundaryCondition{"pins", BCWall, "", true, {0, 1}}));
    EXPECT_EQ(CellArray(document->grid, kCgnsBcArray), (std::vector<std::int64_t>{0, 0, 1}));

    // The family selects its conditions' cells; the vertex condition has nodes, no cells.
    EXPECT_EQ(*GroupCells(*document, "Walls"), (std::vector<std::int64_t>{2}));
    EXPECT_EQ(*GroupCells(*document, "pins"), (std::vector<std::int64_t>{}));
    EXPECT_EQ(*CgnsGroupNodes(*document, "pins"), (std::vector<std::int64_t>{0, 1}));
    const absl::StatusOr<std::vector<std::uint8_t>> fixed =
        SelectFixedNodes(*document, {"pins", "Walls"}, false);
    ASSERT_TRUE(fixed.ok()) << fixed.status();
    EXPECT_EQ(*fixed, (std::vector<std::uint8_t>{1, 1, 1, 0, 0, 0, 0, 0, 0, 0}));
    EXPECT_EQ(GroupCells(*document, "outlet").status(),
              absl::NotFoundError("no group 'outlet': the CGNS file's boundary conditions are "
                                  "'inlet', 'pins'; its families 'Walls'"));
  }
}

TEST(CgnsRead, PrismInVtkOrderReadsBackInverted) {
  LibraryFileOptions options;
  options.path = ::testing::TempDir() + "/library_vtk_prism.cgns";
  options.prism_in_vtk_order = true;
  const absl::StatusOr<MeshDocument> document = ReadCgnsFile(WriteLibraryFile(options));
  ASSERT_TRUE(document.ok()) << document.status();
  const absl::StatusOr<GridMesh> mesh = GridToMesh(document->grid);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  ASSERT_EQ(mesh->mesh.type(1), ElementType::kPrism);
  const auto prism =
      GatherNodes<ElementType::kPrism>(mesh->mesh, mesh->mesh.element_nodes(1).data());
  EXPECT_FALSE(IsValid<ElementType::kPrism>(prism));
  const auto tet =
      GatherNodes<ElementType::kTetrahedron>(mesh->mesh, mesh->mesh.element_nodes(0).data());
  EXPECT_NEAR(MeanRatio<ElementType::kTetrahedron>(tet), 1.0, 1e-12);
}

TEST(CgnsRead, NamedByExtensionAndFormatName) {
  EXPECT_EQ(FormatFromExtension("dir.v2/mesh.CGNS"), FileFormat::kCgns);
  const absl::StatusOr<FormatChoice> choice = ParseFormatName("cgns");
  ASSERT_TRUE(choice.ok()) << choice.status();
  EXPECT_EQ(choice->format, FileFormat::kCgns);
  EXPECT_STREQ(FormatDisplayName(FileFormat::kCgns), "CGNS");
  // Another HDF5 or ADF file is taken for CGNS; the library then says whether it is one.
  EXPECT_EQ(SniffFormat(std::string("\x89HDF\r\n\x1a\n\0\0", 10)), FileFormat::kCgns);
  EXPECT_EQ(SniffFormat(std::string("\x89HDF\r\n\x1a", 7)), std::nullopt);
}

TEST(CgnsRead, SniffedFromBytesThroughATemporaryFile) {
  LibraryFileOptions options;
  options.path = ::testing::TempDir() + "/library_sniffed.cgns";
  for (const int file_type : {CG_FILE_HDF5, CG_FILE_ADF}) {
    options.file_type = file_type;
    const std::string path = WriteLibraryFile(options);
    // No extension names the format: the content does (HDF5 signature, ADF header).
    const std::string renamed = ::testing::TempDir() + "/library_sniffed.data";
    ASSERT_EQ(std::rename(path.c_str(), renamed.c_str()), 0);
    const absl::StatusOr<MeshDocument> document = ReadMeshDocument(renamed);
    ASSERT_TRUE(document.ok()) << document.status();
    EXPECT_EQ(document->format, FileFormat::kCgns);
    EXPECT_EQ(document->grid.cells.size(), 3);
  }
}

}  // namespace
}  // namespace getme::formats
