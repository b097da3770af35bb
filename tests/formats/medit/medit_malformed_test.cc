// Malformed MEDIT input gives InvalidArgument naming the line, the section and the entry; no
// prefix of a valid file crashes the parser or passes for a whole file.

#include <gtest/gtest.h>

#include <ostream>
#include <random>
#include <string>
#include <vector>

#include "formats/medit/medit_reader.h"
#include "formats/medit/medit_writer.h"

namespace getme::formats {
namespace {

constexpr char kHeader[] = "MeshVersionFormatted 2\nDimension 3\n";
// Lines 3..8: "Vertices", "4" and four vertices; Valid() puts its sections from line 9 on.
constexpr char kVertices[] = "Vertices\n4\n0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n";

struct MalformedCase {
  const char* name;
  std::string text;
  std::vector<std::string> message_parts;
};

std::string Valid(const std::string& sections) {
  return std::string(kHeader) + kVertices + sections + "End\n";
}

std::vector<MalformedCase> Cases() {
  return {
      {"Empty", "", {"line 1", "expected MeshVersionFormatted, found the end of the file"}},
      {"NoVersion", "Dimension 3\nEnd\n", {"line 1", "expected MeshVersionFormatted"}},
      {"VersionOutOfRange",
       "MeshVersionFormatted 5\nDimension 3\nEnd\n",
       {"line 1", "MeshVersionFormatted 5", "1 (single precision) to 4"}},
      {"VersionNotANumber",
       "MeshVersionFormatted two\nDimension 3\nEnd\n",
       {"line 1", "expected an integer, found 'two'"}},
      {"DimensionTwo",
       "MeshVersionFormatted 2\nDimension 2\nEnd\n",
       {"line 2", "Dimension 2", "only Dimension 3"}},
      {"DimensionMissing",
       "MeshVersionFormatted 2\nVertices\n0\nEnd\n",
       {"line 2", "expected Dimension after MeshVersionFormatted, found 'Vertices'"}},
      {"TruncatedInVertices",
       std::string(kHeader) + "Vertices\n2\n0.000000 0.000000 0.000000 1\n1.000000 0.0000",
       {"line 6", "the file ends in Vertices entry 2 of 2", "truncated"}},
      {"TruncatedBeforeCount",
       std::string(kHeader) + "Vertices",
       {"line 3", "the file ends before the entry count of Vertices"}},
      {"NoEnd", std::string(kHeader) + kVertices, {"line 9", "ends without End"}},
      {"CountLargerThanEntries",
       std::string(kHeader) + "Vertices\n3\n0 0 0 1\n1 0 0 1\nTetrahedra\n1\n1 2 3 1 0\nEnd\n",
       {"line 7", "Vertices entry 3, field 1", "expected a real number, found 'Tetrahedra'"}},
      {"CountSmallerThanEntries",
       std::string(kHeader) + "Vertices\n1\n0 0 0 1\n1 0 0 1\nEnd\n",
       {"line 6", "expected a keyword, found '1'"}},
      {"CountBeyondTheFile",
       std::string(kHeader) + "Vertices\n99999999999999\n0 0 0 1\nEnd\n",
       {"line 4", "Vertices: 99999999999999 entries of 4 numbers cannot fit", "truncated"}},
      {"NegativeCount",
       std::string(kHeader) + "Vertices\n-1\nEnd\n",
       {"line 4", "Vertices: expected an entry count, found '-1'"}},
      {"UnknownKeywordWithData",
       Valid("Foo\n2\n1 2\n"),
       {"line 9", "unknown keyword 'Foo'", "cannot be skipped"}},
      {"UnsupportedHighOrder",
       Valid("TetrahedraP2\n0\n"),
       {"line 9", "'TetrahedraP2' is not supported", "high-order"}},
      {"SolutionKeywordInMesh",
       Valid("SolAtVertices\n0\n"),
       {"line 9", "'SolAtVertices' is not supported", ".sol"}},
      {"VertexIndexZero",
       Valid("Tetrahedra\n2\n1 2 3 4 0\n0 1 2 3 0\n"),
       {"line 12", "Tetrahedra entry 2: vertex 0 out of range 1..4"}},
      {"VertexIndexBeyondCount",
       Valid("Triangles\n1\n1 2 5 0\n"),
       {"line 11", "Triangles entry 1: vertex 5 out of range 1..4"}},
      {"VertexIndexNotAnInteger",
       Valid("Edges\n1\n1.5 2 0\n"),
       {"line 11", "Edges entry 1, field 1: expected an integer, found '1.5'"}},
      {"CoordinateNotANumber",
       std::string(kHeader) + "Vertices\n1\n0 0 x 1\nEnd\n",
       {"line 5", "Vertices entry 1, field 3: expected a real number, found 'x'"}},
      {"RefTooLarge",
       Valid("Edges\n1\n1 2 4294967296\n"),
       {"line 11", "Edges entry 1: reference 4294967296 does not fit a 32-bit integer"}},
      {"DuplicateSection",
       Valid("Corners\n1\n1\nCorners\n1\n2\n"),
       {"line 12", "second Corners section (the first is at line 9)"}},
      {"SecondHeader", Valid("Dimension\n3\n"), {"line 9", "second Dimension"}},
      {"CornerOutOfRange",
       Valid("Corners\n2\n1\n9\n"),
       {"line 12", "Corners entry 2: vertex 9 out of range 1..4"}},
      {"RidgeWithoutEdges",
       Valid("Ridges\n1\n1\n"),
       {"line 11", "Ridges entry 1: edge 1 out of range: the file has no edge entities"}},
      {"NormalIndexOutOfRange",
       Valid("Normals\n1\n0 0 1\nNormalAtVertices\n1\n1 2\n"),
       {"line 14", "NormalAtVertices entry 1: normal 2 out of range 1..1"}},
      {"RequiredVertexOutOfRange",
       Valid("RequiredVertices\n1\n7\n"),
       {"line 11", "RequiredVertices entry 1: vertex 7 out of range 1..4"}},
      {"DataAfterEnd", Valid("") + "Corners\n1\n1\n", {"line 10", "'Corners' after End"}},
  };
}

void PrintTo(const MalformedCase& param, std::ostream* out) { *out << param.name; }

class MeditMalformedTest : public ::testing::TestWithParam<MalformedCase> {};

TEST_P(MeditMalformedTest, IsInvalidArgumentNamingWhereAndWhat) {
  const MalformedCase& param = GetParam();
  const absl::StatusOr<MeshDocument> document = ParseMedit(param.text);
  ASSERT_FALSE(document.ok()) << "parsed:\n" << param.text;
  EXPECT_EQ(document.status().code(), absl::StatusCode::kInvalidArgument);
  for (const std::string& part : param.message_parts) {
    EXPECT_NE(document.status().message().find(part), absl::string_view::npos)
        << "'" << part << "' not in: " << document.status().message();
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, MeditMalformedTest, ::testing::ValuesIn(Cases()),
                         [](const ::testing::TestParamInfo<MalformedCase>& info) {
                           return std::string(info.param.name);
                         });

TEST(MeditMalformed, EveryPrefixOfAValidFileIsRefusedCleanly) {
  const std::string text =
      Valid("Tetrahedra\n1\n1 2 3 4 7\nCorners\n1\n3\nNormals\n1\n0 0 1\n") + "# done\n";
  ASSERT_TRUE(ParseMedit(text).ok());
  const std::size_t end = text.find("End") + 3;
  for (std::size_t length = 0; length < text.size(); ++length) {
    const absl::StatusOr<MeshDocument> document = ParseMedit(text.substr(0, length));
    if (length >= end) {
      EXPECT_TRUE(document.ok()) << length << ": " << document.status();
    } else {
      ASSERT_FALSE(document.ok()) << "prefix of " << length << " bytes parsed";
      EXPECT_EQ(document.status().code(), absl::StatusCode::kInvalidArgument);
    }
  }
}

TEST(MeditMalformed, RandomEditsAreRefusedOrWrittenBack) {
  // Whatever parses must serialize and read back as the same document; the rest is refused with
  // InvalidArgument (and, under the sanitizers, without touching memory it should not).
  const std::string valid = Valid(
      "Edges\n1\n1 2 3\nTetrahedra\n1\n1 2 3 4 7\nRequiredVertices\n1\n2\n"
      "Corners\n1\n3\nRidges\n1\n1\nNormals\n1\n0 0 1\nNormalAtVertices\n1\n4 1\n");
  const std::string alphabet = "0123456789 \n#.-+eE-xVEnd";
  std::mt19937 random(20240611);
  int parsed = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::string text = valid;
    const int edits = 1 + static_cast<int>(random() % 3);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = random() % text.size();
      switch (random() % 3) {
        case 0:
          text[at] = alphabet[random() % alphabet.size()];
          break;
        case 1:
          text.erase(at, 1 + random() % 4);
          break;
        default:
          text.insert(at, 1, alphabet[random() % alphabet.size()]);
          break;
      }
    }
    const absl::StatusOr<MeshDocument> document = ParseMedit(text);
    if (!document.ok()) {
      ASSERT_EQ(document.status().code(), absl::StatusCode::kInvalidArgument) << text;
      ASSERT_EQ(document.status().message().rfind("line ", 0), 0u) << document.status();
      continue;
    }
    ++parsed;
    const absl::StatusOr<std::string> written = SerializeMedit(*document, document->as_read);
    ASSERT_TRUE(written.ok()) << written.status() << "\n" << text;
    const absl::StatusOr<MeshDocument> again = ParseMedit(*written);
    ASSERT_TRUE(again.ok()) << again.status() << "\n" << *written;
    EXPECT_EQ(again->grid.points.reals, document->grid.points.reals);
    EXPECT_EQ(again->grid.cells.connectivity, document->grid.cells.connectivity);
    EXPECT_EQ(again->medit, document->medit);
  }
  EXPECT_GT(parsed, 0);  // some edits (digits in coordinates, comments) keep the file valid
}

}  // namespace
}  // namespace getme::formats
