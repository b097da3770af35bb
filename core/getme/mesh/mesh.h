#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "getme/elements/element_type.h"
#include "getme/mesh/mesh_error_names.h"

namespace getme {

using NodeId = std::int32_t;
using ElementId = std::int32_t;

// Elements of one type, stored contiguously so hot loops run one templated kernel per type.
struct ElementBlock {
  std::vector<NodeId> nodes;        // NodeCount(type) ids per element, paper node order (Fig. 1)
  std::vector<ElementId> elements;  // global element id of each block entry
};

// Compressed sparse rows: the items of row r are items[offsets[r] .. offsets[r+1]).
struct CompressedRows {
  std::vector<std::int64_t> offsets;
  std::vector<std::int32_t> items;

  std::span<const std::int32_t> Row(std::int64_t row) const {
    return {items.data() + offsets[row], items.data() + offsets[row + 1]};
  }
  std::int64_t RowCount() const { return static_cast<std::int64_t>(offsets.size()) - 1; }
};

// Builds CSR rows from (row, item) pairs: for_each_pair(emit) calls emit(row, item) for every
// pair, the same pairs in the same order each time (it is called twice: to count, then to fill).
// Items stay in emission order within a row.
template <typename ForEachPair>
CompressedRows BuildRows(std::int64_t rows, ForEachPair&& for_each_pair) {
  CompressedRows csr;
  csr.offsets.assign(rows + 1, 0);
  for_each_pair([&](std::int64_t row, std::int32_t) { ++csr.offsets[row + 1]; });
  for (std::int64_t row = 0; row < rows; ++row) csr.offsets[row + 1] += csr.offsets[row];
  csr.items.resize(csr.offsets.back());
  std::vector<std::int64_t> cursor(csr.offsets.begin(), csr.offsets.end() - 1);
  for_each_pair([&](std::int64_t row, std::int32_t item) { csr.items[cursor[row]++] = item; });
  return csr;
}

// A mixed volume mesh: structure-of-arrays coordinates, connectivity per element type in the
// paper's node order, free/fixed flags, and the topology the smoothers need (node→element
// adjacency, boundary nodes, element neighbours). Global element ids follow insertion order, so
// they match the element numbering of the file or message the mesh came from.
// Topology is immutable after Build(); only coordinates change during smoothing.
class Mesh {
 public:
  std::int64_t node_count() const { return static_cast<std::int64_t>(x_.size()); }
  std::int64_t element_count() const { return static_cast<std::int64_t>(element_type_.size()); }
  std::int64_t element_count(ElementType type) const {
    return static_cast<std::int64_t>(blocks_[TypeIndex(type)].elements.size());
  }

  std::span<double> x() { return x_; }
  std::span<double> y() { return y_; }
  std::span<double> z() { return z_; }
  std::span<const double> x() const { return x_; }
  std::span<const double> y() const { return y_; }
  std::span<const double> z() const { return z_; }

  ElementType type(ElementId element) const { return element_type_[element]; }
  // Position of the element inside its type block.
  std::int32_t block_index(ElementId element) const { return block_index_[element]; }
  const ElementBlock& block(ElementType type) const { return blocks_[TypeIndex(type)]; }
  // In the header: the polish and the sequential substep call it for every element around every
  // node they step, and out of line the call was 4 % of a default run on cub_wedge_like.vtk.
  std::span<const NodeId> element_nodes(ElementId element) const {
    const ElementType element_type = element_type_[element];
    const int n = NodeCount(element_type);
    const auto& nodes = blocks_[TypeIndex(element_type)].nodes;
    return {nodes.data() + static_cast<std::int64_t>(block_index_[element]) * n,
            static_cast<std::size_t>(n)};
  }

  // Caller-fixed nodes (e.g. a file's `fixed` point data). Boundary nodes are separate; which
  // nodes a smoother moves is decided by its parameters (fix_boundary).
  bool is_fixed(NodeId node) const { return fixed_[node] != 0; }
  std::span<const std::uint8_t> fixed_flags() const { return fixed_; }
  void set_fixed(NodeId node, bool fixed) { fixed_[node] = fixed ? 1 : 0; }
  // Nodes of faces that belong to exactly one element.
  bool is_boundary(NodeId node) const { return boundary_[node] != 0; }
  std::span<const std::uint8_t> boundary_flags() const { return boundary_; }
  std::int64_t boundary_face_count() const { return boundary_face_count_; }

