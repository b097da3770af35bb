#include "remote/mesh_chunks.h"

#include <algorithm>
#include <array>
#include <functional>

#include "absl/strings/str_cat.h"

namespace getme::remote {
namespace {

using google::protobuf::RepeatedField;

// One repeated field of Mesh: how many values make one item (node, element), an upper bound of
// the encoded bytes per value, and how to copy a range of it into a chunk.
struct FieldSpec {
  int values_per_item;
  std::size_t bytes_per_value;
  std::function<int(const v1::Mesh&)> size;
  std::function<void(const v1::Mesh&, std::int64_t begin, std::int64_t end, v1::Mesh&)> copy;
};

template <typename T>
FieldSpec Field(int values_per_item, std::size_t bytes_per_value,
                const RepeatedField<T>& (v1::Mesh::*get)() const,
                RepeatedField<T>* (v1::Mesh::*mutable_get)()) {
  return FieldSpec{values_per_item, bytes_per_value,
                   [get](const v1::Mesh& mesh) { return (mesh.*get)().size(); },
                   [get, mutable_get](const v1::Mesh& mesh, std::int64_t begin, std::int64_t end,
                                      v1::Mesh& chunk) {
                     const RepeatedField<T>& source = (mesh.*get)();
                     (chunk.*mutable_get)()->Add(source.begin() + begin, source.begin() + end);
                   }};
}

// Varints of uint32 take at most 5 bytes, of uint64 at most 10; doubles are packed 8 bytes.
const std::array<FieldSpec, 8>& Fields() {
  static const std::array<FieldSpec, 8> fields = {
      Field<double>(3, 8, &v1::Mesh::coordinates, &v1::Mesh::mutable_coordinates),
      Field<std::uint32_t>(4, 5, &v1::Mesh::tetrahedra, &v1::Mesh::mutable_tetrahedra),
      Field<std::uint32_t>(8, 5, &v1::Mesh::hexahedra, &v1::Mesh::mutable_hexahedra),
      Field<std::uint32_t>(6, 5, &v1::Mesh::wedges, &v1::Mesh::mutable_wedges),
      Field<std::uint32_t>(5, 5, &v1::Mesh::pyramids, &v1::Mesh::mutable_pyramids),
      Field<std::uint32_t>(1, 5, &v1::Mesh::fixed_nodes, &v1::Mesh::mutable_fixed_nodes),
      Field<std::uint64_t>(1, 10, &v1::Mesh::node_ids, &v1::Mesh::mutable_node_ids),
      Field<std::uint64_t>(1, 10, &v1::Mesh::element_ids, &v1::Mesh::mutable_element_ids),
  };
  return fields;
}

}  // namespace

v1::MeshSize SizeOf(const v1::Mesh& mesh) {
  v1::MeshSize size;
  size.set_nodes(mesh.coordinates_size() / 3);
  size.set_tetrahedra(mesh.tetrahedra_size() / 4);
  size.set_hexahedra(mesh.hexahedra_size() / 8);
  size.set_wedges(mesh.wedges_size() / 6);
  size.set_pyramids(mesh.pyramids_size() / 5);
  return size;
}

MeshChunker::MeshChunker(const v1::Mesh& mesh, std::size_t chunk_bytes)
    : mesh_(mesh), chunk_bytes_(std::max<std::size_t>(chunk_bytes, 64)) {}

bool MeshChunker::Next(v1::MeshChunk& chunk) {
  chunk.Clear();
  v1::Mesh& part = *chunk.mutable_mesh();
  const auto& fields = Fields();
  std::size_t budget = chunk_bytes_;
  bool added = false;
  while (field_ < static_cast<int>(fields.size())) {
    const FieldSpec& spec = fields[field_];
    const std::int64_t size = spec.size(mesh_);
    if (position_ >= size) {
      ++field_;
      position_ = 0;
      continue;
    }
    const std::size_t item_bytes = spec.values_per_item * spec.bytes_per_value;
    std::int64_t items = static_cast<std::int64_t>(budget / item_bytes);
    // At least one item per chunk, however small the budget, so the loop always advances.
    if (items == 0 && !added) items = 1;
    if (items == 0) break;
    const std::int64_t end = std::min(size, position_ + items * spec.values_per_item);
    spec.copy(mesh_, position_, end, part);
    budget -= std::min(budget, static_cast<std::size_t>(end - position_) * spec.bytes_per_value);
    position_ = end;
    added = true;
  }
  if (!added && handed_out_any_) return false;
  handed_out_any_ = true;
  return true;
}

absl::Status MeshAssembler::CheckComplete(std::uint64_t nodes) const {
  if (static_cast<std::uint64_t>(mesh_.coordinates_size()) != 3 * nodes) {
    return absl::FailedPreconditionError(absl::StrCat(
        "the result stream ended with ", mesh_.coordinates_size(),
        " coordinates, but the result announced ", nodes, " nodes (", 3 * nodes, " coordinates)"));
  }
  return absl::OkStatus();
}

}  // namespace getme::remote
