// ElementTiles (core/getme/parallel/element_tiles.h), checked by brute force: every element is in
// exactly one tile, the visiting order's node and element ids are the block's, no two tiles of a
// colour share a node, the build is deterministic, and a mesh numbered without locality gets the
// Morton order (with far fewer colours than its own order would need).

#include "getme/parallel/element_tiles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <span>
#include <utility>
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

// The Morton order, computed here by brute force: each entry's key interleaves the bits of its
// centroid's cell on a 65,536³ grid over the mesh's bounding cube (x in bit 0, y in bit 1, z in
// bit 2 of every triple), and std::stable_sort by key keeps ties in block order.
std::uint64_t MortonKeyOf(const Mesh& mesh, const NodeId* nodes, int count) {
  const std::span<const double> axes[3] = {mesh.x(), mesh.y(), mesh.z()};
  double low[3];
  double extent = 0.0;
  for (int a = 0; a < 3; ++a) {
    const auto [min, max] = std::minmax_element(axes[a].begin(), axes[a].end());
    low[a] = *min;
    extent = std::max(extent, *max - *min);
  }
  std::uint64_t key = 0;
  for (int a = 0; a < 3; ++a) {
    double sum = 0.0;
    for (int k = 0; k < count; ++k) sum += axes[a][nodes[k]];
    const double cell = (sum / count - low[a]) * (65536.0 / extent);
    const auto index = static_cast<std::uint64_t>(std::clamp(cell, 0.0, 65535.0));
    for (int bit = 0; bit < 16; ++bit) key |= ((index >> bit) & 1) << (3 * bit + a);
  }
  return key;
}

TEST(ElementTilesTest, TheMortonOrderSortsCentroidsTiesInBlockOrder) {
  const absl::StatusOr<Mesh> block = meshgen::HybridBlock(12, 12, 10, 0.3, 4);
  ASSERT_TRUE(block.ok()) << block.status();
  const Mesh mesh = mesh_test::Shuffled(*block, 9);
  const ElementTiles tiles(mesh);
  ASSERT_TRUE(tiles.morton_order());
  for (ElementType type : kAllElementTypes) {
    const ElementBlock& entries = mesh.block(type);
    const int per_element = NodeCount(type);
    std::vector<std::pair<std::uint64_t, std::size_t>> keyed;
    for (std::size_t i = 0; i < entries.elements.size(); ++i) {
      keyed.emplace_back(MortonKeyOf(mesh, entries.nodes.data() + i * per_element, per_element), i);
    }
    std::stable_sort(keyed.begin(), keyed.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<ElementId> expected;
    for (const auto& [key, entry] : keyed) expected.push_back(entries.elements[entry]);
    EXPECT_TRUE(std::equal(expected.begin(), expected.end(), tiles.elements(type)))
        << TypeName(type);
  }
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
