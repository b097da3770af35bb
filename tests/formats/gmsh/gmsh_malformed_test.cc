// Malformed MSH input gives InvalidArgument naming the line (ASCII) or the byte offset and
// section (binary), the node or element involved and what was expected — and never crashes,
// whatever the damage. Also: a big-endian binary file reads like its little-endian twin.

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <random>

#include "formats/gmsh/gmsh_reader.h"
#include "gmsh_test_util.h"

namespace getme::formats {
namespace {

using testing::GmshInput;
using testing::ReadBytes;

// Line numbers below refer to these files.
constexpr char kMsh22[] = R"($MeshFormat
2.2 0 8
$EndMeshFormat
$PhysicalNames
1
3 1 "solid"
$EndPhysicalNames
$Nodes
5
1 0 0 0
2 1 0 0
3 0 1 0
4 0 0 1
5 1 1 1
$EndNodes
$Elements
2
1 4 2 1 1 1 2 3 4
2 4 2 1 1 2 3 4 5
$EndElements
$NodeData
1
"fixed"
1
0
3
0
1
2
1 1
2 1
$EndNodeData
)";

constexpr char kMsh41[] = R"($MeshFormat
4.1 0 8
$EndMeshFormat
$Entities
0 0 0 1
1 0 0 0 1 1 1 1 7 0
$EndEntities
$Nodes
1 5 1 5
3 1 0 5
1
2
3
4
5
0 0 0
1 0 0
0 1 0
0 0 1
1 1 1
$EndNodes
$Elements
1 2 1 2
3 1 4 2
1 1 2 3 4
2 2 3 4 5
$EndElements
)";

std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

// The text up to (not including) line `line` (1-based).
std::string FirstLines(const std::string& text, int lines) {
  std::size_t end = 0;
  for (int i = 0; i < lines; ++i) end = text.find('\n', end) + 1;
  return text.substr(0, end);
}

std::string ParseError(const std::string& bytes) {
  const absl::StatusOr<MeshDocument> document = ParseGmsh(bytes);
  EXPECT_FALSE(document.ok());
  if (document.ok()) return "";
  EXPECT_EQ(document.status().code(), absl::StatusCode::kInvalidArgument) << document.status();
  return std::string(document.status().message());
}

TEST(GmshMalformed, TheBaseFilesAreFine) {
  const absl::StatusOr<MeshDocument> a = ParseGmsh(kMsh22);
  ASSERT_TRUE(a.ok()) << a.status();
  EXPECT_EQ(a->grid.cells.size(), 2);
  const absl::StatusOr<MeshDocument> b = ParseGmsh(kMsh41);
  ASSERT_TRUE(b.ok()) << b.status();
  EXPECT_EQ(b->grid.cells.size(), 2);
}

TEST(GmshMalformed, NotAnMshFile) {
  EXPECT_EQ(ParseError(""), "line 1: the file is empty; expected '$MeshFormat'");
  EXPECT_EQ(ParseError("hello\n"),
            "line 1: expected '$MeshFormat', found 'hello'; this is not a Gmsh MSH file");
  EXPECT_EQ(ParseError("$NOD\n1\n"),
            "line 1: this is an MSH 1 file ($NOD); getme reads MSH 2.2 and 4.1");
}

