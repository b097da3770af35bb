#include "getme/meshgen/mesh_draft.h"

#include <algorithm>

#include "getme/elements/element_quality.h"
#include "getme/elements/element_tables.h"

namespace getme::meshgen {

void MeshDraft::Reserve(std::int64_t nodes, std::int64_t elements, std::int64_t element_nodes) {
  x_.reserve(nodes);
  y_.reserve(nodes);
  z_.reserve(nodes);
  types_.reserve(elements);
  offsets_.reserve(elements + 1);
  nodes_.reserve(element_nodes);
}

NodeId MeshDraft::AddNode(const Vec3& position) {
  x_.push_back(position.x());
  y_.push_back(position.y());
  z_.push_back(position.z());
  return static_cast<NodeId>(x_.size() - 1);
}

ElementId MeshDraft::AddElement(ElementType type, std::span<const NodeId> nodes) {
  types_.push_back(type);
  nodes_.insert(nodes_.end(), nodes.begin(), nodes.end());
  offsets_.push_back(static_cast<std::int64_t>(nodes_.size()));
  return static_cast<ElementId>(types_.size() - 1);
}

std::int64_t MeshDraft::element_count(ElementType type) const {
  return std::count(types_.begin(), types_.end(), type);
}

void MeshDraft::set_node(NodeId id, const Vec3& position) {
  x_[id] = position.x();
  y_[id] = position.y();
  z_[id] = position.z();
}

bool MeshDraft::IsElementValid(ElementId element) const {
  const NodeId* ids = nodes_.data() + offsets_[element];
  return DispatchElementType(types_[element], [&]<ElementType kType>() {
    return IsValid<kType>(GatherNodes<kType>(x_, y_, z_, ids));
  });
}

CompressedRows MeshDraft::NodeElements() const {
  CompressedRows rows;
  rows.offsets.assign(x_.size() + 1, 0);
  for (const NodeId node : nodes_) ++rows.offsets[node + 1];
  for (std::size_t i = 1; i < rows.offsets.size(); ++i) rows.offsets[i] += rows.offsets[i - 1];
  rows.items.resize(nodes_.size());
  std::vector<std::int64_t> cursor(rows.offsets.begin(), rows.offsets.end() - 1);
  // Elements are visited in ascending order, so every row comes out sorted.
  for (ElementId element = 0; element < static_cast<ElementId>(types_.size()); ++element) {
    for (const NodeId node : element_nodes(element)) rows.items[cursor[node]++] = element;
  }
  return rows;
}

absl::StatusOr<Mesh> MeshDraft::Build() && {
  MeshBuilder builder;
  builder.Reserve(node_count(), element_count());
  for (std::size_t i = 0; i < x_.size(); ++i) builder.AddNode(x_[i], y_[i], z_[i]);
  std::vector<double>().swap(x_);
  std::vector<double>().swap(y_);
  std::vector<double>().swap(z_);
  std::vector<std::int64_t> element(kMaxElementNodes);
  for (ElementId e = 0; e < static_cast<ElementId>(types_.size()); ++e) {
    const std::span<const NodeId> ids = element_nodes(e);
    element.assign(ids.begin(), ids.end());
    builder.AddElement(types_[e], element);
  }
  std::vector<ElementType>().swap(types_);
  std::vector<NodeId>().swap(nodes_);
  std::vector<std::int64_t>{0}.swap(offsets_);
  return std::move(builder).Build();
}

}  // namespace getme::meshgen
