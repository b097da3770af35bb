#pragma once

#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

#include "absl/status/statusor.h"
#include "getme/elements/element_type.h"
#include "getme/elements/vec3.h"
#include "getme/mesh/mesh.h"

namespace getme::meshgen {

// A mesh under construction whose nodes may still move: generators add nodes and elements (paper
// node order, docs/node-orders.md), distort coordinates while checking element validity, and
// finally turn it into an immutable getme::Mesh through MeshBuilder.
class MeshDraft {
 public:
  // Sizes the storage up front: large generators would otherwise hold up to twice their arrays
  // while a vector grows.
  void Reserve(std::int64_t nodes, std::int64_t elements, std::int64_t element_nodes);
  NodeId AddNode(const Vec3& position);
  ElementId AddElement(ElementType type, std::span<const NodeId> nodes);
  ElementId AddElement(ElementType type, std::initializer_list<NodeId> nodes) {
    return AddElement(type, std::span<const NodeId>(nodes.begin(), nodes.size()));
  }

  std::int64_t node_count() const { return static_cast<std::int64_t>(x_.size()); }
  std::int64_t element_count() const { return static_cast<std::int64_t>(types_.size()); }
  std::int64_t element_count(ElementType type) const;

  Vec3 node(NodeId id) const { return Vec3(x_[id], y_[id], z_[id]); }
  void set_node(NodeId id, const Vec3& position);
  ElementType type(ElementId element) const { return types_[element]; }
  std::span<const NodeId> element_nodes(ElementId element) const {
    return {nodes_.data() + offsets_[element], nodes_.data() + offsets_[element + 1]};
  }

  // Def. 2: every node tetrahedron of the element has a positive determinant.
  bool IsElementValid(ElementId element) const;

  // Elements containing each node (rows indexed by node id, ascending element ids).
  CompressedRows NodeElements() const;

  // Hands the nodes and elements to MeshBuilder, freeing each array once it is copied so a
  // 10M-element draft and the builder's copy are not held together; no node is marked fixed.
  absl::StatusOr<Mesh> Build() &&;

 private:
  std::vector<double> x_, y_, z_;
  std::vector<ElementType> types_;
  std::vector<NodeId> nodes_;
  std::vector<std::int64_t> offsets_{0};
};

}  // namespace getme::meshgen
