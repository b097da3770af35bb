// tests/data/hybrid-example.vtk (the README demo's mesh) is
//   getme-meshgen hybrid tests/data/hybrid-example.vtk --size 7,7,8 --distortion 0.3 --seed 1
// This checks that the committed file is exactly that mesh, so it can be regenerated.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "absl/strings/str_cat.h"
#include "formats/grid_mesh.h"
#include "formats/unstructured_grid.h"
#include "formats/vtk_reader.h"
#include "getme/meshgen/hybrid_block.h"
#include "mesh_checks.h"

namespace getme::meshgen {
namespace {

TEST(HybridExampleFileTest, IsTheHybridBlockItClaimsToBeWithAllFourTypes) {
  const std::string path = absl::StrCat(GETME_TEST_DATA, "/hybrid-example.vtk");
  absl::StatusOr<formats::UnstructuredGrid> file = formats::ReadVtkFile(path);
  ASSERT_TRUE(file.ok()) << file.status();
  EXPECT_EQ(file->encoding, formats::Encoding::kAscii);
  absl::StatusOr<formats::GridMesh> read = formats::GridToMesh(*file);
  ASSERT_TRUE(read.ok()) << read.status();
  absl::StatusOr<Mesh> generated = HybridBlock(7, 7, 8, 0.3, 1);
  ASSERT_TRUE(generated.ok()) << generated.status();

  const Mesh& mesh = read->mesh;
  ASSERT_EQ(mesh.node_count(), generated->node_count());
  ASSERT_EQ(mesh.element_count(), generated->element_count());
  EXPECT_TRUE(std::ranges::equal(mesh.x(), generated->x()));
  EXPECT_TRUE(std::ranges::equal(mesh.y(), generated->y()));
  EXPECT_TRUE(std::ranges::equal(mesh.z(), generated->z()));
  for (ElementId e = 0; e < mesh.element_count(); ++e) {
    ASSERT_EQ(mesh.type(e), generated->type(e)) << "element " << e;
    ASSERT_TRUE(std::ranges::equal(mesh.element_nodes(e), generated->element_nodes(e)))
        << "element " << e;
  }
  for (const ElementType type : kAllElementTypes) {
    EXPECT_GT(mesh.element_count(type), 0) << TypeName(type);
  }
  EXPECT_GE(mesh.element_count(), 1000);
  EXPECT_LE(mesh.element_count(), 3000);
  EXPECT_TRUE(testing::InvalidElements(mesh).empty());
}

}  // namespace
}  // namespace getme::meshgen
