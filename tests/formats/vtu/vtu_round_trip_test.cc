// Every shared Mesquite mesh and tests/data/hybrid-example.vtk, read by the legacy reader,
// survive SerializeVtu → ParseVtu in every layout with the same content (points bit for bit),
// and writing what was read gives the same bytes again.

#include <gtest/gtest.h>

#include <cmath>

#include "formats/vtk_reader.h"
#include "formats/vtk_writer.h"
#include "formats/vtu/vtu_reader.h"
#include "formats/vtu/vtu_writer.h"
#include "vtk_test_util.h"

namespace getme::formats {
namespace {

using testing::AllSharedMeshNames;
using testing::DeclaredCount;
using testing::ExpectSameContent;
using testing::ReadText;
using testing::SharedMesh;

struct Mode {
  const char* name;
  WriteOptions options;
};

void PrintTo(const Mode& mode, std::ostream* out) { *out << mode.name; }

const Mode kModes[] = {
    {"ascii", {Encoding::kAscii, GmshVersion::k41, VtuLayout::kInline, false}},
    {"inline", {Encoding::kBinary, GmshVersion::k41, VtuLayout::kInline, false}},
    {"inline_zlib", {Encoding::kBinary, GmshVersion::k41, VtuLayout::kInline, true}},
    {"appended", {Encoding::kBinary, GmshVersion::k41, VtuLayout::kAppended, false}},
    {"appended_zlib", {Encoding::kBinary, GmshVersion::k41, VtuLayout::kAppended, true}},
};

std::string MeshPath(const std::string& name) {
  return name == "hybrid-example.vtk" ? std::string(GETME_TEST_DATA) + "/" + name
                                      : SharedMesh(name);
}

std::vector<std::string> AllMeshNames() {
  std::vector<std::string> names = AllSharedMeshNames();
  names.push_back("hybrid-example.vtk");
  return names;
}

// What a legacy file becomes through .vtu: no title, the default legacy version, and bit arrays
// as unsigned_char (VTK XML's Bit type is unknown to most readers). Nothing else changes for
// these files: their types (int, float, double) have XML twins, and their attribute sections
// are SCALARS, the first of each block the active one.
UnstructuredGrid ThroughVtu(UnstructuredGrid file) {
  file.title.clear();
  file.version_major = UnstructuredGrid{}.version_major;
  file.version_minor = UnstructuredGrid{}.version_minor;
  for (auto* section : {&file.point_data, &file.cell_data, &file.field_data}) {
    for (VtkAttribute& attribute : *section) {
      for (DataArray& array : attribute.arrays) {
        if (array.type == VtkDataType::kBit) array.type = VtkDataType::kUnsignedChar;
      }
    }
  }
  return file;
}

class VtuRoundTripTest : public ::testing::TestWithParam<std::tuple<std::string, Mode>> {};

TEST_P(VtuRoundTripTest, KeepsTheContent) {
  const auto& [name, mode] = GetParam();
  const absl::StatusOr<UnstructuredGrid> legacy = ReadVtkFile(MeshPath(name));
  ASSERT_TRUE(legacy.ok()) << legacy.status();
  MeshDocument document;
  document.grid = *legacy;
  const absl::StatusOr<std::string> bytes = SerializeVtu(document, mode.options);
  ASSERT_TRUE(bytes.ok()) << bytes.status();

  // Counts in the text, found without the reader.
  const std::string legacy_text = ReadText(MeshPath(name));
  EXPECT_NE(bytes->find(absl::StrCat("NumberOfPoints=\"", DeclaredCount(legacy_text, "POINTS"),
                                     "\" NumberOfCells=\"",
                                     DeclaredCount(legacy_text, "CELL_TYPES"), "\"")),
            std::string::npos);

  const absl::StatusOr<MeshDocument> back = ParseVtu(*bytes);
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_EQ(back->format, FileFormat::kVtkXml);
  EXPECT_EQ(back->as_read.encoding, mode.options.encoding);
  if (mode.options.encoding == Encoding::kBinary) {
    EXPECT_EQ(back->as_read.vtu_layout, mode.options.vtu_layout);
    EXPECT_EQ(back->as_read.vtu_compress, mode.options.vtu_compress);
  }
  ExpectSameContent(ThroughVtu(*legacy), back->grid);
  const absl::StatusOr<std::string> again = SerializeVtu(*back, mode.options);
  ASSERT_TRUE(again.ok()) << again.status();
  EXPECT_EQ(*again, *bytes);
  // And what came through .vtu still writes as a legacy file that reads back the same.
  const absl::StatusOr<std::string> as_legacy = SerializeVtk(back->grid, Encoding::kAscii);
  ASSERT_TRUE(as_legacy.ok()) << as_legacy.status();
  const absl::StatusOr<UnstructuredGrid> legacy_again = ParseVtk(*as_legacy);
  ASSERT_TRUE(legacy_again.ok()) << legacy_again.status();
  ExpectSameContent(back->grid, *legacy_again);
}

std::string RoundTripName(const ::testing::TestParamInfo<std::tuple<std::string, Mode>>& info) {
  std::string name = std::get<0>(info.param);
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return absl::StrCat(name, "_", std::get<1>(info.param).name);
}

INSTANTIATE_TEST_SUITE_P(AllMeshes, VtuRoundTripTest,
                         ::testing::Combine(::testing::ValuesIn(AllMeshNames()),
                                            ::testing::ValuesIn(kModes)),
                         RoundTripName);

TEST(VtuRoundTrip, ActiveScalarsAreNamedForParaView) {
  const absl::StatusOr<UnstructuredGrid> legacy = ReadVtkFile(MeshPath("hybrid-example.vtk"));
  ASSERT_TRUE(legacy.ok()) << legacy.status();
  MeshDocument document;
  document.grid = *legacy;
  const absl::StatusOr<std::string> bytes = SerializeVtu(document, {});
  ASSERT_TRUE(bytes.ok()) << bytes.status();
  // The file's first CELL_DATA SCALARS section is mean_ratio.
  EXPECT_NE(bytes->find("<CellData Scalars=\"mean_ratio\">"), std::string::npos);
  EXPECT_EQ(bytes->find("<PointData"), std::string::npos);
}

TEST(VtuRoundTrip, FloatStaysFloat32OnlyWhenExact) {
  MeshDocument document;
  UnstructuredGrid& grid = document.grid;
  grid.points.type = VtkDataType::kFloat;
  grid.points.components = 3;
  grid.points.reals = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.5, 0.25, 1};
  grid.cells.Add(10, {0, 1, 2, 3});
  VtkAttribute exact{VtkAttributeKind::kScalars, "exact", "default", {}};
  exact.arrays.push_back({"exact", VtkDataType::kFloat, 1, {0.5, 1.5, -2, 3.25}, {}});
  VtkAttribute inexact{VtkAttributeKind::kScalars, "inexact", "default", {}};
  inexact.arrays.push_back({"inexact", VtkDataType::kFloat, 1, {0.1, 1, 2, 3}, {}});
  grid.point_data = {exact, inexact};
  for (const Mode& mode : kModes) {
    SCOPED_TRACE(mode.name);
    const absl::StatusOr<std::string> bytes = SerializeVtu(document, mode.options);
    ASSERT_TRUE(bytes.ok()) << bytes.status();
    EXPECT_NE(bytes->find("type=\"Float32\" Name=\"Points\""), std::string::npos);
    EXPECT_NE(bytes->find("type=\"Float32\" Name=\"exact\""), std::string::npos);
    // 0.1 is no float: written as Float64 so no digit is lost.
    EXPECT_NE(bytes->find("type=\"Float64\" Name=\"inexact\""), std::string::npos);
    const absl::StatusOr<MeshDocument> back = ParseVtu(*bytes);
    ASSERT_TRUE(back.ok()) << back.status();
    EXPECT_EQ(back->grid.points.type, VtkDataType::kFloat);
    EXPECT_EQ(back->grid.point_data[1].arrays[0].reals[0], 0.1);
  }
}

TEST(VtuRoundTrip, AsciiNumbersArePrintedLikeTheLegacyWriter) {
  MeshDocument document;
  UnstructuredGrid& grid = document.grid;
  grid.points.components = 3;
  grid.points.reals = {0.1, 1.0 / 3.0, -2.5e-300, 1e22, 123456789.125, -0.0};
  grid.cells.Add(1, {0});
  grid.cells.Add(1, {1});
  const absl::StatusOr<std::string> bytes = SerializeVtu(document, {});
  ASSERT_TRUE(bytes.ok()) << bytes.status();
  // Shortest round-trip decimals, one tuple per line.
  EXPECT_NE(bytes->find("\n          0.1 0.3333333333333333 -2.5e-300\n"
                        "          1e+22 123456789.125 -0\n"),
            std::string::npos)
      << *bytes;
}

TEST(VtuRoundTrip, AttributeRolesAndFieldDataSurvive) {
  MeshDocument document;
  UnstructuredGrid& grid = document.grid;
  grid.points.components = 3;
  grid.points.reals = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  grid.cells.Add(10, {0, 1, 2, 3});
  auto section = [](VtkAttributeKind kind, const std::string& name, VtkDataType type,
                    int components, std::vector<double> reals, std::vector<std::int64_t> integers) {
    VtkAttribute attribute{kind, name, kind == VtkAttributeKind::kScalars ? "default" : "", {}};
    attribute.arrays.push_back({name, type, components, std::move(reals), std::move(integers)});
    return attribute;
  };
  VtkAttribute field{VtkAttributeKind::kField, "FieldData", "", {}};
  field.arrays.push_back({"six", VtkDataType::kDouble, 6, std::vector<double>(24, 0.5), {}});
  field.arrays.push_back({"id", VtkDataType::kUnsignedShort, 1, {}, {1, 2, 3, 65535}});
  grid.point_data = {
      field,
      section(VtkAttributeKind::kScalars, "s", VtkDataType::kDouble, 2, std::vector(8, 1.5), {}),
      section(VtkAttributeKind::kVectors, "v", VtkDataType::kFloat, 3, std::vector(12, 2.0), {}),
      section(VtkAttributeKind::kNormals, "n", VtkDataType::kDouble, 3, std::vector(12, 0.0), {}),
      section(VtkAttributeKind::kTextureCoordinates, "uv", VtkDataType::kFloat, 2,
              std::vector(8, 0.25), {}),
      section(VtkAttributeKind::kTensors, "t", VtkDataType::kDouble, 9, std::vector(36, 3.0), {}),
      section(VtkAttributeKind::kGlobalIds, "gid", VtkDataType::kLong, 1, {}, {7, 8, 9, 10}),
      section(VtkAttributeKind::kScalars, "later", VtkDataType::kChar, 1, {}, {-1, 0, 1, 2}),
  };
  grid.cell_data = {
      section(VtkAttributeKind::kScalars, "q", VtkDataType::kUnsignedLong, 1, {}, {-1}),
  };
  VtkAttribute dataset_field{VtkAttributeKind::kField, "FieldData", "", {}};
  dataset_field.arrays.push_back({"time", VtkDataType::kDouble, 1, {0.125, 8.5}, {}});
  grid.field_data = {dataset_field};

  for (const Mode& mode : kModes) {
    SCOPED_TRACE(mode.name);
    const absl::StatusOr<std::string> bytes = SerializeVtu(document, mode.options);
    ASSERT_TRUE(bytes.ok()) << bytes.status();
    EXPECT_NE(bytes->find("<PointData Scalars=\"s\" Vectors=\"v\" Normals=\"n\" Tensors=\"t\" "
                          "TCoords=\"uv\" GlobalIds=\"gid\">"),
              std::string::npos)
        << *bytes;
    EXPECT_NE(bytes->find("Name=\"time\" NumberOfTuples=\"2\""), std::string::npos);
    const absl::StatusOr<MeshDocument> back = ParseVtu(*bytes);
    ASSERT_TRUE(back.ok()) << back.status();
    ExpectSameContent(ThroughVtu(grid), back->grid);
  }
}

TEST(VtuRoundTrip, LookupTablesMoveToFieldData) {
  MeshDocument document;
  UnstructuredGrid& grid = document.grid;
  grid.points.components = 3;
  grid.points.reals = {0, 0, 0};
  grid.cells.Add(1, {0});
  VtkAttribute table{VtkAttributeKind::kLookupTable, "colors", "", {}};
  table.arrays.push_back({"colors", VtkDataType::kFloat, 4, {0, 0, 0, 1, 1, 1, 1, 1}, {}});
  grid.point_data = {table};
  const absl::StatusOr<std::string> bytes = SerializeVtu(document, {});
  ASSERT_TRUE(bytes.ok()) << bytes.status();
  const absl::StatusOr<MeshDocument> back = ParseVtu(*bytes);
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_TRUE(back->grid.point_data.empty());
  const DataArray* colors = FindArray(back->grid.field_data, "colors");
  ASSERT_NE(colors, nullptr);
  EXPECT_EQ(colors->components, 4);
  EXPECT_EQ(colors->reals, table.arrays[0].reals);
}

TEST(VtuWriter, RefusesWhatItCannotWrite) {
  MeshDocument document;
  UnstructuredGrid& grid = document.grid;
  grid.points.components = 3;
  grid.points.reals = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  grid.cells.Add(42, {4, 4, 0, 1, 2, 3});
  absl::StatusOr<std::string> bytes = SerializeVtu(document, {});
  ASSERT_FALSE(bytes.ok());
  EXPECT_EQ(bytes.status().message(),
            "Cells: cell 0 is a polyhedron (VTK type 42); getme does not write polyhedra to .vtu "
            "(their faces need the faces / faceoffsets arrays)");

  grid.cells = {};
  grid.cells.Add(10, {0, 1, 2, 4});
  bytes = SerializeVtu(document, {});
  ASSERT_FALSE(bytes.ok());
  EXPECT_EQ(bytes.status().message(), "Cells: cell 0 refers to point 4, but there are 4 points");

  grid.cells = {};
  grid.cells.Add(10, {0, 1, 2, 3});
  VtkAttribute bad{VtkAttributeKind::kScalars, "a\x01", "default", {}};
  bad.arrays.push_back({"a\x01", VtkDataType::kInt, 1, {}, {1, 2, 3, 4}});
  grid.point_data = {bad};
  bytes = SerializeVtu(document, {});
  ASSERT_FALSE(bytes.ok());
  EXPECT_EQ(bytes.status().message(),
            "the array name 'a\\x01' holds a control character, which XML cannot carry");

  bad.arrays[0].name = "short";
  bad.arrays[0].integers = {1, 2, 3};
  grid.point_data = {bad};
  bytes = SerializeVtu(document, {});
  ASSERT_FALSE(bytes.ok());
  EXPECT_EQ(bytes.status().message(),
            "PointData SCALARS a\x01 array short: has 3 tuples; expected 4");
}

TEST(VtuWriter, EscapesNames) {
  MeshDocument document;
  UnstructuredGrid& grid = document.grid;
  grid.points.components = 3;
  grid.points.reals = {0, 0, 0};
  grid.cells.Add(1, {0});
  const std::string name = "a <b> & \"c\"\td\ne";
  VtkAttribute attribute{VtkAttributeKind::kScalars, name, "default", {}};
  attribute.arrays.push_back({name, VtkDataType::kInt, 1, {}, {5}});
  grid.point_data = {attribute};
  const absl::StatusOr<std::string> bytes = SerializeVtu(document, {});
  ASSERT_TRUE(bytes.ok()) << bytes.status();
  const absl::StatusOr<MeshDocument> back = ParseVtu(*bytes);
  ASSERT_TRUE(back.ok()) << back.status();
  ASSERT_EQ(back->grid.point_data.size(), 1u);
  EXPECT_EQ(back->grid.point_data[0].kind, VtkAttributeKind::kScalars);
  EXPECT_EQ(back->grid.point_data[0].arrays[0].name, name);
}

}  // namespace
}  // namespace getme::formats
