// SU2 → SU2 keeps every row's node order (the mirrored elements written back as the file had
// them), the markers and the tail; the writer's layout, names and refusals; the files that
// check_meshio_reads_ours.py then gives to meshio.

#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "formats/file_io.h"
#include "formats/su2/su2_reader.h"
#include "formats/su2/su2_writer.h"
#include "su2_test_util.h"
#include "vtk_test_util.h"

namespace getme::formats {
namespace {

using testing::ReadText;
using testing::SectionRows;
using testing::SharedSu2;
using testing::Su2FixturePath;

// The point rows as numbers (the writer's decimals differ from the file's, the values do not).
std::vector<double> PointValues(const std::string& text) {
  std::vector<double> values;
  for (const auto& row : SectionRows(text, "NPOIN=")) {
    for (std::size_t k = 0; k < 3; ++k) {
      double value = 0;
      EXPECT_TRUE(absl::SimpleAtod(row[k], &value));
      values.push_back(value);
    }
  }
  return values;
}

void ExpectSameRows(const std::string& original, const std::string& written) {
  EXPECT_EQ(SectionRows(written, "NELEM="), SectionRows(original, "NELEM="));
  EXPECT_EQ(PointValues(written), PointValues(original));
}

TEST(Su2RoundTrip, KnowlesMixedBeamWritesMirroredElementsBackInTheFilesOrder) {
  const std::string original = ReadText(SharedSu2("knowles-mixed-beam.su2"));
  const absl::StatusOr<MeshDocument> document = ParseSu2(original);
  ASSERT_TRUE(document.ok()) << document.status();
  const absl::StatusOr<std::string> written = SerializeSu2(*document, document->as_read);
  ASSERT_TRUE(written.ok()) << written.status();
  // Element rows token for token (type, nodes in the file's order, index).
  ExpectSameRows(original, *written);
  for (const char* marker : {"MARKER_TAG= clamped", "MARKER_TAG= load"}) {
    EXPECT_EQ(SectionRows(*written, marker), SectionRows(original, marker)) << marker;
  }
  const absl::StatusOr<MeshDocument> again = ParseSu2(*written);
  ASSERT_TRUE(again.ok()) << again.status();
  EXPECT_EQ(again->su2, document->su2);
  testing::ExpectSameContent(document->grid, again->grid);
}

TEST(Su2RoundTrip, BrickPrismKeepsMarkersAndTail) {
  const std::string original = ReadText(SharedSu2("brick-prism.su2"));
  const absl::StatusOr<MeshDocument> document = ParseSu2(original);
  ASSERT_TRUE(document.ok()) << document.status();
  const absl::StatusOr<std::string> written = SerializeSu2(*document, document->as_read);
  ASSERT_TRUE(written.ok()) << written.status();
  ExpectSameRows(original, *written);
  for (const char* marker : {"MARKER_TAG= x_m", "MARKER_TAG= y_p", "MARKER_TAG= z_p"}) {
    EXPECT_EQ(SectionRows(*written, marker), SectionRows(original, marker)) << marker;
  }
  const std::size_t tail = original.find("NPERIODIC=");
  ASSERT_NE(tail, std::string::npos);
  EXPECT_EQ(written->substr(written->size() - (original.size() - tail)), original.substr(tail));
}

TEST(Su2RoundTrip, MeshioLayoutStaysWithoutIndices) {
  const std::string original = ReadText(Su2FixturePath("hybrid_meshio.su2"));
  const absl::StatusOr<MeshDocument> document = ParseSu2(original);
  ASSERT_TRUE(document.ok()) << document.status();
  const absl::StatusOr<std::string> written = SerializeSu2(*document, document->as_read);
  ASSERT_TRUE(written.ok()) << written.status();
  ExpectSameRows(original, *written);
  EXPECT_EQ(SectionRows(*written, "NELEM=")[0].size(), 9u);  // "12" and 8 nodes, no index
}

// One hexahedron listed mirror-wise (bottom quad clockwise seen from the top) and one tangled:
// the unit cube with node 6 pulled through the bottom face, so only some corners are negative.
constexpr char kMirroredAndTangled[] =
    "NDIME= 3\n"
    "NELEM= 2\n"
    "12 0 3 2 1 4 7 6 5 0\n"
    "12 8 9 10 11 12 13 14 15 1\n"
    "NPOIN= 16\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "2 0 0\n3 0 0\n3 1 0\n2 1 0\n2 0 1\n3 0 1\n3 1 -0.5\n2 1 1\n"
    "NMARK= 0\n";

TEST(Su2RoundTrip, OnlyWhollyMirroredElementsAreRenumbered) {
  const absl::StatusOr<MeshDocument> document = ParseSu2(kMirroredAndTangled);
  ASSERT_TRUE(document.ok()) << document.status();
  EXPECT_EQ(document->su2->mirrored_cells, (std::vector<std::int64_t>{0}));
  const GridCells& cells = document->grid.cells;
  EXPECT_EQ(std::vector<std::int64_t>(cells.nodes(0), cells.nodes(0) + 8),
            (std::vector<std::int64_t>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(std::vector<std::int64_t>(cells.nodes(1), cells.nodes(1) + 8),
            (std::vector<std::int64_t>{8, 9, 10, 11, 12, 13, 14, 15}));
  EXPECT_EQ(testing::InvalidVolumeCells(document->grid), 1);  // the tangled one, left as it is
  const absl::StatusOr<std::string> written = SerializeSu2(*document, document->as_read);
  ASSERT_TRUE(written.ok()) << written.status();
  EXPECT_EQ(SectionRows(*written, "NELEM="), SectionRows(kMirroredAndTangled, "NELEM="));
}

// A document from another format: Gmsh physical groups name the markers, rows get SU2's indices,
// arrays a .su2 cannot hold are left out.
TEST(Su2Writer, WritesGmshGroupsAsNamedMarkers) {
  MeshDocument document;
  document.format = FileFormat::kGmsh;
  UnstructuredGrid& grid = document.grid;
  grid.points.components = 3;
  grid.points.reals = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1.5};
  grid.cells.Add(10, {0, 1, 2, 3});
  grid.cells.Add(5, {0, 2, 1});
  grid.cells.Add(5, {0, 1, 3});
  grid.cells.Add(1, {3});
  DataArray physical;
  physical.name = "gmsh:physical";
  physical.type = VtkDataType::kInt;
  physical.integers = {1, 7, 8, 9};
  DataArray quality;
  quality.name = "mean_ratio";
  quality.reals = {1, -1, -1, -1};
  grid.cell_data.push_back({VtkAttributeKind::kScalars, physical.name, "default", {physical}});
  grid.cell_data.push_back({VtkAttributeKind::kScalars, quality.name, "default", {quality}});
  GmshExtras gmsh;
  gmsh.physical_names = {{2, 7, "bottom"}, {3, 1, "volume"}};
  document.gmsh = gmsh;
  const absl::StatusOr<std::string> written = SerializeSu2(document, WriteOptions{});
  ASSERT_TRUE(written.ok()) << written.status();
  EXPECT_EQ(*written,
            "NDIME= 3\n"
            "NELEM= 1\n"
            "10 0 1 2 3 0\n"
            "NPOIN= 4\n"
            "0 0 0 0\n1 0 0 1\n0 1 0 2\n0 0 1.5 3\n"
            "NMARK= 2\n"
            "MARKER_TAG= bottom\nMARKER_ELEMS= 1\n5 0 2 1\n"
            "MARKER_TAG= 8\nMARKER_ELEMS= 1\n5 0 1 3\n");
  const absl::StatusOr<MeshDocument> again = ParseSu2(*written);
  ASSERT_TRUE(again.ok()) << again.status();
  EXPECT_EQ(again->su2->markers, (std::vector<Su2Marker>{{"bottom", 1}, {"8", 8}}));
}

TEST(Su2Writer, RefusesWhatSu2CannotHold) {
  MeshDocument document;
  document.grid.points.components = 3;
  document.grid.points.reals = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0,
                                0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
  WriteOptions binary;
  binary.encoding = Encoding::kBinary;
  EXPECT_EQ(SerializeSu2(document, binary).status(),
            absl::InvalidArgumentError(
                "SU2 native meshes are ASCII only (SU2 reads binary meshes as CGNS)"));
  document.grid.cells.Add(11, {0, 1, 2, 3, 4, 5, 6, 7});
  EXPECT_EQ(SerializeSu2(document, WriteOptions{}).status(),
            absl::InvalidArgumentError(
                "cell 0: VTK type 11 (voxel) cannot be written to SU2, which holds tetrahedra, "
                "hexahedra, prisms, pyramids and boundary triangles, quads and lines"));
  document.grid.cells = GridCells{};
  document.grid.cells.Add(10, {0, 1, 2, 8});
  EXPECT_EQ(SerializeSu2(document, WriteOptions{}).status(),
            absl::InvalidArgumentError("cell 0: node 8 out of range 0..7"));
  document.grid.cells = GridCells{};
  document.grid.cells.Add(5, {0, 1, 2});
  Su2Extras extras;
  extras.markers = {{" wall", 0}};
  document.su2 = extras;
  DataArray tags;
  tags.name = "su2:tag";
  tags.type = VtkDataType::kInt;
  tags.integers = {0};
  document.grid.cell_data.push_back({VtkAttributeKind::kScalars, tags.name, "default", {tags}});
  EXPECT_EQ(SerializeSu2(document, WriteOptions{}).status(),
            absl::InvalidArgumentError(
                "marker name ' wall' cannot be written to SU2: it is empty, holds '%' or a line "
                "break, or starts or ends with a space"));
  document.grid.points.reals[4] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(SerializeSu2(document, WriteOptions{}).status(),
            absl::InvalidArgumentError(
                "point 1: coordinate 1 is not a finite number, which an SU2 mesh cannot hold"));
}

// A marker name is the rest of its line: inner spaces and '=' survive a round trip.
TEST(Su2RoundTrip, MarkerNamesKeepInnerSpacesAndEquals) {
  const std::string text =
      "NDIME= 3\nNELEM= 1\n10 0 1 2 3\nNPOIN= 4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\nNMARK= 2\n"
      "MARKER_TAG=  inlet wall \nMARKER_ELEMS= 1\n5 0 2 1\nMARKER_TAG= a=b\nMARKER_ELEMS= 0\n";
  const absl::StatusOr<MeshDocument> document = ParseSu2(text);
  ASSERT_TRUE(document.ok()) << document.status();
  EXPECT_EQ(document->su2->markers, (std::vector<Su2Marker>{{"inlet wall", 1}, {"a=b", 2}}));
  const absl::StatusOr<std::string> written = SerializeSu2(*document, document->as_read);
  ASSERT_TRUE(written.ok()) << written.status();
  const absl::StatusOr<MeshDocument> again = ParseSu2(*written);
  ASSERT_TRUE(again.ok()) << again.status();
  EXPECT_EQ(again->su2, document->su2);
}

// Files for check_meshio_reads_ours.py (formats_su2_meshio_reads_ours), beside the originals
// it compares them with.
TEST(Su2Outputs, WriteForMeshio) {
  for (const char* name : {"knowles-mixed-beam", "brick-prism"}) {
    const absl::StatusOr<MeshDocument> document =
        ParseSu2(ReadText(SharedSu2(absl::StrCat(name, ".su2"))));
    ASSERT_TRUE(document.ok()) << document.status();
    const absl::StatusOr<std::string> written = SerializeSu2(*document, document->as_read);
    ASSERT_TRUE(written.ok()) << written.status();
    ASSERT_TRUE(
        WriteFileAtomically(Su2FixturePath(absl::StrCat("ours_", name, ".su2")), *written).ok());
  }
}

}  // namespace
}  // namespace getme::formats
