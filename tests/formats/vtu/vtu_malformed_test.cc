// Malformed .vtu input gives InvalidArgument naming the line, the XML element and the array —
// and never crashes, whatever the damage.

#include <gtest/gtest.h>

#include <random>

#include "absl/strings/escaping.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "formats/vtu/vtu_reader.h"
#include "formats/vtu/vtu_writer.h"
#include "vtk_test_util.h"
#include "vtu_expected.h"

namespace getme::formats {
namespace {

// Line numbers below refer to this file.
constexpr char kTets[] = R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="1.0" byte_order="LittleEndian">
  <UnstructuredGrid>
    <Piece NumberOfPoints="5" NumberOfCells="2">
      <PointData Scalars="fixed">
        <DataArray type="Int32" Name="fixed" format="ascii">
          1 1 1 1 0
        </DataArray>
      </PointData>
      <Points>
        <DataArray type="Float64" Name="Points" NumberOfComponents="3" format="ascii">
          0 0 0  1 0 0  0 1 0
          0 0 1  1 1 1
        </DataArray>
      </Points>
      <Cells>
        <DataArray type="Int64" Name="connectivity" format="ascii">
          0 1 2 3  1 2 3 4
        </DataArray>
        <DataArray type="Int64" Name="offsets" format="ascii">
          4 8
        </DataArray>
        <DataArray type="UInt8" Name="types" format="ascii">
          10 10
        </DataArray>
      </Cells>
    </Piece>
  </UnstructuredGrid>
</VTKFile>
)";

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at == std::string::npos) return text;
  return text.replace(at, from.size(), to);
}

// Parses and returns the error message, failing the test if parsing succeeds or the error is not
// InvalidArgument.
std::string ParseError(const std::string& text) {
  const absl::StatusOr<MeshDocument> document = ParseVtu(text);
  EXPECT_FALSE(document.ok());
  if (document.ok()) return "";
  EXPECT_EQ(document.status().code(), absl::StatusCode::kInvalidArgument) << document.status();
  return std::string(document.status().message());
}

// kTets written by SerializeVtu in a binary layout.
std::string Binary(VtuLayout layout, bool zlib) {
  const absl::StatusOr<MeshDocument> document = ParseVtu(kTets);
  EXPECT_TRUE(document.ok()) << document.status();
  const absl::StatusOr<std::string> bytes =
      SerializeVtu(*document, {Encoding::kBinary, GmshVersion::k41, layout, zlib});
  EXPECT_TRUE(bytes.ok()) << bytes.status();
  return bytes.ok() ? *bytes : "";
}

TEST(VtuMalformed, TheBaseFileIsFine) {
  const absl::StatusOr<MeshDocument> document = ParseVtu(kTets);
  ASSERT_TRUE(document.ok()) << document.status();
  EXPECT_EQ(document->grid.point_count(), 5);
  EXPECT_EQ(document->grid.cells.size(), 2);
  EXPECT_EQ(document->as_read.encoding, Encoding::kAscii);
  EXPECT_EQ(document->as_read.vtu_layout, VtuLayout::kInline);
}

TEST(VtuMalformed, Empty) {
  EXPECT_EQ(ParseError(""), "line 1: not well-formed XML (No document element found)");
}

TEST(VtuMalformed, Truncated) {
  const std::string text = kTets;
  EXPECT_EQ(ParseError(text.substr(0, text.find("0 0 1  1 1 1"))),
            "line 13: not well-formed XML (Start-end tags mismatch)");
}

TEST(VtuMalformed, NotAVtkFile) {
  EXPECT_EQ(ParseError("<?xml version=\"1.0\"?>\n<html><body/></html>\n"),
            "line 2: <html>: expected the root element <VTKFile>; this is not a VTK XML file");
  EXPECT_EQ(ParseError(Replace(kTets, "UnstructuredGrid\" version", "PolyData\" version")),
            "line 2: <VTKFile>: type 'PolyData' is not supported; getme reads type "
            "\"UnstructuredGrid\"");
  EXPECT_EQ(ParseError(Replace(kTets, "Grid\" version=\"1.0\"", "Grid\" version=\"3.0\"")),
            "line 2: <VTKFile>: version '3.0' is not supported; expected 0.1, 1.0 or 2.x");
  EXPECT_EQ(ParseError(Replace(kTets, "LittleEndian", "MiddleEndian")),
            "line 2: <VTKFile>: byte_order 'MiddleEndian' is not supported; expected "
            "LittleEndian or BigEndian");
}

