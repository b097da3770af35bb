// Exodus → Exodus keeps points, blocks (ids, names, type spellings), side sets, node sets and
// number maps; a grid from another format is written in blocks by type. The files written here
// (ours_*.exo) are read back by meshio in check_with_meshio.py.

#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "exodus_test_util.h"
#include "formats/exodus/exodus_reader.h"
#include "formats/exodus/exodus_writer.h"
#include "formats/mesh_file.h"

namespace getme::formats {
namespace {

using testing::CellIntegers;
using testing::CellRows;
using testing::ExodusFixture;
using testing::ExpectExodusContent;
using testing::ReadExodusExpected;

MeshDocument MustRead(const std::string& path) {
  absl::StatusOr<MeshDocument> document = ReadExodus(path);
  EXPECT_TRUE(document.ok()) << document.status();
  return document.ok() ? *std::move(document) : MeshDocument{};
}

class ExodusRoundTripTest : public ::testing::TestWithParam<const char*> {};

TEST_P(ExodusRoundTripTest, KeepsEverythingItRead) {
  const std::string name = GetParam();
  const MeshDocument original = MustRead(ExodusFixture(name + ".exo"));
  ExpectExodusContent(ReadExodusExpected(name), original);
  ASSERT_TRUE(original.exodus.has_value());

  const std::string written = ExodusFixture("ours_" + name + ".exo");
  ASSERT_TRUE(WriteExodus(written, original, original.as_read).ok());
  const MeshDocument again = MustRead(written);
  ExpectExodusContent(ReadExodusExpected(name), again);
  ASSERT_TRUE(again.exodus.has_value());
  EXPECT_EQ(*again.exodus, *original.exodus);
}

INSTANTIATE_TEST_SUITE_P(AllVariants, ExodusRoundTripTest,
                         ::testing::Values("hybrid", "hybrid_classic", "hybrid_netcdf4",
                                           "hybrid_meshio"));

TEST(ExodusRoundTrip, HybridKeepsNamesIdsMapsAndTitle) {
  const MeshDocument document = MustRead(ExodusFixture("hybrid.exo"));
  ASSERT_TRUE(document.exodus.has_value());
  const ExodusExtras& extras = *document.exodus;
  EXPECT_EQ(extras.title, "hybrid test mesh");
  ASSERT_EQ(extras.blocks.size(), 5u);
  EXPECT_EQ(extras.blocks[0].id, 100);
  EXPECT_EQ(extras.blocks[0].name, "tetra_block");
  EXPECT_EQ(extras.blocks[0].topology, "TETRA");
  EXPECT_EQ(extras.blocks[3].topology, "HEX8");
  EXPECT_EQ(extras.blocks[4].topology, "SHELL4");
  ASSERT_EQ(extras.side_sets.size(), 2u);
  EXPECT_EQ(extras.side_sets[0].name, "inlet");
  EXPECT_EQ(extras.side_sets[0].elements, (std::vector<std::int64_t>{1, 4, 5}));
  EXPECT_EQ(extras.side_sets[0].sides, (std::vector<std::int64_t>{4, 3, 5}));
  ASSERT_EQ(extras.node_number_map.size(), 46u);
  EXPECT_EQ(extras.node_number_map[2], 1006);
  ASSERT_EQ(extras.element_number_map.size(), 9u);
  EXPECT_EQ(extras.element_number_map[8], 508);
}

TEST(ExodusRoundTrip, MovedPointsAreWrittenBitForBit) {
  MeshDocument document = MustRead(ExodusFixture("hybrid.exo"));
  for (double& value : document.grid.points.reals) value = value * 1.1 + 1e-17;
  const std::string written = ExodusFixture("ours_moved.exo");
  ASSERT_TRUE(WriteExodus(written, document, document.as_read).ok());
  const MeshDocument again = MustRead(written);
  EXPECT_EQ(again.grid.points.reals, document.grid.points.reals);
  EXPECT_EQ(CellRows(again.grid.cells), CellRows(document.grid.cells));
}

// A grid from another format: VTK order, types interleaved, no Exodus extras.
MeshDocument InterleavedGrid() {
  MeshDocument document;
  document.format = FileFormat::kVtkLegacy;
  UnstructuredGrid& grid = document.grid;
  grid.points.components = 3;
  for (int k = 0; k < 12; ++k) {
    grid.points.reals.insert(grid.points.reals.end(),
                             {double(k % 3), double(k / 3), double(k % 2)});
  }
  grid.cells.Add(10, {0, 1, 2, 3});
  grid.cells.Add(12, {0, 1, 2, 3, 4, 5, 6, 7});
  grid.cells.Add(9, {4, 5, 6, 7});
  grid.cells.Add(10, {4, 5, 6, 7});
  grid.cells.Add(13, {0, 1, 2, 3, 4, 5});
  grid.cells.Add(14, {7, 8, 9, 10, 11});
  return document;
}

TEST(ExodusRoundTrip, OtherFormatsGridIsGroupedByTypeInVtkOrder) {
  const MeshDocument document = InterleavedGrid();
  const std::string written = ExodusFixture("ours_interleaved.exo");
  ASSERT_TRUE(WriteExodus(written, document, document.as_read).ok());
  const MeshDocument again = MustRead(written);
  EXPECT_EQ(CellRows(again.grid.cells),
            (std::vector<std::vector<std::int64_t>>{{10, 0, 1, 2, 3},
                                                    {10, 4, 5, 6, 7},
                                                    {12, 0, 1, 2, 3, 4, 5, 6, 7},
                                                    {9, 4, 5, 6, 7},
                                                    {13, 0, 1, 2, 3, 4, 5},
                                                    {14, 7, 8, 9, 10, 11}}));
  EXPECT_EQ(CellIntegers(again.grid, "exodus:block"),
            (std::vector<std::int64_t>{1, 1, 2, 3, 4, 5}));
  ASSERT_TRUE(again.exodus.has_value());
  std::vector<std::string> names, types;
  for (const ExodusBlock& block : again.exodus->blocks) {
    names.push_back(block.name);
    types.push_back(block.topology);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"tetra", "hexahedron", "quad", "wedge", "pyramid"}));
  EXPECT_EQ(types, (std::vector<std::string>{"TETRA", "HEX8", "SHELL4", "WEDGE", "PYRAMID"}));
}

