// Round trips: VTK → MEDIT → document keeps points bit for bit and cells (grouped by kind);
// MEDIT → MEDIT keeps the extras sections verbatim, whatever the input's layout; and the files
// check_with_meshio.py reads back with meshio.

#include <gtest/gtest.h>

#include <bit>
#include <sstream>
#include <string>

#include "formats/medit/medit_reader.h"
#include "formats/medit/medit_writer.h"
#include "formats/vtk_reader.h"
#include "medit_test_util.h"
#include "vtk_test_util.h"

namespace getme::formats {
namespace {

using testing::AllSharedMeshNames;
using testing::ExpectedContent;
using testing::FixedPoints;
using testing::FixturePath;
using testing::GroupedCellOrder;
using testing::IntegerValues;
using testing::ReadText;
using testing::Reordered;
using testing::SharedMesh;

// The count on the line after a line holding just `keyword`, found by plain text search; -1 if
// the keyword is absent.
std::int64_t SectionCount(const std::string& text, const std::string& keyword) {
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (line != keyword) continue;
    std::int64_t count = -1;
    lines >> count;
    return count;
  }
  return -1;
}

std::int64_t CellsOfType(const GridCells& cells, int type) {
  std::int64_t count = 0;
  for (const std::uint8_t t : cells.types) count += t == type ? 1 : 0;
  return count;
}

void ExpectSamePointBits(const DataArray& expected, const DataArray& actual) {
  ASSERT_EQ(expected.reals.size(), actual.reals.size());
  for (std::size_t i = 0; i < expected.reals.size(); ++i) {
    ASSERT_EQ(std::bit_cast<std::uint64_t>(expected.reals[i]),
              std::bit_cast<std::uint64_t>(actual.reals[i]))
        << "coordinate " << i << ": " << expected.reals[i] << " vs " << actual.reals[i];
  }
}

MeshDocument FromVtk(const std::string& path) {
  const absl::StatusOr<UnstructuredGrid> file = ReadVtkFile(path);
  EXPECT_TRUE(file.ok()) << file.status();
  MeshDocument document;
  document.format = FileFormat::kVtkLegacy;
  if (file.ok()) document.grid = *file;
  return document;
}

std::vector<std::string> VtkInputs() {
  std::vector<std::string> paths;
  for (const std::string& name : AllSharedMeshNames()) paths.push_back(SharedMesh(name));
  paths.push_back(std::string(GETME_TEST_DATA) + "/hybrid-example.vtk");
  return paths;
}

class MeditVtkRoundTripTest : public ::testing::TestWithParam<std::string> {};

TEST_P(MeditVtkRoundTripTest, PointsBitIdenticalCellsGroupedByKind) {
  const MeshDocument document = FromVtk(GetParam());
  const UnstructuredGrid& vtk = document.grid;
  ASSERT_GT(vtk.cells.size(), 0);
  const absl::StatusOr<std::string> text = SerializeMedit(document, WriteOptions{});
  ASSERT_TRUE(text.ok()) << text.status();

  // Section sizes, counted in the text independently of the reader.
  EXPECT_EQ(SectionCount(*text, "Vertices"), vtk.point_count());
  const std::pair<const char*, int> kinds[] = {
      {"Edges", 3},   {"Triangles", 5},  {"Quadrilaterals", 9}, {"Tetrahedra", 10},
      {"Prisms", 13}, {"Hexahedra", 12}, {"Pyramids", 14}};
  for (const auto& [keyword, type] : kinds) {
    const std::int64_t cells = CellsOfType(vtk.cells, type);
    EXPECT_EQ(SectionCount(*text, keyword), cells > 0 ? cells : -1) << keyword;
  }
  const std::vector<std::int64_t> fixed = FixedPoints(vtk);
  EXPECT_EQ(SectionCount(*text, "RequiredVertices"),
            fixed.empty() ? -1 : static_cast<std::int64_t>(fixed.size()));

  const absl::StatusOr<MeshDocument> parsed = ParseMedit(*text);
  ASSERT_TRUE(parsed.ok()) << parsed.status();
  ExpectSamePointBits(vtk.points, parsed->grid.points);
  const GridCells expected = Reordered(vtk.cells, GroupedCellOrder(vtk.cells));
  EXPECT_EQ(parsed->grid.cells.types, expected.types);
  EXPECT_EQ(parsed->grid.cells.offsets, expected.offsets);
  EXPECT_EQ(parsed->grid.cells.connectivity, expected.connectivity);
  EXPECT_EQ(FixedPoints(parsed->grid), fixed);
  EXPECT_EQ(IntegerValues(parsed->grid.point_data, "medit:ref"),
            std::vector<std::int64_t>(vtk.point_count(), 0));
  EXPECT_EQ(IntegerValues(parsed->grid.cell_data, "medit:ref"),
            std::vector<std::int64_t>(expected.size(), 0));

  // MEDIT → MEDIT writes the same text again.
  const absl::StatusOr<std::string> again = SerializeMedit(*parsed, parsed->as_read);
  ASSERT_TRUE(again.ok()) << again.status();
  EXPECT_EQ(*again, *text);
}

INSTANTIATE_TEST_SUITE_P(SharedMeshesAndHybrid, MeditVtkRoundTripTest,
                         ::testing::ValuesIn(VtkInputs()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param.substr(info.param.rfind('/') + 1);
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

// getme's own layout, so the round trip must reproduce it byte for byte.
constexpr char kWithExtras[] = R"(MeshVersionFormatted 2

Dimension 3

Vertices
5
0 0 0 1
1 0 0 1
0 1 0 2
0 0 1 2
0.25 0.25 0.25 3

Edges
2
1 2 7
2 3 7

Triangles
1
1 3 2 4

Tetrahedra
2
1 2 3 5 1
1 2 5 4 1

RequiredVertices
3
4
1
2

Corners
2
1
4

Ridges
1
2

RequiredEdges
1
1

Normals
2
0 0 -1
0.57735026918962573 0.57735026918962573 0.57735026918962573

NormalAtVertices
2
1 1
5 2

Tangents
1
1 0 0

TangentAtVertices
1
2 1

AngleOfCornerBound
45

BoundingBox
0 1 0 1 0 1

End
)";

// The same content as libMeshb's free format allows it: comments, any case, tokens wrapping
// lines, tabs, CRLF line ends.
constexpr char kWithExtrasFreeFormat[] = R"(# written by hand
meshversionformatted 2 DIMENSION
3   # the dimension
VERTICES 5 0 0 0 1	1 0 0 1
0 1 0 2 0 0 1 2 0.25
  0.25 0.25 3
edges 2 1 2 7 2 3 7 triangles 1 1 3 2 4
Tetrahedra
2
1 2 3 5 1 1 2
5 4 1
# required vertices in the file's own order
RequiredVertices 3 4 1 2
corners 2 1 4 Ridges 1 2 RequiredEdges 1 1
Normals 2 0 0 -1 0.57735026918962573 0.57735026918962573 0.57735026918962573
NormalAtVertices 2 1 1 5 2 Tangents 1 1 0 0 TangentAtVertices 1 2 1
AngleOfCornerBound 45 BoundingBox 0 1 0 1 0 1
End
# trailing comment
)";

std::string WithCrLf(std::string text) {
  std::string result;
  for (const char c : text) {
    if (c == '\n') result.push_back('\r');
    result.push_back(c);
  }
  return result;
}

TEST(MeditExtrasRoundTrip, WritesBackVerbatim) {
  const absl::StatusOr<MeshDocument> document = ParseMedit(kWithExtras);
  ASSERT_TRUE(document.ok()) << document.status();
  ASSERT_TRUE(document->medit.has_value());
  std::vector<std::string> keywords;
  for (const MeditSection& section : document->medit->sections) keywords.push_back(section.keyword);
  EXPECT_EQ(keywords, (std::vector<std::string>{"Corners", "Ridges", "RequiredEdges", "Normals",
                                                "NormalAtVertices", "Tangents", "TangentAtVertices",
                                                "AngleOfCornerBound", "BoundingBox"}));
  EXPECT_EQ(document->medit->sections[3].entries,
            (std::vector<std::string>{
                "0 0 -1", "0.57735026918962573 0.57735026918962573 0.57735026918962573"}));
  EXPECT_EQ(FixedPoints(document->grid), (std::vector<std::int64_t>{0, 1, 3}));

  const absl::StatusOr<std::string> text = SerializeMedit(*document, document->as_read);
  ASSERT_TRUE(text.ok()) << text.status();
  EXPECT_EQ(*text, kWithExtras);
}

TEST(MeditExtrasRoundTrip, FreeFormatReadsAsTheCanonicalLayout) {
  const absl::StatusOr<MeshDocument> canonical = ParseMedit(kWithExtras);
  ASSERT_TRUE(canonical.ok()) << canonical.status();
  for (const std::string& variant :
       {std::string(kWithExtrasFreeFormat), WithCrLf(kWithExtrasFreeFormat)}) {
    const absl::StatusOr<MeshDocument> document = ParseMedit(variant);
    ASSERT_TRUE(document.ok()) << document.status();
    testing::ExpectSameContent(canonical->grid, document->grid);
    EXPECT_EQ(document->medit, canonical->medit);
    const absl::StatusOr<std::string> text = SerializeMedit(*document, document->as_read);
    ASSERT_TRUE(text.ok()) << text.status();
    EXPECT_EQ(*text, kWithExtras);
  }
}

TEST(MeditExtrasRoundTrip, ChangedFixedSetIsWrittenAscending) {
  absl::StatusOr<MeshDocument> document = ParseMedit(kWithExtras);
  ASSERT_TRUE(document.ok()) << document.status();
  DataArray* fixed = FindArray(document->grid.point_data, "fixed");
  ASSERT_NE(fixed, nullptr);
  fixed->integers[4] = 1;  // vertex 5 joins 4, 1, 2
  const absl::StatusOr<std::string> text = SerializeMedit(*document, document->as_read);
  ASSERT_TRUE(text.ok()) << text.status();
  EXPECT_NE(text->find("\nRequiredVertices\n4\n1\n2\n4\n5\n\n"), std::string::npos) << *text;
}

TEST(MeditVersionRoundTrip, SinglePrecisionStaysVersionOneUntilCoordinatesNeedDoubles) {
  constexpr char kVersionOne[] =
      "MeshVersionFormatted 1\n\nDimension 3\n\nVertices\n4\n0 0 0 0\n0.5 0 0 0\n0 0.25 0 0\n"
      "0 0 0.125 0\n\nTetrahedra\n1\n1 2 3 4 0\n\nEnd\n";
  absl::StatusOr<MeshDocument> document = ParseMedit(kVersionOne);
  ASSERT_TRUE(document.ok()) << document.status();
  absl::StatusOr<std::string> text = SerializeMedit(*document, document->as_read);
  ASSERT_TRUE(text.ok()) << text.status();
  EXPECT_EQ(*text, kVersionOne);
  // A smoothed coordinate that is no float: single-precision readers would round it.
  document->grid.points.reals[3] = 0.1;
  text = SerializeMedit(*document, document->as_read);
  ASSERT_TRUE(text.ok()) << text.status();
  EXPECT_EQ(text->rfind("MeshVersionFormatted 2\n", 0), 0u) << *text;
  EXPECT_NE(text->find("\n0.1 0 0 0\n"), std::string::npos) << *text;
}

// getme's own files for check_with_meshio.py (a ctest fixture run after this suite), each with
// the sidecar of what meshio must read: grid points, cells grouped by kind, refs.
void WriteForMeshio(const MeshDocument& document, const std::string& name) {
  const absl::StatusOr<std::string> text = SerializeMedit(document, WriteOptions{});
  ASSERT_TRUE(text.ok()) << text.status();
  testing::WriteText(FixturePath(name + ".mesh"), *text);
  const UnstructuredGrid& grid = document.grid;
  const std::vector<std::int64_t> order = GroupedCellOrder(grid.cells);
  ExpectedContent expected;
  expected.points = grid.points.reals;
  expected.point_refs = IntegerValues(grid.point_data, "medit:ref");
  if (expected.point_refs.empty()) expected.point_refs.assign(grid.point_count(), 0);
  expected.cells = Reordered(grid.cells, order);
  const std::vector<std::int64_t> refs = IntegerValues(grid.cell_data, "medit:ref");
  for (const std::int64_t cell : order) {
    expected.cell_refs.push_back(refs.empty() ? 0 : refs[cell]);
  }
  testing::WriteExpected(FixturePath(name + ".expected"), expected);
}

TEST(MeditForMeshio, WritesGetmeFilesForMeshio) {
  WriteForMeshio(FromVtk(std::string(GETME_TEST_DATA) + "/hybrid-example.vtk"),
                 "ours_hybrid_example");
  WriteForMeshio(FromVtk(SharedMesh("6-wedge-prism.vtk")), "ours_6_wedge_prism");
  WriteForMeshio(FromVtk(SharedMesh("mixed-hex-pyr-tet.vtk")), "ours_mixed_hex_pyr_tet");
  const absl::StatusOr<MeshDocument> hybrid =
      ParseMedit(ReadText(FixturePath("hybrid_meshio.mesh")));
  ASSERT_TRUE(hybrid.ok()) << hybrid.status();
  WriteForMeshio(*hybrid, "ours_from_hybrid_meshio");
}

}  // namespace
}  // namespace getme::formats