TEST(GmshMalformed, BadMeshFormat) {
  EXPECT_EQ(ParseError(Replace(kMsh22, "2.2 0 8", "3.0 0 8")),
            "line 2 in $MeshFormat: unsupported MSH version '3.0'; getme reads 2.2 and 4.1");
  EXPECT_EQ(ParseError(Replace(kMsh41, "4.1 0 8", "4 0 8")),
            "line 2 in $MeshFormat: MSH 4.0 is not supported (its layout differs from 4.1); getme "
            "reads MSH 2.2 and 4.1 (gmsh -save -format msh41 converts)");
  EXPECT_EQ(ParseError(Replace(kMsh22, "2.2 0 8", "2.2 0")),
            "line 2 in $MeshFormat: expected 'version file-type data-size' (e.g. '4.1 0 8'), "
            "found '2.2 0'");
  EXPECT_EQ(ParseError(Replace(kMsh22, "2.2 0 8", "2.2 2 8")),
            "line 2 in $MeshFormat: file-type must be 0 (ASCII) or 1 (binary), found 2");
  EXPECT_EQ(
      ParseError(Replace(kMsh22, "2.2 0 8", "2.2 0 4")),
      "line 2 in $MeshFormat: data-size 4 is not supported; MSH 2.2 needs 8 (sizeof(double))");
  EXPECT_EQ(ParseError(Replace(kMsh22, "$EndMeshFormat", "$Nodes")),
            "line 3 in $MeshFormat: expected '$EndMeshFormat' after the declared number of "
            "entries, found '$Nodes'");
  EXPECT_EQ(ParseError(Replace(kMsh22, "$EndNodeData\n", "$EndNodeData\n$MeshFormat\n")),
            "line 33 in $MeshFormat: a second $MeshFormat section");
}

TEST(GmshMalformed, TruncatedInEachSection) {
  const std::string text = kMsh22;
  EXPECT_EQ(ParseError(FirstLines(text, 2)),
            "line 3 in $MeshFormat: the file ends before "
            "'$EndMeshFormat'");
  EXPECT_EQ(ParseError(FirstLines(text, 5)),
            "line 5 in $PhysicalNames: declares 1 physical names, but the 1 bytes left in the "
            "file cannot hold them");
  EXPECT_EQ(ParseError(FirstLines(text, 8) + "2\n1 0.25 0.25 0.25\n2 1.25 0.25"),
            "line 11 in $Nodes: the file ends where the z coordinate of node 2 of 2 was expected");
  EXPECT_EQ(ParseError(FirstLines(text, 12)),
            "line 9 in $Nodes: declares 5 nodes, but the 25 bytes left in the file cannot hold "
            "them");
  EXPECT_EQ(ParseError(FirstLines(text, 18)),
            "line 19 in $Elements: the file ends where the tag of element 2 of 2 was expected");
  EXPECT_EQ(ParseError(text.substr(0, text.find("2 3 4 5"))),
            "line 19 in $Elements: the file ends where node 1 of 4 of element 2 (4-node "
            "tetrahedron) was expected");
  EXPECT_EQ(ParseError(FirstLines(text, 30)),
            "line 29 in $NodeData: declares 2 entries, but the 4 bytes left in the file cannot "
            "hold them");
  EXPECT_EQ(ParseError(FirstLines(text, 29) + "1 1.000000\n2 "),
            "line 31 in $NodeData: the file ends where value 1 of 1 of entry 2 (node 2) was "
            "expected");
  EXPECT_EQ(ParseError(FirstLines(text, 27)),
            "line 26 in $NodeData: declares 3 integer tags, but the 2 bytes left in the file "
            "cannot hold them");
  EXPECT_EQ(ParseError(FirstLines(text, 21)),
            "line 22 in $NodeData: the file ends before the number of string tags");
  EXPECT_EQ(ParseError(FirstLines(text, 31)),
            "line 32 in $NodeData: the file ends before '$EndNodeData'");
}

