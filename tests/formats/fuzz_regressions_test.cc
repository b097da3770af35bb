// The inputs in tests/data/fuzz-regressions/ once broke an invariant the fuzz targets check
// (fuzz/, docs/fuzzing.md). Each must now be read as the fuzzers require: refused with
// InvalidArgument, or read, written back in its own format and read again.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "formats/mesh_file.h"

namespace getme::formats {
namespace {

std::vector<std::string> RegressionInputs() {
  std::vector<std::string> paths;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(GETME_TEST_DATA) + "/fuzz-regressions")) {
    if (entry.is_regular_file()) paths.push_back(entry.path().string());
  }
  return paths;
}

TEST(FuzzRegressions, EveryInputIsRefusedOrWrittenBack) {
  const std::vector<std::string> paths = RegressionInputs();
  ASSERT_FALSE(paths.empty());
  for (const std::string& path : paths) {
    SCOPED_TRACE(path);
    const absl::StatusOr<MeshDocument> document = ReadMeshDocument(path);
    if (!document.ok()) {
      EXPECT_EQ(document.status().code(), absl::StatusCode::kInvalidArgument) << document.status();
      continue;
    }
    const absl::StatusOr<std::string> bytes =
        SerializeMeshDocument(*document, document->format, document->as_read);
    ASSERT_TRUE(bytes.ok()) << bytes.status();
    const absl::StatusOr<MeshDocument> again = ParseMeshDocument(*bytes, document->format);
    ASSERT_TRUE(again.ok()) << again.status();
    EXPECT_EQ(again->grid.points.reals, document->grid.points.reals);
    EXPECT_EQ(again->grid.cells.connectivity, document->grid.cells.connectivity);
  }
}

// The first regression: a Gmsh view whose string tag is a lone '"'.
TEST(FuzzRegressions, GmshStringTagHoldingAQuoteIsRefusedNamingTheLine) {
  const absl::StatusOr<MeshDocument> document = ReadMeshDocument(
      std::string(GETME_TEST_DATA) + "/fuzz-regressions/gmsh-string-tag-single-quote.msh");
  ASSERT_FALSE(document.ok());
  EXPECT_NE(document.status().message().find("line 31 in $NodeData: string tag 1 of 1"),
            std::string::npos)
      << document.status();
}

}  // namespace
}  // namespace getme::formats
