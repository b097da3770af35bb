// `--fix-physical G` on an Exodus file: G names a node set, side set or element block (by name,
// then id), and SelectFixedNodes holds exactly its nodes.

#include "formats/exodus/exodus_groups.h"

#include <gtest/gtest.h>

#include <string>

#include "exodus_test_util.h"
#include "formats/exodus/exodus_reader.h"
#include "formats/mesh_file.h"

namespace getme::formats {
namespace {

using testing::ExodusFixture;

MeshDocument Hybrid() {
  absl::StatusOr<MeshDocument> document = ReadExodus(ExodusFixture("hybrid.exo"));
  EXPECT_TRUE(document.ok()) << document.status();
  return document.ok() ? *std::move(document) : MeshDocument{};
}

using Nodes = std::vector<std::int64_t>;

TEST(ExodusGroups, NodeSetByNameAndId) {
  const MeshDocument document = Hybrid();
  EXPECT_EQ(*ExodusGroupNodes(document, "clamp"), (Nodes{0, 1, 2}));
  EXPECT_EQ(*ExodusGroupNodes(document, "5"), (Nodes{0, 1, 2}));
  // The second hexahedron's top: points 38..45 are its nodes, 42..45 the top four.
  EXPECT_EQ(*ExodusGroupNodes(document, "top"), (Nodes{42, 43, 44, 45}));
}

TEST(ExodusGroups, SideSetAndBlockGiveTheirCellsNodes) {
  const MeshDocument document = Hybrid();
  // "wall": side 6 (top) of the first hexahedron (points 30..37) and side 4 of the first tet.
  EXPECT_EQ(*ExodusGroupNodes(document, "wall"), (Nodes{0, 1, 2, 34, 35, 36, 37}));
  EXPECT_EQ(*ExodusGroupNodes(document, "tetra_block"), (Nodes{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(*ExodusGroupNodes(document, "7"), (Nodes{34, 35, 36, 37}));
}

TEST(ExodusGroups, UnknownGroupListsWhatThereIs) {
  const absl::StatusOr<Nodes> nodes = ExodusGroupNodes(Hybrid(), "outlet");
  EXPECT_EQ(nodes.status().code(), absl::StatusCode::kNotFound);
  EXPECT_EQ(nodes.status().message(),
            "no node set, side set or element block 'outlet' (by name or id); node sets: clamp "
            "(5), top (6); side sets: inlet (1), wall (2); element blocks: tetra_block (100), "
            "wedge_block (101), pyramid_block (102), hexahedron_block (103), lid (7)");
}

TEST(ExodusGroups, SelectFixedNodesHoldsANodeSet) {
  const MeshDocument document = Hybrid();
  const absl::StatusOr<std::vector<std::uint8_t>> fixed =
      SelectFixedNodes(document, {"clamp", "top"}, false);
  ASSERT_TRUE(fixed.ok()) << fixed.status();
  Nodes marked;
  for (std::size_t k = 0; k < fixed->size(); ++k) {
    if ((*fixed)[k] != 0) marked.push_back(static_cast<std::int64_t>(k));
  }
  EXPECT_EQ(marked, (Nodes{0, 1, 2, 42, 43, 44, 45}));
}

}  // namespace
}  // namespace getme::formats
