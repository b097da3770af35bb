#pragma once

// Tiles of elements for a deterministic parallel scatter: every element belongs to one tile; the
// tiles of one colour share no node, so threads can add element contributions straight into
// per-node sums, tile by tile, with no per-corner buffer and no races. A node then receives its
// contributions in a fixed order — colour by colour, and within a tile in the tile's element
// order — whatever the thread count (docs/design.md, "Step 2's node sums").
//
// A tile is a run of one type block's elements in a visiting order: the block's own order when
// that already keeps neighbours together (generated and structured meshes), else the Morton
// (Z-curve) order of the element centroids, which does for any numbering (a mesher's file order
// can scatter neighbours across the whole file: on Mesquite's 112k-tetrahedron CUBIT mesh the
// file order's tiles need more than 64 colours, the Morton order's 12). Tiles are coloured
// greedily in tile order.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "getme/elements/element_type.h"
#include "getme/mesh/mesh.h"

namespace getme {

class ElementTiles {
 public:
  // A run of entries [begin, end) of one type's visiting order.
  struct Tile {
    ElementType type = ElementType::kTetrahedron;
    std::int64_t begin = 0;
    std::int64_t end = 0;
  };

  // Colours greedy colouring may use; tiles that find none free go to the serial group.
  static constexpr int kMaxColours = 64;

  // Elements per tile for a mesh of `elements`: the largest power of two up to elements / 64,
  // within [128, 1024]. Up to 1024, a tile's nodes stay in the core's cache while its elements
  // add into them; a mesh of 10k–100k elements still gets several tiles per colour for the
  // threads to share.
  static std::int64_t DefaultTileElements(std::int64_t elements);

  // Built from the mesh's connectivity and its coordinates at this time (for the Morton order);
  // the result depends on nothing else. tile_elements 0 means DefaultTileElements; max_colours
  // ∈ [1, kMaxColours].
  explicit ElementTiles(const Mesh& mesh, std::int64_t tile_elements = 0,
                        int max_colours = kMaxColours);

  std::int64_t tile_elements() const { return tile_elements_; }

  // The node ids (NodeCount(type) per entry) and element ids of `type`'s elements in visiting
  // order: the mesh's own block arrays, or reordered copies with the Morton order.
  const NodeId* nodes(ElementType type) const { return nodes_[TypeIndex(type)]; }
  const ElementId* elements(ElementType type) const { return elements_[TypeIndex(type)]; }
  // True when the tiles follow the Morton order (the block order's colouring was worse).
  bool morton_order() const { return morton_chosen_; }

  int colour_count() const { return static_cast<int>(colour_begin_.size()) - 1; }
  // The tiles of colour c, in tile order; no two of them share a node.
  std::span<const Tile> colour(int c) const {
    return {tiles_.data() + colour_begin_[c], tiles_.data() + colour_begin_[c + 1]};
  }
  // Tiles that found no free colour among max_colours, in tile order: run one after another,
  // after every colour.
  std::span<const Tile> serial() const { return serial_; }
  std::int64_t tile_count() const {
    return static_cast<std::int64_t>(tiles_.size() + serial_.size());
  }

 private:
  std::array<const NodeId*, kElementTypeCount> nodes_{};
  std::array<const ElementId*, kElementTypeCount> elements_{};
  std::array<std::vector<NodeId>, kElementTypeCount> morton_nodes_;
  std::array<std::vector<ElementId>, kElementTypeCount> morton_elements_;
  bool morton_chosen_ = false;
  std::int64_t tile_elements_ = 0;
  std::vector<Tile> tiles_;  // grouped by colour
  std::vector<std::int64_t> colour_begin_;
  std::vector<Tile> serial_;
};

}  // namespace getme