// The quality arrays of a smoothed mesh become element variables; check_with_meshio.py reads
// them back from ours_quality.exo (meshio's cell_data "quality", in block order).
TEST(ExodusRoundTrip, OneComponentCellArraysBecomeElementVariables) {
  MeshDocument document = InterleavedGrid();
  VtkAttribute attribute;
  attribute.name = "quality";
  DataArray values;
  values.name = "quality";
  values.reals = {0.0, 0.5, 1.0, 1.5, 2.0, 2.5};
  attribute.arrays.push_back(values);
  document.grid.cell_data.push_back(attribute);
  ASSERT_TRUE(WriteExodus(ExodusFixture("ours_quality.exo"), document, {}).ok());
}

TEST(ExodusRoundTrip, BytesAreNetcdf64BitOffsetAndParseBack) {
  const MeshDocument document = MustRead(ExodusFixture("hybrid.exo"));
  const absl::StatusOr<std::string> bytes = SerializeExodus(document, document.as_read);
  ASSERT_TRUE(bytes.ok()) << bytes.status();
  ASSERT_GE(bytes->size(), 4u);
  EXPECT_EQ(bytes->substr(0, 4), std::string("CDF\x02", 4));
  EXPECT_EQ(SniffFormat(*bytes), FileFormat::kExodus);
  const absl::StatusOr<MeshDocument> again = ParseMeshDocument(*bytes, FileFormat::kExodus);
  ASSERT_TRUE(again.ok()) << again.status();
  EXPECT_EQ(again->exodus, document.exodus);
  EXPECT_EQ(CellRows(again->grid.cells), CellRows(document.grid.cells));
}

TEST(ExodusRoundTrip, ExtensionsAndNames) {
  for (const char* path : {"a.exo", "b.E", "c.ex2", "d.g"}) {
    EXPECT_EQ(FormatFromExtension(path), FileFormat::kExodus) << path;
  }
  EXPECT_EQ(ParseFormatName("exodus")->format, FileFormat::kExodus);
  EXPECT_EQ(ParseFormatName("EXO")->format, FileFormat::kExodus);
  EXPECT_STREQ(FormatDisplayName(FileFormat::kExodus), "Exodus II");
  // netCDF-4 (HDF5) Exodus files are left to the extension: the HDF5 signature is CGNS's.
  EXPECT_EQ(SniffFormat(std::string("CDF\x01", 4)), FileFormat::kExodus);
  EXPECT_EQ(SniffFormat(std::string("CDF\x05", 4)), FileFormat::kExodus);
  EXPECT_NE(SniffFormat(std::string("\x89HDF\r\n\x1a\n", 8)), FileFormat::kExodus);
}

TEST(ExodusWriter, FaceThatIsNoElementSideIsRefused) {
  MeshDocument document = MustRead(ExodusFixture("hybrid.exo"));
  // The first face of side set 1 ("inlet") now joins nodes of two different elements.
  GridCells& cells = document.grid.cells;
  const std::int64_t face = 9;
  ASSERT_EQ(CellIntegers(document.grid, "exodus:sideset")[face], 1);
  cells.connectivity[cells.offsets[face]] = 45;
  const absl::Status status = WriteExodus(ExodusFixture("ours_refused.exo"), document, {});
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(status.message(),
            "side set 1 ('inlet'): cell 9 (nodes 45 2 1) is no side of a volume "
            "element");
}

TEST(ExodusWriter, CellsExodusCannotHoldAreRefused) {
  MeshDocument document = InterleavedGrid();
  document.grid.cells.Add(11, {0, 1, 2, 3, 4, 5, 6, 7});  // VTK_VOXEL
  const absl::Status status = WriteExodus(ExodusFixture("ours_voxel.exo"), document, {});
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_EQ(status.message(),
            "cell 6: a VTK voxel cell (type 11) cannot be written to Exodus: getme writes tetra, "
            "pyramid, wedge, hexahedron, triangle, quad, line and vertex cells");
}

}  // namespace
}  // namespace getme::formats
