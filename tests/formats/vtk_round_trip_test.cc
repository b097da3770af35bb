// Every section kind and data type survives ASCII and BINARY round trips; BINARY follows the
// VTK legacy byte layout (checked against hand-made bytes); VTK 5.1 OFFSETS/CONNECTIVITY cells.

#include <gtest/gtest.h>

#include <bit>
#include <cstring>

#include "formats/vtk_reader.h"
#include "formats/vtk_writer.h"
#include "vtk_test_util.h"

namespace getme::formats {
namespace {

using testing::ExpectSameContent;

constexpr char kAllSections[] = R"(# vtk DataFile Version 3.0
every section kind
ASCII
DATASET UNSTRUCTURED_GRID
FIELD FieldData 2
TIME 1 1 double
1.5
CYCLE 1 1 int
7
POINTS 5 float
0 0 0 1 0 0 0 1 0 0 0 1 0.1 0.2 0.3
CELLS 3 13
4 0 1 2 3
4 1 2 3 4
2 0 4
CELL_TYPES 3
10
10
3
POINT_DATA 5
SCALARS fixed bit
LOOKUP_TABLE default
1 1 1 1 0
SCALARS temperature%20C double 2
LOOKUP_TABLE my_table
1 2 3 4 5 6 7 8 9 1e-300
COLOR_SCALARS rgb 3
0 0.2 0.4 0.6 0.8 1 0 0 0 1 1 1 0.4 0.4 0.4
LOOKUP_TABLE my_table 2
0 0 0 1 1 0.2 0.8 1
VECTORS velocity double
1 2 3 4 5 6 7 8 9 10 11 12 13 14 -1.25e10
NORMALS n float
1 0 0 0 1 0 0 0 1 1 0 0 0.5 0.5 0.5
TEXTURE_COORDINATES uv 2 float
0 0 1 0 0 1 1 1 0.25 0.75
TENSORS stress double
1 2 3 4 5 6 7 8 9
1 2 3 4 5 6 7 8 9
1 2 3 4 5 6 7 8 9
1 2 3 4 5 6 7 8 9
1 2 3 4 5 6 7 8 9
GLOBAL_IDS ids long
0 1 2 9223372036854775807 -9223372036854775808
FIELD extras 4
u8 1 5 unsigned_char
0 255 3 4 5
i16 2 5 short
-32768 32767 0 1 2 3 4 5 6 7
METADATA
INFORMATION 0

u64 1 5 unsigned_long
18446744073709551615 0 1 2 3
c 1 5 char
-128 127 0 1 2
CELL_DATA 3
SCALARS id vtkIdType 1
LOOKUP_TABLE default
0 1 -2147483648
FIELD more 1
f32 3 3 float
0.5 0.25 0.125 1 2 3 -4 -5 -6
)";

TEST(VtkRoundTrip, ReadsEverySectionKind) {
  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(kAllSections);
  ASSERT_TRUE(file.ok()) << file.status();
  ASSERT_EQ(file->field_data.size(), 1u);
  EXPECT_EQ(file->field_data[0].arrays[0].reals, std::vector<double>{1.5});
  EXPECT_EQ(file->field_data[0].arrays[1].integers, std::vector<std::int64_t>{7});
  ASSERT_EQ(file->point_data.size(), 10u);
  EXPECT_EQ(file->point_data[0].arrays[0].type, VtkDataType::kBit);
  EXPECT_EQ(file->point_data[0].arrays[0].integers, (std::vector<std::int64_t>{1, 1, 1, 1, 0}));
  EXPECT_EQ(file->point_data[1].name, "temperature C");  // %20 decoded
  EXPECT_EQ(file->point_data[1].lookup_table, "my_table");
  EXPECT_EQ(file->point_data[1].arrays[0].components, 2);
  EXPECT_EQ(file->point_data[2].kind, VtkAttributeKind::kColorScalars);
  EXPECT_EQ(file->point_data[3].kind, VtkAttributeKind::kLookupTable);
  EXPECT_EQ(file->point_data[3].arrays[0].tuple_count(), 2);
  EXPECT_EQ(file->point_data[6].arrays[0].components, 2);  // TEXTURE_COORDINATES uv 2
  EXPECT_EQ(file->point_data[7].arrays[0].components, 9);  // TENSORS
  EXPECT_EQ(file->point_data[8].arrays[0].integers[3], INT64_MAX);
  EXPECT_EQ(file->point_data[8].arrays[0].integers[4], INT64_MIN);
  const VtkAttribute& extras = file->point_data[9];
  ASSERT_EQ(extras.arrays.size(), 4u);  // the METADATA block is skipped
  EXPECT_EQ(extras.arrays[2].AsDouble(0), 18446744073709551615.0);
  EXPECT_EQ(extras.arrays[3].integers, (std::vector<std::int64_t>{-128, 127, 0, 1, 2}));
  ASSERT_EQ(file->cell_data.size(), 2u);
  EXPECT_EQ(file->cell_data[0].arrays[0].integers[2], INT32_MIN);
  // A float array keeps the parsed double: 0.1 is 0.1, not the float nearest to it.
  EXPECT_EQ(file->points.AsDouble(12), 0.1);
}

TEST(VtkRoundTrip, AsciiAndBinaryKeepEverything) {
  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(kAllSections);
  ASSERT_TRUE(file.ok()) << file.status();
  for (const Encoding encoding : {Encoding::kAscii, Encoding::kBinary}) {
    const absl::StatusOr<std::string> bytes = SerializeVtk(*file, encoding);
    ASSERT_TRUE(bytes.ok()) << bytes.status();
    const absl::StatusOr<UnstructuredGrid> again = ParseVtk(*bytes);
    ASSERT_TRUE(again.ok()) << again.status() << "\n" << *bytes;
    ExpectSameContent(*file, *again);
    // And once more from the re-read file: byte-identical.
    EXPECT_EQ(*SerializeVtk(*again, encoding), *bytes);
  }
}

TEST(VtkRoundTrip, FloatArraysArePromotedOnlyWhenNeeded) {
  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(kAllSections);
  ASSERT_TRUE(file.ok()) << file.status();
  const std::string ascii = *SerializeVtk(*file, Encoding::kAscii);
  // POINTS hold 0.1 (not a float): written as double, in the shortest exact form.
  EXPECT_NE(ascii.find("POINTS 5 double\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0.1 0.2 0.3\n"),
            std::string::npos)
      << ascii;
  // NORMALS hold only exact floats: they stay float.
  EXPECT_NE(ascii.find("NORMALS n float\n"), std::string::npos);
  EXPECT_NE(ascii.find("SCALARS temperature%20C double 2\nLOOKUP_TABLE my_table\n"),
            std::string::npos);
}

TEST(VtkRoundTrip, CoordinatesSurviveBitForBit) {
  UnstructuredGrid file;
  file.points.type = VtkDataType::kDouble;
  file.points.components = 3;
  file.points.reals = {0.1,
                       1.0 / 3.0,
                       -2.5e-310,
                       1e300,
                       -0.0,
                       6.02214076e23,
                       std::nextafter(1.0, 2.0),
                       123456789.123456789,
                       5e-324};
  file.cells.Add(1, {0});
  file.cells.Add(1, {1});
  file.cells.Add(1, {2});
  for (const Encoding encoding : {Encoding::kAscii, Encoding::kBinary}) {
    const absl::StatusOr<UnstructuredGrid> again = ParseVtk(*SerializeVtk(file, encoding));
    ASSERT_TRUE(again.ok()) << again.status();
    ASSERT_EQ(again->points.reals.size(), file.points.reals.size());
    for (std::size_t i = 0; i < file.points.reals.size(); ++i) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(again->points.reals[i]),
                std::bit_cast<std::uint64_t>(file.points.reals[i]))
          << i;
    }
  }
}