TEST(VtuMalformed, WrongNumberOfPoints) {
  EXPECT_EQ(ParseError(Replace(kTets, "NumberOfPoints=\"5\"", "NumberOfPoints=\"6\"")),
            "line 11: DataArray 'Points' of <Points>: holds 15 values, but "
            "NumberOfPoints=\"6\" of <Piece> (line 4) needs 18 (6 tuples of 3 components)");
  EXPECT_EQ(ParseError(Replace(kTets, "0 0 1  1 1 1", "0 0 1  1 1 1  2 2 2")),
            "line 13: DataArray 'Points' of <Points>: holds more than the 15 values expected");
  // The point data disagrees with the points as well; the first array read is named.
  EXPECT_EQ(ParseError(Replace(kTets, "1 1 1 1 0", "1 1 1 1")),
            "line 6: DataArray 'fixed' of <PointData>: holds 4 values, but "
            "NumberOfPoints=\"5\" of <Piece> (line 4) needs 5 (5 tuples of 1 components)");
}

TEST(VtuMalformed, WrongNumberOfCells) {
  EXPECT_EQ(ParseError(Replace(kTets, "NumberOfCells=\"2\"", "NumberOfCells=\"3\"")),
            "line 20: DataArray 'offsets' of <Cells>: holds 2 values, but NumberOfCells=\"3\" "
            "of <Piece> (line 4) needs 3 (3 tuples of 1 components)");
}

TEST(VtuMalformed, Offsets) {
  EXPECT_EQ(ParseError(Replace(kTets, "4 8\n", "4 10\n")),
            "line 20: DataArray 'offsets' of <Cells>: the last offset is 10, but DataArray "
            "'connectivity' of <Cells> (line 17) holds 8 node ids");
  EXPECT_EQ(ParseError(Replace(kTets, "4 8\n", "9 8\n")),
            "line 20: DataArray 'offsets' of <Cells>: offset 1 (8) is smaller than offset 0 (9)");
  EXPECT_EQ(ParseError(Replace(kTets, "4 8\n", "-1 8\n")),
            "line 20: DataArray 'offsets' of <Cells>: offset 0 (-1) is negative");
  EXPECT_EQ(ParseError(Replace(kTets, "4 8\n", "5 8\n")),
            "line 20: DataArray 'offsets' of <Cells>: cell 0 is a tetra (VTK type 10) with 5 "
            "node ids; expected 4");
}

TEST(VtuMalformed, CellTypes) {
  EXPECT_EQ(ParseError(Replace(kTets, "10 10\n", "10 99\n")),
            "line 23: DataArray 'types' of <Cells>: cell 1 has unknown VTK cell type 99");
  EXPECT_EQ(ParseError(Replace(kTets, "10 10\n", "10 1000\n")),
            "line 24: DataArray 'types' of <Cells>: value 2 is '1000'; expected an integer of "
            "type UInt8 in [0, 255]");
  EXPECT_EQ(ParseError(Replace(Replace(kTets, "UInt8\" Name=\"types", "Int32\" Name=\"types"),
                               "10 10\n", "10 1000\n")),
            "line 23: DataArray 'types' of <Cells>: cell 1 has unknown VTK cell type 1000");
  EXPECT_EQ(ParseError(Replace(kTets, "10 10\n", "10 42\n")),
            "line 23: DataArray 'types' of <Cells>: cell 1 is a polyhedron (VTK type 42), which "
            "getme does not read");
  EXPECT_EQ(ParseError(Replace(kTets, "      </Cells>",
                               "        <DataArray type=\"Int64\" Name=\"faces\" "
                               "format=\"ascii\">1</DataArray>\n      </Cells>")),
            "line 26: DataArray 'faces' of <Cells>: polyhedron cells (faces / faceoffsets) are "
            "not supported; getme reads tetrahedra, hexahedra, wedges, pyramids and linear cells "
            "of dimension 0-2");
}

TEST(VtuMalformed, NodeIdOutOfRange) {
  EXPECT_EQ(ParseError(Replace(kTets, "1 2 3 4\n", "1 2 3 5\n")),
            "line 17: DataArray 'connectivity' of <Cells>: cell 1 (tetra) refers to point 5, but "
            "the piece has 5 points (ids 0 to 4)");
  EXPECT_EQ(ParseError(Replace(kTets, "0 1 2 3 ", "0 1 -2 3 ")),
            "line 17: DataArray 'connectivity' of <Cells>: cell 0 (tetra) refers to point -2, "
            "but the piece has 5 points (ids 0 to 4)");
}

