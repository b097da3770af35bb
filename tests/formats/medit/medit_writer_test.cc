// Writing grids that did not come from MEDIT: refs from other formats' arrays, cells MEDIT
// cannot hold, interleaved kinds, the .sol beside the .mesh, malformed extras.

#include "formats/medit/medit_writer.h"

#include <gtest/gtest.h>

#include <string>

#include "formats/medit/medit_reader.h"
#include "medit_test_util.h"

namespace getme::formats {
namespace {

DataArray Array(std::string name, VtkDataType type, int components, std::vector<double> values) {
  DataArray array;
  array.name = std::move(name);
  array.type = type;
  array.components = components;
  if (IsIntegerType(type)) {
    for (const double v : values) array.integers.push_back(static_cast<std::int64_t>(v));
  } else {
    array.reals = std::move(values);
  }
  return array;
}

void AddScalars(std::vector<VtkAttribute>& section, DataArray array) {
  VtkAttribute attribute{VtkAttributeKind::kScalars, array.name, "default", {}};
  attribute.arrays.push_back(std::move(array));
  section.push_back(std::move(attribute));
}

// Points 1..9 (0-based 0..8) and cells tetra, pyramid, tetra, hexahedron: interleaved kinds.
MeshDocument Interleaved() {
  MeshDocument document;
  UnstructuredGrid& grid = document.grid;
  grid.points.type = VtkDataType::kDouble;
  grid.points.components = 3;
  for (int i = 0; i < 9; ++i) {
    grid.points.reals.insert(grid.points.reals.end(), {0.5 * i, 1.0 * (i % 3), 0.25 * (i % 2)});
  }
  grid.cells.Add(10, {0, 1, 2, 3});
  grid.cells.Add(14, {0, 1, 2, 3, 4});
  grid.cells.Add(10, {4, 5, 6, 7});
  grid.cells.Add(12, {0, 1, 2, 3, 4, 5, 6, 7});
  return document;
}

std::string Between(const std::string& text, const std::string& from, const std::string& to) {
  const std::size_t start = text.find(from);
  if (start == std::string::npos) return "<missing " + from + ">";
  const std::size_t end = text.find(to, start + from.size());
  return text.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

TEST(MeditWriter, BinaryIsRefused) {
  WriteOptions options;
  options.encoding = Encoding::kBinary;
  const absl::StatusOr<std::string> text = SerializeMedit(Interleaved(), options);
  ASSERT_FALSE(text.ok());
  EXPECT_EQ(text.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(text.status().message().find("libMeshb"), absl::string_view::npos);
}

TEST(MeditWriter, InterleavedKindsAreGroupedInFirstAppearanceOrder) {
  const absl::StatusOr<std::string> text = SerializeMedit(Interleaved(), WriteOptions{});
  ASSERT_TRUE(text.ok()) << text.status();
  EXPECT_EQ(Between(*text, "Tetrahedra\n", "\n\n"), "Tetrahedra\n2\n1 2 3 4 0\n5 6 7 8 0");
  EXPECT_EQ(Between(*text, "Pyramids\n", "\n\n"), "Pyramids\n1\n1 2 3 4 5 0");
  EXPECT_EQ(Between(*text, "Hexahedra\n", "\n\n"), "Hexahedra\n1\n1 2 3 4 5 6 7 8 0");
  EXPECT_LT(text->find("Tetrahedra"), text->find("Pyramids"));
  EXPECT_LT(text->find("Pyramids"), text->find("Hexahedra"));
}

TEST(MeditWriter, WedgeIsWrittenInPrismOrder) {
  MeshDocument document = Interleaved();
  document.grid.cells = GridCells();
  document.grid.cells.Add(13, {0, 1, 2, 3, 4, 5});
  const absl::StatusOr<std::string> text = SerializeMedit(document, WriteOptions{});
  ASSERT_TRUE(text.ok()) << text.status();
  EXPECT_EQ(Between(*text, "Prisms\n", "\n\n"), "Prisms\n1\n1 3 2 4 6 5 0");
}

TEST(MeditWriter, RefsFromMeditRefElseGmshPhysical) {
  MeshDocument document = Interleaved();
  AddScalars(document.grid.cell_data, Array("gmsh:physical", VtkDataType::kInt, 1, {5, 6, 7, 8}));
  AddScalars(document.grid.point_data,
             Array("medit:ref", VtkDataType::kInt, 1, {1, 2, 3, 4, 5, 6, 7, 8, 9}));
  absl::StatusOr<std::string> text = SerializeMedit(document, WriteOptions{});
  ASSERT_TRUE(text.ok()) << text.status();
  EXPECT_EQ(Between(*text, "Tetrahedra\n", "\n\n"), "Tetrahedra\n2\n1 2 3 4 5\n5 6 7 8 7");
  EXPECT_EQ(Between(*text, "Vertices\n", "\n0.5 "), "Vertices\n9\n0 0 0 1");

  AddScalars(document.grid.cell_data, Array("medit:ref", VtkDataType::kDouble, 1, {-1, 2, 3, 4}));
  text = SerializeMedit(document, WriteOptions{});
  ASSERT_TRUE(text.ok()) << text.status();
  EXPECT_EQ(Between(*text, "Tetrahedra\n", "\n\n"), "Tetrahedra\n2\n1 2 3 4 -1\n5 6 7 8 3");
}

TEST(MeditWriter, RefThatIsNoIntegerIsRefused) {
  MeshDocument document = Interleaved();
  AddScalars(document.grid.cell_data, Array("medit:ref", VtkDataType::kDouble, 1, {1, 2.5, 3, 4}));
  const absl::StatusOr<std::string> text = SerializeMedit(document, WriteOptions{});
  ASSERT_FALSE(text.ok());
  EXPECT_EQ(text.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(text.status().message().find("at cell 1 is 2.5"), absl::string_view::npos)
      << text.status();
}

TEST(MeditWriter, CellTypeMeditCannotHoldIsRefused) {
  MeshDocument document = Interleaved();
  document.grid.cells.Add(11, {0, 1, 2, 3, 4, 5, 6, 7});  // voxel
  const absl::StatusOr<std::string> text = SerializeMedit(document, WriteOptions{});
  ASSERT_FALSE(text.ok());
  EXPECT_EQ(text.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(text.status().message().find("cell 4 has VTK type 11 (voxel)"), absl::string_view::npos)
      << text.status();
}

TEST(MeditWriter, VertexCellsAreLeftOut) {
  MeshDocument document = Interleaved();
  document.grid.cells.Add(1, {8});
  const absl::StatusOr<std::string> text = SerializeMedit(document, WriteOptions{});
  ASSERT_TRUE(text.ok()) << text.status();
  const absl::StatusOr<MeshDocument> parsed = ParseMedit(*text);
  ASSERT_TRUE(parsed.ok()) << parsed.status();
  EXPECT_EQ(parsed->grid.cells.types, (std::vector<std::uint8_t>{10, 10, 14, 12}));
}

TEST(MeditWriter, FixedPointsBecomeRequiredVerticesAscending) {
  MeshDocument document = Interleaved();
  AddScalars(document.grid.point_data,
             Array("fixed", VtkDataType::kFloat, 1, {0, 0, 1, 0, 0, 0, 0, 0, 0.5}));
  const absl::StatusOr<std::string> text = SerializeMedit(document, WriteOptions{});
  ASSERT_TRUE(text.ok()) << text.status();
  EXPECT_EQ(Between(*text, "RequiredVertices\n", "\n\n"), "RequiredVertices\n2\n3\n9");
}

TEST(MeditWriter, MalformedExtrasAreRefused) {
  struct Case {
    MeditSection section;
    const char* message;
  };
  const Case cases[] = {
      {{"Corners", {"10"}}, "Corners entry 1: vertex 10 out of range 1..9"},
      {{"Ridges", {"1"}}, "Ridges entry 1: edge 1 out of range"},
      {{"NormalAtVertices", {"1"}}, "NormalAtVertices entry 1 has 1 numbers; expected 2"},
      {{"Normals", {"0 x 1"}}, "Normals entry 1, field 2: expected a real number, found 'x'"},
      {{"Tetrahedra", {"1 2 3 4 0"}}, "'Tetrahedra' is not a section getme keeps verbatim"},
      {{"AngleOfCornerBound", {"45", "46"}}, "AngleOfCornerBound holds exactly one entry, not 2"},
  };
  for (const Case& c : cases) {
    MeshDocument document = Interleaved();
    document.medit = MeditExtras{};
    document.medit->sections.push_back(c.section);
    const absl::StatusOr<std::string> text = SerializeMedit(document, WriteOptions{});
    ASSERT_FALSE(text.ok()) << c.message;
    EXPECT_EQ(text.status().code(), absl::StatusCode::kInvalidArgument);
    EXPECT_NE(text.status().message().find(c.message), absl::string_view::npos) << text.status();
  }
}

TEST(MeditWriter, UnknownVersionIsRefused) {
  MeshDocument document = Interleaved();
  document.medit = MeditExtras{};
  document.medit->version = 7;
  const absl::StatusOr<std::string> text = SerializeMedit(document, WriteOptions{});
  ASSERT_FALSE(text.ok());
  EXPECT_EQ(text.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(text.status().message().find("version 7"), absl::string_view::npos) << text.status();
}

TEST(MeditSolution, EmptyWithoutCellArrays) {
  MeshDocument document = Interleaved();
  AddScalars(document.grid.cell_data, Array("medit:ref", VtkDataType::kInt, 1, {1, 2, 3, 4}));
  const absl::StatusOr<std::string> sol = SerializeMeditSolution(document);
  ASSERT_TRUE(sol.ok()) << sol.status();
  EXPECT_EQ(*sol, "");
}

TEST(MeditSolution, FollowsTheMeshSectionsWithGmfTypes) {
  MeshDocument document = Interleaved();
  UnstructuredGrid& grid = document.grid;
  grid.cells.Add(1, {8});  // a vertex cell: in no section of either file
  AddScalars(grid.cell_data, Array("gmsh:physical", VtkDataType::kInt, 1, {5, 6, 7, 8, 9}));
  AddScalars(grid.cell_data, Array("id", VtkDataType::kDouble, 1, {0, 1, 2, 3, 4}));
  AddScalars(grid.cell_data, Array("valid", VtkDataType::kUInt8, 1, {1, 0, 1, 1, 0}));
  AddScalars(grid.cell_data, Array("v", VtkDataType::kDouble, 3,
                                   {0.5, 1, 2, 10, 11, 12, 20, 21, 22, 30, 31, 32, 40, 41, 42}));
  AddScalars(grid.cell_data,
             Array("uv", VtkDataType::kFloat, 2, {0.25, 1, 10, 11, 20, 21, 30, 31, 40, 41}));
  const absl::StatusOr<std::string> sol = SerializeMeditSolution(document);
  ASSERT_TRUE(sol.ok()) << sol.status();
  // gmsh:physical is the .mesh's ref; the 2-component array has no GMF type: two scalars.
  EXPECT_EQ(*sol,
            "MeshVersionFormatted 2\n\nDimension 3\n"
            "\nSolAtTetrahedra\n2\n5 1 1 2 1 1\n"
            "0 1 0.5 1 2 0.25 1\n"
            "2 1 20 21 22 20 21\n"
            "\nSolAtPyramids\n1\n5 1 1 2 1 1\n"
            "1 0 10 11 12 10 11\n"
            "\nSolAtHexahedra\n1\n5 1 1 2 1 1\n"
            "3 1 30 31 32 30 31\n"
            "\nReferenceStrings\n15\n"
            "66 1 id\n66 2 valid\n66 3 v\n66 4 uv[0]\n66 5 uv[1]\n"
            "26 1 id\n26 2 valid\n26 3 v\n26 4 uv[0]\n26 5 uv[1]\n"
            "68 1 id\n68 2 valid\n68 3 v\n68 4 uv[0]\n68 5 uv[1]\n"
            "\nEnd\n");
}

TEST(MeditSolution, ArrayOfTheWrongLengthIsRefused) {
  MeshDocument document = Interleaved();
  AddScalars(document.grid.cell_data, Array("id", VtkDataType::kDouble, 1, {0, 1, 2}));
  const absl::StatusOr<std::string> sol = SerializeMeditSolution(document);
  ASSERT_FALSE(sol.ok());
  EXPECT_EQ(sol.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_NE(sol.status().message().find("cell data 'id' has 3 values of 1 components for 4 cells"),
            absl::string_view::npos)
      << sol.status();
}

}  // namespace
}  // namespace getme::formats