TEST(GmshMalformed, WrongCounts) {
  EXPECT_EQ(ParseError(Replace(kMsh22, "$Nodes\n5\n", "$Nodes\n6\n")),
            "line 15 in $Nodes: expected the tag of node 6 of 6 (an integer), found '$EndNodes'");
  EXPECT_EQ(ParseError(Replace(kMsh22, "$Nodes\n5\n", "$Nodes\n4\n")),
            "line 14 in $Nodes: expected '$EndNodes' after the declared number of entries, found "
            "'5 1 1 1'");
  EXPECT_EQ(ParseError(Replace(kMsh22, "$Elements\n2\n", "$Elements\n3\n")),
            "line 20 in $Elements: expected the tag of element 3 of 3 (an integer), found "
            "'$EndElements'");
  EXPECT_EQ(ParseError(Replace(kMsh22, "$Nodes\n5\n", "$Nodes\n99999999999\n")),
            "line 9 in $Nodes: declares 99999999999 nodes, but the 165 bytes left in the file "
            "cannot hold them");
  EXPECT_EQ(ParseError(Replace(kMsh22, "$Nodes\n5\n", "$Nodes\n-1\n")),
            "line 9 in $Nodes: negative nodes count -1");
  EXPECT_EQ(ParseError(Replace(kMsh41, "3 1 0 5\n", "3 1 0 6\n")),
            "line 10 in $Nodes: node block 1 declares 6 nodes, but the header's 5 leave 5");
  EXPECT_EQ(ParseError(Replace(kMsh41, "1 5 1 5\n3 1 0 5", "2 5 1 5\n3 1 0 5")),
            "line 21 in $Nodes: expected the entity dimension of node block 2 of 2 (an integer), "
            "found '$EndNodes'");
  EXPECT_EQ(ParseError(Replace(kMsh41, "1 2 1 2\n", "1 3 1 2\n")),
            "line 26 in $Elements: the header declares 3 elements, but the blocks hold 2");
  EXPECT_EQ(ParseError(Replace(kMsh22, "2\n1 1\n2 1\n", "3\n1 1\n2 1\n")),
            "line 32 in $NodeData: expected the node tag of entry 3 of 3 (an integer), found "
            "'$EndNodeData'");
}

TEST(GmshMalformed, BadElements) {
  EXPECT_EQ(ParseError(Replace(kMsh22, "2 4 2 1 1 2 3 4 5", "2 99 2 1 1 2 3 4 5")),
            "line 19 in $Elements: element 2: unknown Gmsh element type 99");
  EXPECT_EQ(ParseError(Replace(kMsh22, "2 4 2 1 1 2 3 4 5", "2 11 2 1 1 2 3 4 5 1 2 3 4 5 1")),
            "line 19 in $Elements: element 2: Gmsh element type 11 (10-node second-order "
            "tetrahedron) is not supported; getme reads linear elements (types 1-7 and 15)");
  EXPECT_EQ(ParseError(Replace(kMsh22, "2 4 2 1 1 2 3 4 5", "2 4 2 1 1 2 3 4 9")),
            "line 19 in $Elements: element 2: node tag 9 is not in $Nodes");
  EXPECT_EQ(ParseError(Replace(kMsh22, "2 4 2 1 1 2 3 4 5", "1 4 2 1 1 2 3 4 5")),
            "line 19 in $Elements: element tag 1 appears twice (first as element 1 of $Elements)");
  EXPECT_EQ(ParseError(Replace(kMsh22, "2 4 2 1 1 2 3 4 5", "2 4 2 1 1 2 x 4 5")),
            "line 19 in $Elements: expected node 2 of 4 of element 2 (4-node tetrahedron) (an "
            "integer), found 'x'");
  EXPECT_EQ(ParseError(Replace(kMsh41, "3 1 4 2\n", "3 1 99 2\n")),
            "line 24 in $Elements: element 1: unknown Gmsh element type 99");
  EXPECT_EQ(ParseError(Replace(kMsh41, "3 1 4 2\n", "5 1 4 2\n")),
            "line 24 in $Elements: element block 1: entity dimension 5 is not 0-3");
  EXPECT_EQ(ParseError(Replace(kMsh41, "2 2 3 4 5\n", "2 2 3 4 6\n")),
            "line 26 in $Elements: element 2: node tag 6 is not in $Nodes");
  // Elements need the nodes first.
  const std::string swapped =
      Replace(Replace(kMsh22, "$Nodes\n", "$Skipped\n"), "$EndNodes\n", "$EndSkipped\n");
  EXPECT_EQ(ParseError(swapped),
            "line 16 in $Elements: $Elements comes before $Nodes; elements refer to node tags");
}

