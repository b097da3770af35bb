#include "getme/parallel/element_tiles.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "getme/elements/element_tables.h"

namespace getme {
namespace {

// A colouring this good is what a regular 3D brick decomposition needs (2 × 2 × 2 parities): the
// block order is kept without trying the Morton order.
constexpr int kGoodColourCount = 8;

// Bits per axis of the Morton key: a 65,536³ grid over the mesh's bounding cube is far finer than
// any tile, and three of them fit a 64-bit key.
constexpr int kMortonBits = 16;

// The low 16 bits of v spread to every third position (bit i to bit 3i).
std::uint64_t SpreadBits(std::uint64_t v) {
  v &= 0xffff;
  v = (v | (v << 16)) & 0x0000ff0000ffULL;
  v = (v | (v << 8)) & 0x00f00f00f00fULL;
  v = (v | (v << 4)) & 0x0c30c30c30c3ULL;
  v = (v | (v << 2)) & 0x249249249249ULL;
  return v;
}

struct BoundingCube {
  double min[3] = {0.0, 0.0, 0.0};
  double cells_per_unit = 0.0;  // grid cells per unit length; 0 for a mesh without extent
};

BoundingCube CubeAround(const Mesh& mesh) {
  BoundingCube cube;
  if (mesh.node_count() == 0) return cube;
  const std::span<const double> axes[3] = {mesh.x(), mesh.y(), mesh.z()};
  double extent = 0.0;
  for (int a = 0; a < 3; ++a) {
    const auto [low, high] = std::minmax_element(axes[a].begin(), axes[a].end());
    cube.min[a] = *low;
    extent = std::max(extent, *high - *low);
  }
  if (extent > 0.0 && std::isfinite(extent)) {
    cube.cells_per_unit = static_cast<double>(1 << kMortonBits) / extent;
  }
  return cube;
}

// Sorts (key, entry) pairs given in ascending entry order by key, ties in entry order: what
// std::sort of the pairs gives. A stable least-significant-digit radix sort, 12 bits a pass and
// only as many passes as the largest key has bits (4 for the 48-bit Morton codes): std::sort was
// about two thirds of building the tiles on cub_wedge_like.vtk (112k tetrahedra; 2026-11-29).
void SortKeyedEntries(std::vector<std::pair<std::uint64_t, std::int32_t>>& keyed) {
  constexpr int kDigitBits = 12;
  constexpr std::size_t kDigits = std::size_t{1} << kDigitBits;
  std::uint64_t largest = 0;
  for (const auto& entry : keyed) largest = std::max(largest, entry.first);
  std::vector<std::pair<std::uint64_t, std::int32_t>> scratch(keyed.size());
  std::vector<std::size_t> start(kDigits + 1);
  for (int shift = 0; shift < 64 && (largest >> shift) != 0; shift += kDigitBits) {
    std::fill(start.begin(), start.end(), 0);
    for (const auto& entry : keyed) ++start[((entry.first >> shift) & (kDigits - 1)) + 1];
    for (std::size_t digit = 0; digit < kDigits; ++digit) start[digit + 1] += start[digit];
    for (const auto& entry : keyed)
      scratch[start[(entry.first >> shift) & (kDigits - 1)]++] = entry;
    keyed.swap(scratch);
  }
}

// The block's entries sorted by the Morton key of their centroids, ties by entry.
template <ElementType kType>
std::vector<std::int32_t> MortonOrder(const Mesh& mesh, const BoundingCube& cube) {
  constexpr int kNodes = ElementTable<kType>::kNodes;
  const ElementBlock& block = mesh.block(kType);
  const auto count = static_cast<std::int32_t>(block.elements.size());
  std::vector<std::pair<std::uint64_t, std::int32_t>> keyed(count);
  const std::span<const double> axes[3] = {mesh.x(), mesh.y(), mesh.z()};
  constexpr double kLastCell = static_cast<double>((1 << kMortonBits) - 1);
  for (std::int32_t entry = 0; entry < count; ++entry) {
    const NodeId* nodes = block.nodes.data() + static_cast<std::int64_t>(entry) * kNodes;
    std::uint64_t key = 0;
    for (int a = 0; a < 3; ++a) {
      double sum = 0.0;
      for (int k = 0; k < kNodes; ++k) sum += axes[a][nodes[k]];
      const double cell = (sum / kNodes - cube.min[a]) * cube.cells_per_unit;
      const double clamped = !(cell > 0.0) ? 0.0 : std::min(cell, kLastCell);  // NaN too
      key |= SpreadBits(static_cast<std::uint64_t>(clamped)) << a;
    }
    keyed[entry] = {key, entry};
  }
  SortKeyedEntries(keyed);
  std::vector<std::int32_t> order(count);
  for (std::int32_t i = 0; i < count; ++i) order[i] = keyed[i].second;
  return order;
}

struct Colouring {
  std::vector<ElementTiles::Tile> tiles;  // grouped by colour, each colour in tile order
  std::vector<std::int64_t> colour_begin{0};
  std::vector<ElementTiles::Tile> serial;