// A float array read from BINARY (exact floats) and written as ASCII reads back as the same
// values: printed as the shortest decimal of the double, not of the float ("0.1" would read
// back as the double 0.1, not as 0.1f).
TEST(VtkRoundTrip, ExactFloatsSurviveAscii) {
  UnstructuredGrid file;
  file.points.type = VtkDataType::kFloat;
  file.points.components = 3;
  file.points.reals = {0.1f, 1.0f / 3.0f, 9.49f, 1e-30f, -7.25f, 3.4e38f};
  file.cells.Add(1, {0});
  file.cells.Add(1, {1});
  const std::string ascii = *SerializeVtk(file, Encoding::kAscii);
  EXPECT_NE(ascii.find("POINTS 2 float\n0.10000000149011612 "), std::string::npos) << ascii;
  const absl::StatusOr<UnstructuredGrid> again = ParseVtk(ascii);
  ASSERT_TRUE(again.ok()) << again.status();
  ASSERT_EQ(again->points.reals.size(), file.points.reals.size());
  for (std::size_t i = 0; i < file.points.reals.size(); ++i) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(again->points.reals[i]),
              std::bit_cast<std::uint64_t>(file.points.reals[i]))
        << i;
  }
}

// Big-endian helpers for hand-made BINARY files.
void PutInt32(std::string& out, std::int32_t value) {
  const auto bits = static_cast<std::uint32_t>(value);
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<char>(bits >> shift));
}
void PutFloat(std::string& out, float value) {
  PutInt32(out, static_cast<std::int32_t>(std::bit_cast<std::uint32_t>(value)));
}