TEST(VtuMalformed, Arrays) {
  EXPECT_EQ(ParseError(Replace(kTets, "0 0 0  1 0 0", "0 0 0  1 x 0")),
            "line 12: DataArray 'Points' of <Points>: value 5 is 'x'; expected a number");
  EXPECT_EQ(ParseError(Replace(kTets, "Int32\" Name=\"fixed", "String\" Name=\"fixed")),
            "line 6: DataArray 'fixed' of <PointData>: type 'String' is not supported; expected "
            "Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64");
  EXPECT_EQ(ParseError(Replace(kTets, "NumberOfComponents=\"3\"", "NumberOfComponents=\"2\"")),
            "line 11: DataArray 'Points' of <Points>: has 2 components; expected 3");
  EXPECT_EQ(ParseError(Replace(kTets, "Int64\" Name=\"offsets", "Float32\" Name=\"offsets")),
            "line 20: DataArray 'offsets' of <Cells>: must have an integer type, not Float32");
  EXPECT_EQ(ParseError(
                Replace(kTets, "Name=\"fixed\" format=\"ascii\"", "Name=\"fixed\" format=\"hex\"")),
            "line 6: DataArray 'fixed' of <PointData>: format 'hex' is not supported; expected "
            "ascii, binary or appended");
  EXPECT_EQ(ParseError(Replace(kTets, "Name=\"connectivity\"", "Name=\"links\"")),
            "line 16: <Cells>: has no DataArray named 'connectivity'");
}

// Found by fuzz/vtu_fuzzer.cc: pugixml does not check that attribute text is XML 1.0, so a name
// with a control character (raw or as a character reference) was read, and the writer then
// refused it. A tab, CR or LF (written as character references) is still fine.
TEST(VtuMalformed, ArrayNameWithAControlCharacter) {
  EXPECT_EQ(ParseError(Replace(kTets, "Name=\"fixed\"",
                               "Name=\"fix\x14"
                               "ed\"")),
            "line 6: DataArray 'fix\x14"
            "ed' of <PointData>: Name holds a control character, which "
            "XML cannot carry");
  EXPECT_EQ(ParseError(Replace(kTets, "Name=\"fixed\"", "Name=\"fix&#x1;ed\"")),
            "line 6: DataArray 'fix\x01"
            "ed' of <PointData>: Name holds a control character, which "
            "XML cannot carry");
  const absl::StatusOr<MeshDocument> tab =
      ParseVtu(Replace(kTets, "Name=\"fixed\"", "Name=\"a&#9;b\""));
  ASSERT_TRUE(tab.ok()) << tab.status();
  EXPECT_NE(FindArray(tab->grid.point_data, "a\tb"), nullptr);
}

TEST(VtuMalformed, BadBase64) {
  std::string text = Binary(VtuLayout::kInline, false);
  // The first data character of the first binary array (fixed).
  const std::size_t data = text.find('>', text.find("Name=\"fixed\"")) + 12;
  text[data + 4] = '*';
  const std::string message = ParseError(text);
  EXPECT_EQ(message,
            "line 6: DataArray 'fixed' of <PointData>: invalid base64 in characters 0 to 50 of "
            "the encoded data")
      << text;
}

TEST(VtuMalformed, CorruptZlib) {
  for (const VtuLayout layout : {VtuLayout::kInline, VtuLayout::kAppended}) {
    SCOPED_TRACE(layout == VtuLayout::kInline ? "inline" : "appended");
    std::string text = Binary(layout, true);
    if (layout == VtuLayout::kAppended) {
      // After the '_': the first array's (fixed's) 32-byte header, then its zlib stream.
      text[text.find('_', text.find("<AppendedData")) + 1 + 32 + 3] ^= 0x5a;
    } else {
      // Re-encode fixed's data (header and blocks are encoded apart) with a flipped byte.
      const std::size_t start = text.find('>', text.find("Name=\"fixed\"")) + 12;
      const std::size_t end = text.find('\n', start);
      const std::string header_text = text.substr(start, 44);  // 32 bytes → 44 characters
      std::string blocks;
      ASSERT_TRUE(absl::Base64Unescape(text.substr(start + 44, end - start - 44), &blocks));
      blocks[3] ^= 0x5a;
      text.replace(start, end - start, header_text + absl::Base64Escape(blocks));
    }
    const std::string message = ParseError(text);
    EXPECT_TRUE(
        message.starts_with("line 6: DataArray 'fixed' of <PointData>: binary data: "
                            "compressed block 0 of 1 is not valid zlib data ("))
        << message;
  }
}

TEST(VtuMalformed, AppendedData) {
  const std::string text = Binary(VtuLayout::kAppended, false);
  EXPECT_EQ(ParseError(Replace(text, "offset=\"0\"", "offset=\"100000\"")),
            "line 6: DataArray 'fixed' of <PointData>: offset 100000 is beyond the 265 bytes of "
            "<AppendedData> (line 18)");
  // Points' data (at 28, after fixed's 8-byte header and 20 bytes) moved to 180, the third id
  // (2) of connectivity (whose ids start at 156 + 8).
  EXPECT_EQ(ParseError(Replace(text, "offset=\"28\"", "offset=\"180\"")),
            "line 9: DataArray 'Points' of <Points>: binary data: the header declares 2 data "
            "bytes; expected 120");
  // The last array (types) with its data cut short, right before </AppendedData>.
  const std::size_t close = text.rfind("\n  </AppendedData>");
  EXPECT_EQ(ParseError(text.substr(0, close - 1) + text.substr(close + 3)),
            "line 14: DataArray 'types' of <Cells>: binary data: the header declares 2 data "
            "bytes, but only 1 follow");
  EXPECT_EQ(ParseError(text.substr(0, close - 20)),
            "line 18: <AppendedData>: no closing </AppendedData>; the file is truncated");
  EXPECT_EQ(ParseError(Replace(text, "encoding=\"raw\"", "encoding=\"hex\"")),
            "line 18: <AppendedData>: encoding 'hex' is not supported; expected raw or base64");
}