  // Colours, with every serial tile counted as a colour of its own beyond the maximum: the
  // number of steps the tiles take one after another.
  std::int64_t Steps() const {
    return static_cast<std::int64_t>(colour_begin.size()) - 1 +
           static_cast<std::int64_t>(serial.size());
  }
};

// Cuts each type's visiting order into tiles and colours them greedily in tile order: each tile
// takes the lowest colour that no earlier tile sharing a node with it has.
Colouring ColourTiles(const Mesh& mesh, const std::array<const NodeId*, kElementTypeCount>& nodes,
                      std::int64_t tile_elements, int max_colours) {
  std::vector<ElementTiles::Tile> all;
  for (ElementType type : kAllElementTypes) {
    const std::int64_t count = mesh.element_count(type);
    for (std::int64_t begin = 0; begin < count; begin += tile_elements) {
      all.push_back({type, begin, std::min(count, begin + tile_elements)});
    }
  }
  // used[node] has bit c set once a tile of colour c touched the node.
  std::vector<std::uint64_t> used(mesh.node_count(), 0);
  const std::uint64_t allowed =
      max_colours == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << max_colours) - 1;
  constexpr int kSerial = -1;
  std::vector<int> tile_colour(all.size());
  int colours = 0;
  for (std::size_t t = 0; t < all.size(); ++t) {
    const ElementTiles::Tile& tile = all[t];
    const int per_element = NodeCount(tile.type);
    const NodeId* first = nodes[TypeIndex(tile.type)] + tile.begin * per_element;
    const NodeId* last = nodes[TypeIndex(tile.type)] + tile.end * per_element;
    std::uint64_t taken = 0;
    for (const NodeId* node = first; node != last; ++node) taken |= used[*node];
    const std::uint64_t free = ~taken & allowed;
    if (free == 0) {
      tile_colour[t] = kSerial;
      continue;
    }
    const int colour = std::countr_zero(free);
    tile_colour[t] = colour;
    colours = std::max(colours, colour + 1);
    for (const NodeId* node = first; node != last; ++node)
      used[*node] |= std::uint64_t{1} << colour;
  }
  Colouring colouring;
  colouring.colour_begin.assign(colours + 1, 0);
  for (int colour : tile_colour) {
    if (colour != kSerial) ++colouring.colour_begin[colour + 1];
  }
  for (int c = 0; c < colours; ++c) colouring.colour_begin[c + 1] += colouring.colour_begin[c];
  colouring.tiles.resize(colouring.colour_begin.back());
  std::vector<std::int64_t> next(colouring.colour_begin.begin(), colouring.colour_begin.end() - 1);
  for (std::size_t t = 0; t < all.size(); ++t) {
    if (tile_colour[t] == kSerial) {
      colouring.serial.push_back(all[t]);
    } else {
      colouring.tiles[next[tile_colour[t]]++] = all[t];
    }
  }
  return colouring;
}

}  // namespace

std::int64_t ElementTiles::DefaultTileElements(std::int64_t elements) {
  constexpr std::int64_t kSmallest = 128;
  constexpr std::int64_t kLargest = 1024;
  return std::clamp<std::int64_t>(
      static_cast<std::int64_t>(std::bit_floor(static_cast<std::uint64_t>(elements / 64) | 1)),
      kSmallest, kLargest);
}

ElementTiles::ElementTiles(const Mesh& mesh, std::int64_t tile_elements, int max_colours) {
  if (tile_elements <= 0) tile_elements = DefaultTileElements(mesh.element_count());
  tile_elements_ = tile_elements;
  max_colours = std::clamp(max_colours, 1, kMaxColours);
  for (ElementType type : kAllElementTypes) {
    nodes_[TypeIndex(type)] = mesh.block(type).nodes.data();
    elements_[TypeIndex(type)] = mesh.block(type).elements.data();
  }
  Colouring colouring = ColourTiles(mesh, nodes_, tile_elements, max_colours);
  if (colouring.Steps() > kGoodColourCount) {
    // The block order scatters neighbours: try the Morton order, with the blocks' node and
    // element ids copied into it so a tile's elements are contiguous in memory too.
    const BoundingCube cube = CubeAround(mesh);
    std::array<const NodeId*, kElementTypeCount> morton_nodes{};
    for (ElementType type : kAllElementTypes) {
      const int t = TypeIndex(type);
      const ElementBlock& block = mesh.block(type);
      const int per_element = NodeCount(type);
      const std::vector<std::int32_t> order = DispatchElementType(
          type, [&]<ElementType kType>() { return MortonOrder<kType>(mesh, cube); });
      morton_nodes_[t].resize(block.nodes.size());
      morton_elements_[t].resize(block.elements.size());
      for (std::size_t i = 0; i < order.size(); ++i) {
        std::copy_n(block.nodes.data() + static_cast<std::int64_t>(order[i]) * per_element,
                    per_element, morton_nodes_[t].data() + i * per_element);
        morton_elements_[t][i] = block.elements[order[i]];
      }
      morton_nodes[t] = morton_nodes_[t].data();
    }
    Colouring morton = ColourTiles(mesh, morton_nodes, tile_elements, max_colours);
    if (morton.Steps() < colouring.Steps()) {
      colouring = std::move(morton);
      morton_chosen_ = true;
      for (int t = 0; t < kElementTypeCount; ++t) {
        nodes_[t] = morton_nodes_[t].data();
        elements_[t] = morton_elements_[t].data();
      }
    } else {
      for (int t = 0; t < kElementTypeCount; ++t) {
        std::vector<NodeId>().swap(morton_nodes_[t]);  // the copies' memory back
        std::vector<ElementId>().swap(morton_elements_[t]);
      }
    }
  }
  tiles_ = std::move(colouring.tiles);
  colour_begin_ = std::move(colouring.colour_begin);
  serial_ = std::move(colouring.serial);
}

}  // namespace getme