TEST(VtkBinaryLayout, ReadsHandMadeBigEndianBytes) {
  std::string bytes = "# vtk DataFile Version 2.0\nhand made\nBINARY\nDATASET UNSTRUCTURED_GRID\n";
  bytes += "POINTS 2 float\n";
  for (const float v : {1.0f, 2.0f, -3.0f, 0.5f, 0.25f, 0.125f}) PutFloat(bytes, v);
  bytes += "\nCELLS 1 3\n";
  for (const int v : {2, 1, 0}) PutInt32(bytes, v);
  bytes += "\nCELL_TYPES 1\n";
  PutInt32(bytes, 3);
  bytes += "\nPOINT_DATA 2\nSCALARS fixed bit 1\nLOOKUP_TABLE default\n";
  bytes.push_back(static_cast<char>(0x80));  // bits 1, 0: most significant bit first
  bytes += "\nSCALARS id vtkIdType 1\nLOOKUP_TABLE default\n";
  PutInt32(bytes, -7);
  PutInt32(bytes, 70000);
  bytes += "\n";

  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(bytes);
  ASSERT_TRUE(file.ok()) << file.status();
  EXPECT_EQ(file->encoding, Encoding::kBinary);
  EXPECT_EQ(file->points.type, VtkDataType::kFloat);
  EXPECT_EQ(file->points.reals, (std::vector<double>{1, 2, -3, 0.5, 0.25, 0.125}));
  EXPECT_EQ(file->cells.connectivity, (std::vector<std::int64_t>{1, 0}));
  EXPECT_EQ(file->cells.types, (std::vector<std::uint8_t>{3}));
  EXPECT_EQ(file->point_data[0].arrays[0].integers, (std::vector<std::int64_t>{1, 0}));
  EXPECT_EQ(file->point_data[1].arrays[0].integers, (std::vector<std::int64_t>{-7, 70000}));
  // The writer produces exactly these bytes (the float points stay float: they are exact).
  EXPECT_EQ(*SerializeVtk(*file, Encoding::kBinary), bytes);
}

constexpr char kVersion51[] = R"(# vtk DataFile Version 5.1
vtk output
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 6 double
0 0 0 1 0 0 0 1 0
0 0 1 1 0 1 0 1 1
METADATA
INFORMATION 0

CELLS 3 10
OFFSETS vtktypeint64
0 6 10
CONNECTIVITY vtktypeint64
0 2 1 3 5 4
0 1 2 3
CELL_TYPES 2
13
10
)";