TEST(GmshMalformed, BadNodesAndData) {
  EXPECT_EQ(ParseError(Replace(kMsh22, "2 1 0 0\n", "2 1 zz 0\n")),
            "line 11 in $Nodes: expected the y coordinate of node 2 of 5 (a number), found 'zz'");
  EXPECT_EQ(ParseError(Replace(kMsh22, "2 1 0 0\n", "1 1 0 0\n")),
            "line 11 in $Nodes: node 2 of 5: node tag 1 appears twice (first as node 1)");
  EXPECT_EQ(ParseError(Replace(kMsh22, "2 1 0 0\n", "0 1 0 0\n")),
            "line 11 in $Nodes: node 2 of 5: node tag 0 is not positive");
  EXPECT_EQ(ParseError(Replace(kMsh22, "1 1\n2 1\n", "1 1\n7 1\n")),
            "line 31 in $NodeData: entry 2 of 2: node tag 7 is not in $Nodes");
  EXPECT_EQ(ParseError(Replace(kMsh22, "3\n0\n1\n2\n", "2\n0\n1\n")),
            "line 28 in $NodeData: expected at least 3 integer tags (time step, components, "
            "entries), found 2");
  EXPECT_EQ(ParseError(Replace(kMsh22, "0\n1\n2\n1 1\n2 1\n", "0\n1000\n0\n")),
            "line 29 in $NodeData: 1000 components for each of the 5 nodes exceed what a file of "
            "this size can carry");
  EXPECT_EQ(ParseError(Replace(kMsh22, "$PhysicalNames\n1\n3 1 \"solid\"",
                               "$PhysicalNames\n1\n3 \"solid\"")),
            "line 6 in $PhysicalNames: physical name 1 of 1: expected 'dim tag \"name\"' (dim "
            "0-3), found '3 \"solid\"'");
}

// Found by fuzz/engine_mesh_fuzzer.cc: the reader kept names the writer then refused as
// inconsistent extras, so a file read fine but could not be written back. Gmsh ends a quoted
// name at its first inner '"', and MSH has no escape: such names are refused when read.
TEST(GmshMalformed, NamesHoldingAQuoteOrACarriageReturn) {
  EXPECT_EQ(ParseError(Replace(kMsh22, "3 1 \"solid\"", "3 1 \"so\"lid\"")),
            "line 6 in $PhysicalNames: physical name 1 of 1: the name holds a '\"' or a carriage "
            "return, found '3 1 \"so\"lid\"'");
  EXPECT_EQ(ParseError(Replace(kMsh22, "1\n\"fixed\"\n", "1\nx\"fixed\"\n")),
            "line 23 in $NodeData: string tag 1 of 1: the text holds a '\"' or a carriage "
            "return, found 'x\"fixed\"'");
  EXPECT_EQ(ParseError(Replace(kMsh22, "1\n\"fixed\"\n", "1\n\"fi\rxed\"\n")),
            "line 23 in $NodeData: string tag 1 of 1: the text holds a '\"' or a carriage "
            "return, found '\"fi\rxed\"'");
}

TEST(GmshMalformed, SectionStructure) {
  EXPECT_EQ(ParseError(std::string(kMsh22) + "$Foo\nbar\n"),
            "line 33 in $Foo: no '$EndFoo' closes the section");
  EXPECT_EQ(ParseError(std::string(kMsh22) + "$EndFoo\n"),
            "line 33: '$EndFoo' without a matching '$Foo'");
  EXPECT_EQ(ParseError(std::string(kMsh22) + "garbage\n"),
            "line 33: expected a section header '$Name', found 'garbage'");
  EXPECT_EQ(ParseError(std::string(kMsh22) + "$Nodes\n1\n9 0 0 0\n$EndNodes\n"),
            "line 33 in $Nodes: a second $Nodes section");
  // Unknown sections are kept, whatever they hold.
  const absl::StatusOr<MeshDocument> kept =
      ParseGmsh(std::string(kMsh22) + "$Foo\n$Bar\n\x01\x02\n$EndFoo\n");
  ASSERT_TRUE(kept.ok()) << kept.status();
  ASSERT_EQ(kept->gmsh->raw_sections.size(), 1u);
  EXPECT_EQ(kept->gmsh->raw_sections[0].body, "$Bar\n\x01\x02\n");
}

