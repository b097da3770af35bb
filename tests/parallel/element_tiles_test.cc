// ElementTiles (core/getme/parallel/element_tiles.h), checked by brute force: every element is in
// exactly one tile, the visiting order's node and element ids are the block's, no two tiles of a
// colour share a node, the build is deterministic, and a mesh numbered without locality gets the
// Morton order (with far fewer colours than its own order would need).

#include "getme/parallel/element_tiles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <vector>

#include "getme/meshgen/hybrid_block.h"
#include "shuffled_mesh.h"

namespace getme {
namespace {

void ExpectValidTiling(const Mesh& mesh, const ElementTiles& tiles) {
  // The visiting order holds each block entry once, with the block's node ids.
  for (ElementType type : kAllElementTypes) {
    const ElementBlock& block = mesh.block(type);
    const int per_element = NodeCount(type);
    std::vector<ElementId> seen(tiles.elements(type), tiles.elements(type) + block.elements.size());
    std::vector<ElementId> expected = block.elements;
    std::sort(seen.begin(), seen.end());
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(seen, expected) << TypeName(type);
    for (std::size_t i = 0; i < block.elements.size(); ++i) {
      const std::span<const NodeId> nodes = mesh.element_nodes(tiles.elements(type)[i]);
      EXPECT_TRUE(std::equal(nodes.begin(), nodes.end(), tiles.nodes(type) + i * per_element))
          << TypeName(type) << " visit " << i;
    }
  }
  // Tiles cover [0, count) of each type once, and a colour's tiles share no node.
  std::vector<std::vector<int>> covered(kElementTypeCount);
  for (ElementType type : kAllElementTypes)
    covered[TypeIndex(type)].assign(mesh.element_count(type), 0);
  const auto cover = [&](const ElementTiles::Tile& tile) {
    ASSERT_LE(0, tile.begin);
    ASSERT_LT(tile.begin, tile.end);
    ASSERT_LE(tile.end, mesh.element_count(tile.type));
    for (std::int64_t i = tile.begin; i < tile.end; ++i) ++covered[TypeIndex(tile.type)][i];
  };
  for (int c = 0; c < tiles.colour_count(); ++c) {
    ASSERT_FALSE(tiles.colour(c).empty()) << "colour " << c;
    std::set<NodeId> colour_nodes;
    for (const ElementTiles::Tile& tile : tiles.colour(c)) {
      cover(tile);
      std::set<NodeId> tile_nodes;
      const int per_element = NodeCount(tile.type);
      for (std::int64_t i = tile.begin * per_element; i < tile.end * per_element; ++i) {
        tile_nodes.insert(tiles.nodes(tile.type)[i]);
      }
      for (NodeId node : tile_nodes) {
        EXPECT_TRUE(colour_nodes.insert(node).second)
            << "colour " << c << ": node " << node << " is in two of its tiles";
      }
    }
  }
  for (const ElementTiles::Tile& tile : tiles.serial()) cover(tile);
  for (const std::vector<int>& counts : covered) {
    EXPECT_TRUE(std::all_of(counts.begin(), counts.end(), [](int n) { return n == 1; }));
  }
}

TEST(ElementTilesTest, AGeneratedBlockKeepsItsOrderAndTilesIt) {
  const absl::StatusOr<Mesh> mesh = meshgen::HybridBlock(12, 12, 10, 0.3, 4);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const ElementTiles tiles(*mesh);
  ExpectValidTiling(*mesh, tiles);
  EXPECT_FALSE(tiles.morton_order());
  EXPECT_EQ(tiles.nodes(ElementType::kTetrahedron),
            mesh->block(ElementType::kTetrahedron).nodes.data());  // no copy
  EXPECT_GT(tiles.tile_count(), 10);
  EXPECT_LE(tiles.colour_count(), 16);
  EXPECT_TRUE(tiles.serial().empty());
}

TEST(ElementTilesTest, AShuffledMeshGetsTheMortonOrder) {
  const absl::StatusOr<Mesh> block = meshgen::HybridBlock(12, 12, 10, 0.3, 4);
  ASSERT_TRUE(block.ok()) << block.status();
  const Mesh mesh = mesh_test::Shuffled(*block, 9);
  const ElementTiles tiles(mesh);
  ExpectValidTiling(mesh, tiles);
  EXPECT_TRUE(tiles.morton_order());
  EXPECT_TRUE(tiles.serial().empty());
  EXPECT_LE(tiles.colour_count(), 24);
}

TEST(ElementTilesTest, TheBuildIsDeterministic) {
  const absl::StatusOr<Mesh> block = meshgen::HybridBlock(8, 8, 6, 0.3, 2);
  ASSERT_TRUE(block.ok()) << block.status();
  const Mesh mesh = mesh_test::Shuffled(*block, 3);
  const ElementTiles first(mesh, 64);
  const ElementTiles second(mesh, 64);
  ASSERT_EQ(first.colour_count(), second.colour_count());
  for (int c = 0; c < first.colour_count(); ++c) {
    ASSERT_EQ(first.colour(c).size(), second.colour(c).size());
    for (std::size_t t = 0; t < first.colour(c).size(); ++t) {
      EXPECT_EQ(first.colour(c)[t].type, second.colour(c)[t].type);
      EXPECT_EQ(first.colour(c)[t].begin, second.colour(c)[t].begin);
    }
  }
  for (ElementType type : kAllElementTypes) {
    EXPECT_TRUE(std::equal(first.elements(type), first.elements(type) + mesh.element_count(type),
                           second.elements(type)));
  }
}

TEST(ElementTilesTest, TilesBeyondTheColourLimitRunSerially) {
  const absl::StatusOr<Mesh> mesh = meshgen::HybridBlock(8, 8, 6, 0.3, 2);
  ASSERT_TRUE(mesh.ok()) << mesh.status();
  const ElementTiles tiles(*mesh, 32, 2);
  ExpectValidTiling(*mesh, tiles);
  EXPECT_LE(tiles.colour_count(), 2);
  EXPECT_FALSE(tiles.serial().empty());
}

TEST(ElementTilesTest, DefaultTileSizeGrowsWithTheMeshUpToItsCap) {
  EXPECT_EQ(ElementTiles::DefaultTileElements(0), 128);
  EXPECT_EQ(ElementTiles::DefaultTileElements(10'752), 128);  // 168 -> 128
  EXPECT_EQ(ElementTiles::DefaultTileElements(23'636), 256);  // 369 -> 256
  EXPECT_EQ(ElementTiles::DefaultTileElements(40'000), 512);  // 625 -> 512
  EXPECT_EQ(ElementTiles::DefaultTileElements(112'393), 1024);
  EXPECT_EQ(ElementTiles::DefaultTileElements(10'000'000), 1024);
}

}  // namespace
}  // namespace getme