TEST(VtkVersion51, ReadsOffsetsAndConnectivity) {
  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(kVersion51);
  ASSERT_TRUE(file.ok()) << file.status();
  EXPECT_EQ(file->cells.offsets, (std::vector<std::int64_t>{0, 6, 10}));
  EXPECT_EQ(file->cells.connectivity, (std::vector<std::int64_t>{0, 2, 1, 3, 5, 4, 0, 1, 2, 3}));
  EXPECT_EQ(file->cells.types, (std::vector<std::uint8_t>{13, 10}));
  for (const Encoding encoding : {Encoding::kAscii, Encoding::kBinary}) {
    const std::string bytes = *SerializeVtk(*file, encoding);
    EXPECT_NE(bytes.find("OFFSETS vtktypeint64"), std::string::npos);
    const absl::StatusOr<UnstructuredGrid> again = ParseVtk(bytes);
    ASSERT_TRUE(again.ok()) << again.status();
    ExpectSameContent(*file, *again);
  }
  // Written as version 3.0, the same cells come out as classic rows.
  UnstructuredGrid classic = *file;
  classic.version_major = 3;
  classic.version_minor = 0;
  const std::string bytes = *SerializeVtk(classic, Encoding::kAscii);
  EXPECT_NE(bytes.find("CELLS 2 12\n6 0 2 1 3 5 4\n4 0 1 2 3\n"), std::string::npos) << bytes;
  const absl::StatusOr<UnstructuredGrid> again = ParseVtk(bytes);
  ASSERT_TRUE(again.ok()) << again.status();
  EXPECT_EQ(again->cells.connectivity, file->cells.connectivity);
}

TEST(VtkVersion51, InconsistentOffsetsAreRefused) {
  std::string text = kVersion51;
  text.replace(text.find("0 6 10"), 6, "0 6 11");
  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(text);
  ASSERT_FALSE(file.ok());
  EXPECT_EQ(file.status().message(),
            "line 12: OFFSETS: the last offset is 11, but CONNECTIVITY has 10 entries");
}

TEST(VtkWriter, RefusesInconsistentModels) {
  UnstructuredGrid file;
  file.points.components = 3;
  file.points.reals = {0, 0, 0};
  file.cells.Add(1, {1});
  absl::StatusOr<std::string> bytes = SerializeVtk(file, Encoding::kAscii);
  ASSERT_FALSE(bytes.ok());
  EXPECT_EQ(bytes.status().message(), "CELLS: cell 0 refers to point 1, but there are 1 points");

  file.cells = GridCells();
  VtkAttribute scalars{VtkAttributeKind::kScalars, "flag", "default", {}};
  scalars.arrays.push_back({"flag", VtkDataType::kUnsignedChar, 1, {}, {300}});
  file.point_data.push_back(scalars);
  bytes = SerializeVtk(file, Encoding::kBinary);
  ASSERT_FALSE(bytes.ok());
  EXPECT_EQ(bytes.status().message(),
            "POINT_DATA SCALARS flag: value 0 (300) does not fit type unsigned_char");

  file.point_data[0].arrays[0].integers = {1, 2};
  bytes = SerializeVtk(file, Encoding::kAscii);
  ASSERT_FALSE(bytes.ok());
  EXPECT_EQ(bytes.status().message(), "POINT_DATA SCALARS flag: has 2 tuples; expected 1");
}

TEST(VtkWriter, WritesFilesAtomicallyAndReportsBadPaths) {
  const std::string path = ::testing::TempDir() + "/vtk_writer_test.vtk";
  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(kAllSections);
  ASSERT_TRUE(file.ok());
  ASSERT_TRUE(WriteVtkFile(path, *file, Encoding::kBinary).ok());
  const absl::StatusOr<UnstructuredGrid> again = ReadVtkFile(path);
  ASSERT_TRUE(again.ok()) << again.status();
  ExpectSameContent(*file, *again);

  const absl::Status status = WriteVtkFile("/nonexistent-dir/x.vtk", *file);
  EXPECT_EQ(status.code(), absl::StatusCode::kNotFound);
  EXPECT_NE(status.message().find("cannot write '/nonexistent-dir/x.vtk'"), std::string::npos);

  const absl::StatusOr<UnstructuredGrid> missing = ReadVtkFile("/nonexistent-dir/x.vtk");
  EXPECT_EQ(missing.status().code(), absl::StatusCode::kNotFound);
  EXPECT_NE(missing.status().message().find("cannot open '/nonexistent-dir/x.vtk'"),
            std::string::npos);
}

}  // namespace
}  // namespace getme::formats