// ---- Binary ----

std::size_t After(const std::string& bytes, const std::string& marker) {
  const std::size_t at = bytes.find(marker);
  EXPECT_NE(at, std::string::npos) << marker;
  return at + marker.size();
}

TEST(GmshMalformedBinary, EndiannessCheck) {
  std::string bytes = ReadBytes(GmshInput("hybrid_41_binary.msh"));
  const std::size_t one = After(bytes, "4.1 1 8\n");
  bytes[one] = 2;
  EXPECT_EQ(ParseError(bytes),
            "byte 20 in $MeshFormat: the endianness check must be the integer 1 (bytes 01 00 00 "
            "00, or 00 00 00 01 from a big-endian machine), found bytes 02 00 00 00");
  EXPECT_EQ(ParseError(bytes.substr(0, one + 2)),
            "byte 20 in $MeshFormat: the file ends before the endianness check (the integer 1)");
}

TEST(GmshMalformedBinary, CountsAndTypesNameSectionAndOffset) {
  const std::string original = ReadBytes(GmshInput("hybrid_41_binary.msh"));
  // $Nodes header: numEntityBlocks, numNodes, … as size_t.
  std::string bytes = original;
  const std::size_t nodes = After(bytes, "$Nodes\n");
  const std::uint64_t huge = 1ull << 40;
  std::memcpy(&bytes[nodes + 8], &huge, 8);
  EXPECT_EQ(ParseError(bytes), "byte " + std::to_string(nodes + 8) +
                                   " in $Nodes: declares 1099511627776 nodes, but "
                                   "the " +
                                   std::to_string(bytes.size() - nodes - 32) +
                                   " bytes left in the file cannot hold them");
  // The first element block's type (after dim and entity tag, 4-byte ints).
  bytes = original;
  const std::size_t block = After(bytes, "$Elements\n") + 32;
  const std::int32_t type = 42;
  std::memcpy(&bytes[block + 8], &type, 4);
  const std::string message = ParseError(bytes);
  EXPECT_TRUE(message.starts_with("byte " + std::to_string(block + 8) + " in $Elements: element "))
      << message;
  EXPECT_TRUE(message.ends_with(": unknown Gmsh element type 42")) << message;
}

TEST(GmshMalformedBinary, TruncatedAnywhere) {
  for (const std::string name : {"hybrid_22_binary.msh", "views_41_binary.msh"}) {
    const std::string bytes = ReadBytes(GmshInput(name));
    const std::size_t binary_from = After(bytes, " 1 8\n");
    for (std::size_t size = 0; size < bytes.size(); ++size) {
      SCOPED_TRACE(name + " cut at " + std::to_string(size));
      const absl::StatusOr<MeshDocument> document = ParseGmsh(bytes.substr(0, size));
      if (document.ok()) continue;  // cut right after a complete section
      ASSERT_EQ(document.status().code(), absl::StatusCode::kInvalidArgument);
      const std::string message(document.status().message());
      // The version line has line numbers; from the endianness check on, byte offsets.
      ASSERT_TRUE(message.starts_with("byte ") ||
                  (size < binary_from && message.starts_with("line ")))
          << message;
    }
  }
  // Cut near the end of each binary section: the message names the section and the offset of
  // the value that is missing (or of the count the rest cannot hold).
  const std::string bytes = ReadBytes(GmshInput("hybrid_41_binary.msh"));
  for (const std::string section : {"Entities", "Nodes", "Elements"}) {
    const std::size_t end = bytes.find("\n$End" + section);
    for (std::size_t cut = end - 40; cut < end; cut += 7) {
      const std::string message = ParseError(bytes.substr(0, cut));
      const std::size_t in = message.find(" in $" + section + ": ");
      ASSERT_NE(in, std::string::npos) << message;
      ASSERT_TRUE(message.starts_with("byte ")) << message;
      const std::size_t offset = std::stoul(message.substr(5, in - 5));
      EXPECT_LE(offset, cut) << message;
      if (message.find("the file ends where") != std::string::npos) {
        EXPECT_GE(offset + 8, cut) << message;
      } else {
        EXPECT_NE(message.find("bytes left in the file cannot hold them"), std::string::npos)
            << message;
      }
    }
  }
}