TEST(VtuMalformed, UnsupportedCompressor) {
  const std::string text =
      Replace(Binary(VtuLayout::kInline, true), "vtkZLibDataCompressor", "vtkLZ4DataCompressor");
  EXPECT_EQ(ParseError(text),
            "line 11: DataArray 'Points' of <Points>: the file's compressor "
            "'vtkLZ4DataCompressor' (line 2) is not supported; getme reads uncompressed data and "
            "vtkZLibDataCompressor");
  // ASCII arrays are never compressed: such a file reads.
  EXPECT_TRUE(ParseVtu(Replace(kTets, "byte_order",
                               "compressor=\"vtkLZ4DataCompressor\" "
                               "byte_order"))
                  .ok());
}

TEST(VtuMalformed, PiecesThatDoNotMatch) {
  const std::string text = kTets;
  const std::size_t begin = text.find("    <Piece");
  const std::size_t end = text.find("  </UnstructuredGrid>");
  const std::string piece = text.substr(begin, end - begin);
  const std::string second = Replace(piece, "Int32\" Name=\"fixed", "Int64\" Name=\"fixed");
  EXPECT_EQ(ParseError(text.substr(0, end) + second + text.substr(end)),
            "line 28: <Piece>: its <PointData> array 'fixed' differs in name, type or components; "
            "every piece must have the arrays of the first (line 4) to be merged into one grid");
  // Matching pieces merge, the second's node ids offset by the first's points.
  const absl::StatusOr<MeshDocument> merged =
      ParseVtu(text.substr(0, end) + piece + text.substr(end));
  ASSERT_TRUE(merged.ok()) << merged.status();
  EXPECT_EQ(merged->grid.point_count(), 10);
  EXPECT_EQ(merged->grid.cells.connectivity,
            (std::vector<std::int64_t>{0, 1, 2, 3, 1, 2, 3, 4, 5, 6, 7, 8, 6, 7, 8, 9}));
  EXPECT_EQ(merged->grid.cells.offsets, (std::vector<std::int64_t>{0, 4, 8, 12, 16}));
  EXPECT_EQ(merged->grid.point_data[0].arrays[0].integers,
            (std::vector<std::int64_t>{1, 1, 1, 1, 0, 1, 1, 1, 1, 0}));
}

// Random damage to every layout: an error or a file, never a crash or an allocation the input
// cannot back (run under the sanitizer stage of scripts/test.sh). The bases cover every layout,
// both byte orders, several pieces and appended base64.
TEST(VtuMalformed, RandomDamageNeverCrashes) {
  std::mt19937 random(7);
  for (const std::string& base :
       {std::string(kTets), Binary(VtuLayout::kInline, false), Binary(VtuLayout::kInline, true),
        Binary(VtuLayout::kAppended, false), Binary(VtuLayout::kAppended, true),
        testing::ReadText(testing::FixturePath("hand_big_endian_zlib_uint64.vtu")),
        testing::ReadText(testing::FixturePath("hand_appended_raw_two_pieces.vtu")),
        testing::ReadText(testing::FixturePath("hand_appended_base64_zlib.vtu"))}) {
    ASSERT_FALSE(base.empty());
    for (int trial = 0; trial < 300; ++trial) {
      std::string text = base;
      const int damage = 1 + static_cast<int>(random() % 4);
      for (int k = 0; k < damage; ++k) {
        const std::size_t at = random() % text.size();
        switch (random() % 3) {
          case 0:
            text[at] = static_cast<char>(random());
            break;
          case 1:
            text.erase(at, 1 + random() % 8);
            break;
          default:
            text.resize(at);
            break;
        }
        if (text.empty()) text.push_back('<');
      }
      const absl::StatusOr<MeshDocument> document = ParseVtu(text);
      if (!document.ok()) {
        EXPECT_EQ(document.status().code(), absl::StatusCode::kInvalidArgument)
            << document.status();
        EXPECT_TRUE(absl::StartsWith(document.status().message(), "line ")) << document.status();
      }
    }
  }
}

}  // namespace
}  // namespace getme::formats
