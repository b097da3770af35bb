// Malformed input gives InvalidArgument naming the line (ASCII) or byte offset and section
// (BINARY) — and never crashes, whatever the damage.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "formats/vtk_reader.h"
#include "formats/vtk_writer.h"
#include "vtk_test_util.h"

namespace getme::formats {
namespace {

using testing::SharedMesh;

// Line numbers below refer to this file.
constexpr char kTet[] = R"(# vtk DataFile Version 2.0
tet
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 4 float
0 0 0
1 0 0
0 1 0
0 0 1
CELLS 1 5
4 0 1 2 3
CELL_TYPES 1
10
POINT_DATA 4
SCALARS fixed int 1
LOOKUP_TABLE default
1 1 1 0
)";

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

// Parses and returns the error message, failing the test if parsing succeeds or the error is
// not InvalidArgument.
std::string ParseError(const std::string& text) {
  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(text);
  EXPECT_FALSE(file.ok());
  if (file.ok()) return "";
  EXPECT_EQ(file.status().code(), absl::StatusCode::kInvalidArgument) << file.status();
  return std::string(file.status().message());
}

TEST(VtkMalformed, TheBaseFileIsFine) { EXPECT_TRUE(ParseVtk(kTet).ok()); }

TEST(VtkMalformed, EmptyInput) {
  EXPECT_EQ(ParseError(""),
            "line 1: the file is empty; expected '# vtk DataFile Version <major>.<minor>'");
}

TEST(VtkMalformed, NotAVtkFile) {
  EXPECT_EQ(ParseError("$MeshFormat\n2.2 0 8\n"),
            "line 1: expected '# vtk DataFile Version <major>.<minor>', found '$MeshFormat'; "
            "this is not a VTK legacy file");
}

TEST(VtkMalformed, UnknownEncoding) {
  EXPECT_EQ(ParseError(Replace(kTet, "ASCII", "XML")),
            "line 3: expected 'ASCII' or 'BINARY', found 'XML'");
}

// Found by fuzz/vtk_fuzzer.cc: a title ending in "\r\r\n" kept one '\r', which the writer then
// refused, so the file read but could not be written back. A CRLF line ending is still fine.
TEST(VtkMalformed, CarriageReturnInsideTheTitle) {
  EXPECT_EQ(ParseError(Replace(kTet, "tet\n", "tet\r\r\n")),
            "line 2: the title holds a carriage return that is not part of the line ending");
  EXPECT_EQ(ParseError(Replace(kTet, "tet\n", "t\ret\n")),
            "line 2: the title holds a carriage return that is not part of the line ending");
  const absl::StatusOr<UnstructuredGrid> crlf = ParseVtk(Replace(kTet, "tet\n", "tet\r\n"));
  ASSERT_TRUE(crlf.ok()) << crlf.status();
  EXPECT_EQ(crlf->title, "tet");
}

TEST(VtkMalformed, OtherDatasetTypes) {
  EXPECT_EQ(ParseError(Replace(kTet, "UNSTRUCTURED_GRID", "POLYDATA")),
            "line 4: DATASET POLYDATA is not supported; getme reads DATASET UNSTRUCTURED_GRID");
}

TEST(VtkMalformed, TruncatedInsidePoints) {
  // Too few bytes left for the declared values: refused before reading them.
  const std::string text = std::string(kTet).substr(0, std::string(kTet).find("0 1 0"));
  EXPECT_EQ(ParseError(text),
            "line 5: POINTS: declares 12 values, but the rest of the file (12 bytes) cannot hold "
            "them");
  // Enough bytes, but they run out before the values do.
  const std::string padded = text + std::string(40, ' ');
  EXPECT_EQ(ParseError(padded),
            "line 8: POINTS: the file ends at value 7 of 12; expected a number");
}

TEST(VtkMalformed, FewerPointsThanDeclared) {
  EXPECT_EQ(ParseError(Replace(kTet, "POINTS 4 float", "POINTS 5 float")),
            "line 10: POINTS: value 13 of 15 is 'CELLS'; expected a number (the section holds "
            "fewer values than its header declares)");
}

TEST(VtkMalformed, MorePointsThanDeclared) {
  EXPECT_EQ(ParseError(Replace(kTet, "POINTS 4 float", "POINTS 3 float")),
            "line 9: expected a section keyword (POINTS, CELLS, CELL_TYPES, FIELD, POINT_DATA, "
            "CELL_DATA), found '0'; the section before it holds more values than its header "
            "declares");
}

TEST(VtkMalformed, UnparsableNumber) {
  EXPECT_EQ(ParseError(Replace(kTet, "1 0 0", "1 0x 0")),
            "line 7: POINTS: value 5 of 12 is '0x'; expected a number");
}

TEST(VtkMalformed, NodeIndexOutOfRange) {
  EXPECT_EQ(ParseError(Replace(kTet, "4 0 1 2 3", "4 0 1 2 4")),
            "line 11: CELLS: cell 0 (tetra) refers to point 4, but POINTS has 4 points (ids 0 "
            "to 3)");
  EXPECT_EQ(ParseError(Replace(kTet, "4 0 1 2 3", "4 0 -1 2 3")),
            "line 11: CELLS: cell 0 (tetra) refers to point -1, but POINTS has 4 points (ids 0 "
            "to 3)");
}

TEST(VtkMalformed, UnknownCellType) {
  EXPECT_EQ(ParseError(Replace(kTet, "CELL_TYPES 1\n10", "CELL_TYPES 1\n99")),
            "line 13: CELL_TYPES: cell 0 has unknown VTK cell type 99");
}

TEST(VtkMalformed, WrongNodeCountForCellType) {
  EXPECT_EQ(ParseError(Replace(kTet, "CELL_TYPES 1\n10", "CELL_TYPES 1\n12")),
            "line 11: CELLS: cell 0 is a hexahedron (VTK type 12) with 4 node ids; expected 8");
}

TEST(VtkMalformed, CellsSizeDisagreesWithRows) {
  EXPECT_EQ(ParseError(Replace(kTet, "CELLS 1 5", "CELLS 1 6")),
            "line 10: CELLS: declares a total size of 6, but its 1 cells hold 5 values");
  EXPECT_EQ(ParseError(Replace(kTet, "CELLS 1 5", "CELLS 1 4")),
            "line 11: CELLS: cell 0 declares 4 node ids, but only 3 values remain of the total "
            "size 4 declared at line 10");
}

TEST(VtkMalformed, CellTypesCountDisagreesWithCells) {
  EXPECT_EQ(ParseError(Replace(kTet, "CELL_TYPES 1\n10", "CELL_TYPES 2\n10 10")),
            "line 12: CELL_TYPES lists 2 cells, but CELLS at line 10 lists 1");
}

TEST(VtkMalformed, PointDataCountDisagreesWithPoints) {
  EXPECT_EQ(ParseError(Replace(kTet, "POINT_DATA 4\n", "POINT_DATA 3\n")),
            "line 14: POINT_DATA declares 3 points, but POINTS has 4");
  EXPECT_EQ(ParseError(std::string(kTet) + "CELL_DATA 2\n"),
            "line 18: CELL_DATA declares 2 cells, but CELLS has 1");
}

TEST(VtkMalformed, IntegerOutOfTypeRange) {
  const std::string text =
      Replace(Replace(kTet, "SCALARS fixed int 1", "SCALARS fixed unsigned_char 1"), "1 1 1 0",
              "1 256 1 0");
  EXPECT_EQ(ParseError(text),
            "line 17: SCALARS fixed: value 2 of 4 is '256'; expected an integer of type "
            "unsigned_char in [0, 255]");
}

// Every form std::from_chars reads (with at most one leading '+') is a value, whether the
// scanner's plain-number fast path takes it (VtkScanner::NextPlainInteger, NextPlainReal) or
// hands it to the general parse: a sign, leading zeros, more than 18 digits, exponents.
TEST(VtkValueForms, SignsZerosAndLongNumbersReadAsTheirValues) {
  std::string text = Replace(kTet, "1 0 0\n0 1 0", "+1 0.0 -0\n0 1e0 +0.0");
  text = Replace(text, "4 0 1 2 3", "+4 0 001 +2 3");
  text = Replace(text, "SCALARS fixed int 1", "SCALARS fixed long 1");
  text = Replace(text, "1 1 1 0", "-0 +7 0000000000000000000000009 -9223372036854775808");
  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(text);
  ASSERT_TRUE(file.ok()) << file.status();
  EXPECT_EQ(file->points.reals, (std::vector<double>{0, 0, 0, 1, 0, -0.0, 0, 1, 0, 0, 0, 1}));
  EXPECT_EQ(file->cells.connectivity, (std::vector<std::int64_t>{0, 1, 2, 3}));
  ASSERT_EQ(file->point_data.size(), 1u);
  EXPECT_EQ(file->point_data[0].arrays[0].integers,
            (std::vector<std::int64_t>{0, 7, 9, std::numeric_limits<std::int64_t>::min()}));
}

// The fast path declines what it cannot judge, so the general parse names it as before.
TEST(VtkValueForms, FormsTheFastPathDeclinesAreReportedAsBefore) {
  const std::string unsigned_fixed =
      Replace(kTet, "SCALARS fixed int 1", "SCALARS fixed unsigned_long 1");
  const absl::StatusOr<UnstructuredGrid> wide =
      ParseVtk(Replace(unsigned_fixed, "1 1 1 0", "18446744073709551615 +1 -0 0"));
  EXPECT_FALSE(wide.ok());  // "-0" is no unsigned 64-bit value for from_chars
  EXPECT_THAT(std::string(wide.status().message()),
              ::testing::HasSubstr("line 17: SCALARS fixed: value 3 of 4 is '-0'"));
  const absl::StatusOr<UnstructuredGrid> largest =
      ParseVtk(Replace(unsigned_fixed, "1 1 1 0", "18446744073709551615 +1 0 0"));
  ASSERT_TRUE(largest.ok()) << largest.status();
  EXPECT_EQ(largest->point_data[0].arrays[0].integers[0], -1);  // stored bit-cast
  EXPECT_EQ(ParseError(Replace(kTet, "4 0 1 2 3", "4 0 1 2 3x")),
            "line 11: CELLS: value 5 of 5 is '3x'; expected an integer of type int in "
            "[-2147483648, 2147483647]");
  EXPECT_EQ(ParseError(Replace(kTet, "4 0 1 2 3", "4 0 1 2 2147483648")),
            "line 11: CELLS: value 5 of 5 is '2147483648'; expected an integer of type int in "
            "[-2147483648, 2147483647]");
  EXPECT_EQ(ParseError(Replace(kTet, "0 1 0\n", "0 1..5 0\n")),
            "line 8: POINTS: value 8 of 12 is '1..5'; expected a number");
}

TEST(VtkMalformed, UnknownDataType) {
  EXPECT_EQ(ParseError(Replace(kTet, "POINTS 4 float", "POINTS 4 quaternion")),
            "line 5: POINTS: unsupported data type 'quaternion'; expected one of bit, "
            "unsigned_char, char, signed_char, unsigned_short, short, unsigned_int, int, "
            "unsigned_long, long, vtkIdType, vtktypeint8, vtktypeuint8, vtktypeint16, "
            "vtktypeuint16, vtktypeint32, vtktypeuint32, vtktypeint64, vtktypeuint64, float, "
            "double");
}

TEST(VtkMalformed, HugeCountsAreRefusedBeforeAllocating) {
  const std::string text = Replace(kTet, "POINTS 4 float", "POINTS 999999999999999 float");
  const std::size_t remaining = text.size() - (text.find("float\n") + 6);
  EXPECT_EQ(ParseError(text),
            "line 5: POINTS: declares 2999999999999997 values, but the rest "
            "of the file (" +
                std::to_string(remaining) + " bytes) cannot hold them");
  EXPECT_EQ(ParseError(Replace(kTet, "POINTS 4 float", "POINTS 9999999999999999999 float")),
            "line 5: POINTS: the count '9999999999999999999' is not a non-negative integer");
}

TEST(VtkMalformed, MissingSections) {
  const std::string kTetText = kTet;
  EXPECT_EQ(ParseError(kTetText.substr(0, kTetText.find("POINTS"))),
            "line 5: the file has no POINTS section");
  EXPECT_EQ(ParseError(Replace(kTet, "CELL_TYPES 1\n10\n", "")),
            "line 10: CELLS without a CELL_TYPES section");
}

// ---- BINARY ----

// kTet as BINARY, by the writer (checked against hand-made bytes in vtk_round_trip_test).
std::string BinaryTet() {
  const absl::StatusOr<UnstructuredGrid> file = ParseVtk(kTet);
  EXPECT_TRUE(file.ok());
  return *SerializeVtk(*file, Encoding::kBinary);
}

TEST(VtkMalformedBinary, PointsBlockTooShort) {
  const std::string binary = BinaryTet();
  const std::size_t data = binary.find("POINTS 4 float\n") + 15;
  // Keep 8 bytes of the 48 the points need.
  const std::string truncated = binary.substr(0, data + 8);
  EXPECT_EQ(ParseError(truncated),
            "byte " + std::to_string(data - 15) +
                ": POINTS: declares 12 values of 4 bytes each, but only 8 bytes remain in the "
                "file");
}

TEST(VtkMalformedBinary, CellTypesBlockTooShort) {
  const std::string binary = BinaryTet();
  const std::size_t header = binary.find("CELL_TYPES 1\n");
  const std::string truncated = binary.substr(0, header + 13 + 2);
  EXPECT_EQ(ParseError(truncated),
            "byte " + std::to_string(header) +
                ": CELL_TYPES: declares 1 values of 4 bytes each, but only 2 bytes remain in "
                "the file");
}

TEST(VtkMalformedBinary, BadCellRowNamesTheByteOffset) {
  std::string binary = BinaryTet();
  const std::size_t row = binary.find("CELLS 1 5\n") + 10;
  binary[row + 3] = 9;  // node count 4 → 9: more ids than the declared size holds
  EXPECT_EQ(ParseError(binary),
            "byte " + std::to_string(row) +
                ": CELLS: cell 0 declares 9 node ids, but only 4 values remain of the total size "
                "5 declared at byte " +
                std::to_string(row - 10));
}

TEST(VtkMalformedBinary, MissingLookupTableLine) {
  std::string binary = BinaryTet();
  binary = Replace(binary, "LOOKUP_TABLE default\n", "");
  const std::size_t scalars = binary.find("SCALARS fixed");
  EXPECT_EQ(ParseError(binary),
            "byte " + std::to_string(scalars) +
                ": SCALARS: expected a 'LOOKUP_TABLE <name>' line after the SCALARS line");
}

// ---- Robustness: every truncation and random damage of real files parses or fails cleanly ----

void ExpectNoCrashOnTruncations(const std::string& bytes) {
  for (std::size_t length = 0; length < bytes.size(); ++length) {
    const absl::StatusOr<UnstructuredGrid> file =
        ParseVtk(absl::string_view(bytes).substr(0, length));
    if (!file.ok()) {
      ASSERT_EQ(file.status().code(), absl::StatusCode::kInvalidArgument) << length;
    }
  }
}

TEST(VtkRobustness, EveryTruncationOfAsciiAndBinaryFiles) {
  const absl::StatusOr<UnstructuredGrid> file = ReadVtkFile(SharedMesh("hexes_4by2by2.vtk"));
  ASSERT_TRUE(file.ok()) << file.status();
  ExpectNoCrashOnTruncations(*SerializeVtk(*file, Encoding::kAscii));
  ExpectNoCrashOnTruncations(*SerializeVtk(*file, Encoding::kBinary));
}

TEST(VtkRobustness, RandomByteDamage) {
  const absl::StatusOr<UnstructuredGrid> file = ReadVtkFile(SharedMesh("6-wedge-prism.vtk"));
  ASSERT_TRUE(file.ok()) << file.status();
  std::mt19937 random(12345);
  for (const Encoding encoding : {Encoding::kAscii, Encoding::kBinary}) {
    const std::string original = *SerializeVtk(*file, encoding);
    for (int trial = 0; trial < 3000; ++trial) {
      std::string damaged = original;
      const int flips = 1 + static_cast<int>(random() % 4);
      for (int f = 0; f < flips; ++f) {
        damaged[random() % damaged.size()] = static_cast<char>(random() % 256);
      }
      const absl::StatusOr<UnstructuredGrid> result = ParseVtk(damaged);
      if (!result.ok()) {
        ASSERT_EQ(result.status().code(), absl::StatusCode::kInvalidArgument);
        ASSERT_FALSE(result.status().message().empty());
      }
    }
  }
}

}  // namespace
}  // namespace getme::formats