TEST(GmshMalformed, TruncatedAtEveryLine) {
  const std::string text = ReadBytes(GmshInput("views_41_ascii.msh"));
  int line = 1;
  for (std::size_t end = 0; end < text.size(); end = text.find('\n', end) + 1, ++line) {
    const absl::StatusOr<MeshDocument> document = ParseGmsh(text.substr(0, end));
    if (document.ok()) continue;
    ASSERT_EQ(document.status().code(), absl::StatusCode::kInvalidArgument);
    ASSERT_TRUE(std::string(document.status().message()).starts_with("line ")) << document.status();
  }
  EXPECT_GT(line, 100);
}

TEST(GmshMalformed, RandomDamageNeverCrashes) {
  std::mt19937 random(5);
  for (const std::string name : {"hybrid_22_ascii.msh", "hybrid_22_binary.msh",
                                 "views_41_ascii.msh", "views_41_binary.msh"}) {
    const std::string original = ReadBytes(GmshInput(name));
    for (int trial = 0; trial < 2000; ++trial) {
      std::string bytes = original;
      for (int k = 0; k < 1 + trial % 4; ++k) {
        bytes[random() % bytes.size()] = static_cast<char>(random() % 256);
      }
      const absl::StatusOr<MeshDocument> document = ParseGmsh(bytes);
      if (!document.ok()) {
        ASSERT_EQ(document.status().code(), absl::StatusCode::kInvalidArgument) << name;
      }
    }
  }
}

// A 2.2 binary file with one tet, little- or big-endian.
std::string TetFile(bool big_endian) {
  std::string out = "$MeshFormat\n2.2 1 8\n";
  const auto append = [&](auto value) {
    char bytes[sizeof(value)];
    std::memcpy(bytes, &value, sizeof(value));
    if (big_endian) std::reverse(bytes, bytes + sizeof(value));
    out.append(bytes, sizeof(value));
  };
  append(std::int32_t{1});
  out += "\n$EndMeshFormat\n$Nodes\n4\n";
  const double coords[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.1, 0.2, 1.0 / 3.0}};
  for (int i = 0; i < 4; ++i) {
    append(std::int32_t{10 * (i + 1)});
    for (double c : coords[i]) append(c);
  }
  out += "\n$EndNodes\n$Elements\n1\n";
  for (std::int32_t value : {4, 1, 2, 7, 0, 3, 10, 20, 30, 40}) append(value);
  out += "\n$EndElements\n";
  return out;
}

TEST(GmshBinary, BigEndianFilesReadLikeLittleEndianOnes) {
  const absl::StatusOr<MeshDocument> little = ParseGmsh(TetFile(false));
  const absl::StatusOr<MeshDocument> big = ParseGmsh(TetFile(true));
  ASSERT_TRUE(little.ok()) << little.status();
  ASSERT_TRUE(big.ok()) << big.status();
  testing::ExpectSameDocument(*little, *big, /*with_extras=*/false);
  EXPECT_EQ(big->gmsh->node_tags, (std::vector<std::int64_t>{10, 20, 30, 40}));
  EXPECT_EQ(big->gmsh->element_tags, (std::vector<std::int64_t>{7}));
  EXPECT_EQ(big->grid.points.reals[11], 1.0 / 3.0);
  EXPECT_TRUE(big->gmsh->big_endian);
  EXPECT_FALSE(little->gmsh->big_endian);
}

}  // namespace
}  // namespace getme::formats