  // The canonical element order: all tetrahedra, then hexahedra, pyramids and prisms, each in
  // insertion order. Every order-dependent step of the engine (sums, tie-breaks, visiting order)
  // follows it rather than the ids, so a mesh gives bit-identical results however its elements of
  // different types are interleaved (a file's order or the service's type-grouped wire order).
  std::span<const ElementId> canonical_order() const { return canonical_order_; }
  // Position of the element in canonical_order(). One load, or none where the ids are already in
  // canonical order (every single-type mesh): the sequential substep asks for it for every element
  // around every pick, and as type offset + block index it cost two cache misses each.
  std::int32_t canonical_rank(ElementId element) const {
    return canonical_rank_.empty() ? element : canonical_rank_[element];
  }
  // Asks for the cache lines element_nodes(element) and canonical_rank(element) read, so that
  // lookups of elements scattered over a large mesh wait for memory side by side rather than one
  // after another (the sequential substep's picks).
  void PrefetchElement(ElementId element) const {
    __builtin_prefetch(&element_type_[element]);
    __builtin_prefetch(&block_index_[element]);
    PrefetchCanonicalRank(element);
  }
  // Asks for the cache line canonical_rank(element) reads.
  void PrefetchCanonicalRank(ElementId element) const {
    if (!canonical_rank_.empty()) __builtin_prefetch(&canonical_rank_[element]);
  }
  // Asks for the cache line node_elements(node) reads first, the row's bounds; where its items
  // lie is known only once that has arrived.
  void PrefetchNodeElements(NodeId node) const {
    __builtin_prefetch(&node_elements_.offsets[node]);
  }
  // Whether canonical_order() is 0, 1, 2, ...: then an element's id is its rank.
  bool ids_in_canonical_order() const { return canonical_rank_.empty(); }
  // Elements containing the node, in canonical order.
  std::span<const ElementId> node_elements(NodeId node) const { return node_elements_.Row(node); }
  // Elements sharing at least one node with the element (excluding itself), canonical order.
  // The table is built on the first call, not by Build(): on a tetrahedral mesh it holds about
  // 80 entries per element, more memory than everything else, so the engine collects neighbours
  // per element instead (ElementNeighbourFinder). Thread-safe; copies of a mesh share the table.
  std::span<const ElementId> element_neighbours(ElementId element) const;
  // Corners (an element's node slots) are numbered block by block: corner c of block t is t's
  // corner_offset + block_index·NodeCount + k. No node→corner table is kept: the simultaneous
  // substep adds into node sums instead of gathering corners (parallel/element_tiles.h).
  std::int64_t corner_offset(ElementType type) const { return corner_offset_[TypeIndex(type)]; }
  std::int64_t corner_count() const { return corner_offset_[kElementTypeCount]; }

 private:
  friend class MeshBuilder;
  std::vector<double> x_, y_, z_;
  std::vector<std::uint8_t> fixed_, boundary_;
  std::vector<ElementType> element_type_;
  std::vector<std::int32_t> block_index_;
  std::array<ElementBlock, kElementTypeCount> blocks_;
  std::array<std::int64_t, kElementTypeCount + 1> corner_offset_{};
  std::vector<ElementId> canonical_order_;
  std::vector<std::int32_t> canonical_rank_;  // inverse of canonical_order_; empty if identity
  CompressedRows node_elements_;
  struct LazyRows {
    std::once_flag built;
    CompressedRows rows;
  };
  std::shared_ptr<LazyRows> element_neighbours_ = std::make_shared<LazyRows>();
  std::int64_t boundary_face_count_ = 0;
};

// Collects nodes and elements, then validates them and builds the topology. Every check of a
// mesh's content happens here, once; errors name the element or node at fault in the words of
// the caller's MeshErrorNames (by default, by insertion index).
class MeshBuilder {
 public:
  // How Build numbers the elements: by default in the order they were added (a file's cell
  // order); with NumberElementsByType, type by type in `order`, each type in the order added (the
  // wire's numbering: all tetrahedra, then hexahedra, wedges, pyramids; mesh.proto).
  void NumberElementsByType(std::array<ElementType, kElementTypeCount> order);
  // `names` must outlive Build; null restores the defaults.
  void SetErrorNames(const MeshErrorNames* names);

  void Reserve(std::int64_t nodes, std::int64_t elements);
  NodeId AddNode(double x, double y, double z);
  void SetFixed(std::int64_t node, bool fixed = true);
  // nodes: NodeCount(type) node ids in the paper's order (Fig. 1; docs/node-orders.md).
  void AddElement(ElementType type, std::span<const std::int64_t> nodes);

  std::int64_t node_count() const { return static_cast<std::int64_t>(mesh_.x_.size()); }
  std::int64_t element_count() const { return mesh_.element_count(); }

  // Fails with InvalidArgument on an empty mesh, a node id out of range or repeated within an
  // element, an element with the wrong number of nodes, a non-finite or out-of-range coordinate,
  // more than 2^31-1 nodes or elements, an element listed twice, or a face shared by more than
  // two elements (mesh_conformity.h).
  absl::StatusOr<Mesh> Build() &&;

 private:
  Mesh mesh_;
  const MeshErrorNames* names_ = nullptr;
  std::optional<std::array<ElementType, kElementTypeCount>> type_order_;
  std::vector<std::pair<std::int64_t, bool>> pending_fixed_;
  // Node ids per type, NodeCount(type) per element, unchecked until Build.
  std::array<std::vector<std::int64_t>, kElementTypeCount> staged_nodes_;
  // The first element added with the wrong number of nodes (reported by Build).
  std::optional<absl::Status> wrong_node_count_;
};

}  // namespace getme
