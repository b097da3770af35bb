// OpenFOAM behind the generic mesh-file interface (formats/mesh_file.h): a directory is read as a
// polyMesh, the format names and paths that select it, patches as groups, and the single-file
// entry points that cannot take a directory.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "formats/mesh_file.h"
#include "openfoam_test_util.h"

namespace getme::formats {
namespace {

using testing::CasePath;

TEST(OpenFoamMeshFile, ADirectoryIsReadAsAPolyMesh) {
  absl::StatusOr<MeshDocument> document = ReadMeshDocument(CasePath("mixed_binary"));
  ASSERT_TRUE(document.ok()) << document.status();
  EXPECT_EQ(document->format, FileFormat::kOpenFoam);
  EXPECT_STREQ(FormatDisplayName(document->format), "OpenFOAM polyMesh");
  EXPECT_EQ(DefaultWriteOptions(*document, FileFormat::kOpenFoam).encoding, Encoding::kBinary);
  const absl::StatusOr<MeshDocument> not_a_case =
      ReadMeshDocument(CasePath("mixed_binary") + "/system");
  EXPECT_EQ(not_a_case.status().code(), absl::StatusCode::kNotFound);
}

TEST(OpenFoamMeshFile, NamesAndPathsSelectOpenFoam) {
  EXPECT_EQ(ParseFormatName("openfoam")->format, FileFormat::kOpenFoam);
  EXPECT_EQ(ParseFormatName("FOAM")->format, FileFormat::kOpenFoam);
  EXPECT_EQ(FormatFromExtension("case/constant/polyMesh"), FileFormat::kOpenFoam);
  EXPECT_EQ(FormatFromExtension("case/constant/polyMesh/"), FileFormat::kOpenFoam);
  EXPECT_EQ(FormatFromExtension("case"), std::nullopt);
  EXPECT_EQ(ParseMeshDocument("x", FileFormat::kOpenFoam).status().message(),
            "an OpenFOAM polyMesh is a directory of files, not one file: read it with "
            "ReadMeshDocument (a case or polyMesh directory)");
  const absl::StatusOr<MeshDocument> document = ReadMeshDocument(CasePath("box_ascii"));
  ASSERT_TRUE(document.ok()) << document.status();
  EXPECT_EQ(
      SerializeMeshDocument(*document, FileFormat::kOpenFoam, document->as_read).status().message(),
      "an OpenFOAM polyMesh is a directory of files, not one file: write it with "
      "WriteMeshDocument");
}

TEST(OpenFoamMeshFile, PatchesAreGroupsByName) {
  const absl::StatusOr<MeshDocument> document = ReadMeshDocument(CasePath("mixed_ascii"));
  ASSERT_TRUE(document.ok()) << document.status();
  const std::map<std::string, std::int64_t> expected = testing::CheckMeshCounts("mixed_ascii");
  for (const OpenFoamPatch& patch : document->openfoam->patches) {
    absl::StatusOr<std::vector<std::int64_t>> cells = GroupCells(*document, patch.name);
    ASSERT_TRUE(cells.ok()) << cells.status();
    EXPECT_EQ(static_cast<std::int64_t>(cells->size()), expected.at("patch " + patch.name));
  }
  // The fixed nodes of patch xmin are the points of its faces, which lie on x = 0.
  absl::StatusOr<std::vector<std::uint8_t>> fixed = SelectFixedNodes(*document, {"xmin"}, false);
  ASSERT_TRUE(fixed.ok()) << fixed.status();
  for (std::int64_t point = 0; point < document->grid.point_count(); ++point) {
    EXPECT_EQ((*fixed)[point] == 1, document->grid.points.reals[3 * point] == 0.0) << point;
  }
  // Tagged faces for --boundary slide: one per boundary face.
  EXPECT_EQ(static_cast<std::int64_t>(TaggedSurfaceFaces(*document).size()),
            document->grid.cells.size() - document->openfoam->cell_count);
  EXPECT_EQ(GroupCells(*document, "inlet").status().message(),
            "no OpenFOAM patch 'inlet'; the mesh's patches: 'zmin', 'ymin', 'xmin', 'xmax', "
            "'ymax', 'zmax'");
}

TEST(OpenFoamMeshFile, WritesACaseDirectory) {
  const absl::StatusOr<MeshDocument> document = ReadMeshDocument(CasePath("box_binary"));
  ASSERT_TRUE(document.ok()) << document.status();
  const std::string out = std::string(OPENFOAM_FIXTURES) + "/written/mesh_file_case";
  std::filesystem::remove_all(out);
  ASSERT_TRUE(WriteMeshDocument(out, *document, FileFormat::kOpenFoam, document->as_read).ok());
  const absl::StatusOr<MeshDocument> again = ReadMeshDocument(out);
  ASSERT_TRUE(again.ok()) << again.status();
  EXPECT_EQ(again->grid.points.reals, document->grid.points.reals);
  EXPECT_TRUE(std::filesystem::exists(out + "/constant/polyMesh/faces"));
}

}  // namespace
}  // namespace getme::formats
