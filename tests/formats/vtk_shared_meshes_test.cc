// Every shared Mesquite mesh reads, converts, and survives ASCII and BINARY round trips.

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <string>

#include "formats/grid_mesh.h"
#include "formats/vtk_reader.h"
#include "formats/vtk_writer.h"
#include "vtk_test_util.h"

namespace getme::formats {
namespace {

using testing::AllSharedMeshNames;
using testing::DeclaredCount;
using testing::DeclaredNumbers;
using testing::ExpectSameContent;
using testing::ReadText;
using testing::SharedMesh;

class SharedMeshTest : public ::testing::TestWithParam<std::string> {};

TEST_P(SharedMeshTest, ReadsWithTheDeclaredCounts) {
  const std::string path = SharedMesh(GetParam());
  const std::string text = ReadText(path);
  const absl::StatusOr<UnstructuredGrid> file = ReadVtkFile(path);
  ASSERT_TRUE(file.ok()) << file.status();
  EXPECT_EQ(file->encoding, Encoding::kAscii);
  EXPECT_EQ(file->point_count(), DeclaredCount(text, "POINTS"));
  EXPECT_EQ(file->cells.size(), DeclaredCount(text, "CELLS"));
  EXPECT_EQ(file->cells.size(), DeclaredCount(text, "CELL_TYPES"));
  // "CELLS n size": size counts every cell's node count and its node ids.
  const std::vector<std::int64_t> cells_line = DeclaredNumbers(text, "CELLS");
  ASSERT_EQ(cells_line.size(), 2u);
  EXPECT_EQ(static_cast<std::int64_t>(file->cells.connectivity.size()) + file->cells.size(),
            cells_line[1]);
}

TEST_P(SharedMeshTest, AsciiRoundTripIsExact) {
  const absl::StatusOr<UnstructuredGrid> file = ReadVtkFile(SharedMesh(GetParam()));
  ASSERT_TRUE(file.ok()) << file.status();
  const absl::StatusOr<std::string> ascii = SerializeVtk(*file, Encoding::kAscii);
  ASSERT_TRUE(ascii.ok()) << ascii.status();
  const absl::StatusOr<UnstructuredGrid> again = ParseVtk(*ascii);
  ASSERT_TRUE(again.ok()) << again.status();
  EXPECT_EQ(again->encoding, Encoding::kAscii);
  ExpectSameContent(*file, *again);
  // Writing what was read gives the same bytes again.
  EXPECT_EQ(*SerializeVtk(*again, Encoding::kAscii), *ascii);
}

TEST_P(SharedMeshTest, BinaryRoundTripIsExact) {
  const absl::StatusOr<UnstructuredGrid> file = ReadVtkFile(SharedMesh(GetParam()));
  ASSERT_TRUE(file.ok()) << file.status();
  const absl::StatusOr<std::string> binary = SerializeVtk(*file, Encoding::kBinary);
  ASSERT_TRUE(binary.ok()) << binary.status();
  EXPECT_NE(binary->find("\nBINARY\n"), std::string::npos);
  const absl::StatusOr<UnstructuredGrid> again = ParseVtk(*binary);
  ASSERT_TRUE(again.ok()) << again.status();
  EXPECT_EQ(again->encoding, Encoding::kBinary);
  ExpectSameContent(*file, *again);
  EXPECT_EQ(*SerializeVtk(*again, Encoding::kBinary), *binary);
}

TEST_P(SharedMeshTest, ConvertsToTheEngineMeshUnlessItIsASurface) {
  const absl::StatusOr<UnstructuredGrid> file = ReadVtkFile(SharedMesh(GetParam()));
  ASSERT_TRUE(file.ok()) << file.status();
  const absl::StatusOr<GridMesh> mesh = GridToMesh(*file);
  if (GetParam() == "sph-10-zsquare.vtk") {
    ASSERT_FALSE(mesh.ok());
    EXPECT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
    EXPECT_EQ(mesh.status().message(),
              "no volume elements: the file has 216 quad cells (VTK type 9); getme smooths "
              "tetrahedra (10), hexahedra (12), wedges (13), pyramids (14)");
    return;
  }
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  EXPECT_EQ(mesh->mesh.node_count(), file->point_count());
  // All Mesquite meshes are pure volume meshes: every cell is an element, in file order.
  EXPECT_EQ(mesh->mesh.element_count(), file->cells.size());
  for (std::int64_t cell = 0; cell < file->cells.size(); ++cell) {
    ASSERT_EQ(mesh->cell_elements[cell], cell);
    ASSERT_EQ(mesh->element_cells[cell], cell);
  }
}

INSTANTIATE_TEST_SUITE_P(Mesquite, SharedMeshTest, ::testing::ValuesIn(AllSharedMeshNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param.substr(0, info.param.size() - 4);
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

// The parametrized tests above run over what the folder holds; this pins the folder to what
// ../shared/meshes/README.md documents for mesquite/ (17 meshes when these tests were written, 20
// since the corpus grew), so a missing or half-copied folder cannot pass with fewer meshes.
TEST(SharedMeshes, EveryMeshTheReadmeListsIsPresent) {
  ASSERT_TRUE(std::filesystem::is_directory(std::string(GETME_SHARED_MESHES) + "/mesquite"))
      << "no folder " << GETME_SHARED_MESHES << "/mesquite: the tests read the shared meshes "
      << "there (configure with -DGETME_SHARED_MESHES=<folder> to point elsewhere)";
  const std::string readme = ReadText(std::string(GETME_SHARED_MESHES) + "/README.md");
  const std::string mesquite_part = readme.substr(0, readme.find("## su2/"));
  std::set<std::string> listed;
  static const std::regex kVtkName(R"(([A-Za-z0-9_./-]+)\.vtk)");
  for (auto it = std::sregex_iterator(mesquite_part.begin(), mesquite_part.end(), kVtkName);
       it != std::sregex_iterator(); ++it) {
    // "../su2/…" rows are meshes of the other folder.
    if ((*it)[1].str().find('/') == std::string::npos) listed.insert((*it)[1].str() + ".vtk");
  }
  const std::vector<std::string> present = AllSharedMeshNames();
  EXPECT_GE(listed.size(), 17u);
  EXPECT_EQ(std::set<std::string>(present.begin(), present.end()), listed);
}

TEST(SharedMeshes, MixedMeshHasTheDocumentedTypeCounts) {
  const absl::StatusOr<UnstructuredGrid> file = ReadVtkFile(SharedMesh("mixed-hex-pyr-tet.vtk"));
  ASSERT_TRUE(file.ok()) << file.status();
  const absl::StatusOr<GridMesh> mesh = GridToMesh(*file);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  // meshes/README.md: 940 (445 tet, 305 hex, 190 pyr).
  EXPECT_EQ(mesh->mesh.element_count(ElementType::kTetrahedron), 445);
  EXPECT_EQ(mesh->mesh.element_count(ElementType::kHexahedron), 305);
  EXPECT_EQ(mesh->mesh.element_count(ElementType::kPyramid), 190);
  EXPECT_EQ(mesh->mesh.element_count(ElementType::kPrism), 0);
}

}  // namespace
}  // namespace getme::formats
