#include "getme_wire/mesh_chunker.h"

#include <algorithm>
#include <array>

#include "getme/elements/node_orders.h"
#include "getme_wire/mesh_fields.h"

namespace getme::wire {

// The repeated fields of getme.v1.Mesh in declaration order, with how many values make one item
// (node, element, id) and an upper bound of the encoded bytes per value: varints of uint32 take
// at most 5 bytes, of uint64 at most 10; doubles are packed 8 bytes.
enum class MeshField {
  kCoordinates,
  kTetrahedra,
  kHexahedra,
  kWedges,
  kPyramids,
  kFixedNodes,
  kNodeIds,
  kElementIds,
  kGroupTriangles,
  kGroupQuads,
  kTriangleGroups,
  kQuadGroups
};
namespace {

struct FieldLayout {
  MeshField field;
  int values_per_item;
  std::size_t bytes_per_value;
  bool per_node;  // items are nodes (ChunkLimits.max_nodes applies)
};
constexpr std::array<FieldLayout, 12> kFields = {{
    {MeshField::kCoordinates, 3, 8, true},
    {MeshField::kTetrahedra, 4, 5, false},
    {MeshField::kHexahedra, 8, 5, false},
    {MeshField::kWedges, 6, 5, false},
    {MeshField::kPyramids, 5, 5, false},
    {MeshField::kFixedNodes, 1, 5, false},
    {MeshField::kNodeIds, 1, 10, true},
    {MeshField::kElementIds, 1, 10, false},
    {MeshField::kGroupTriangles, 3, 5, false},
    {MeshField::kGroupQuads, 4, 5, false},
    {MeshField::kTriangleGroups, 1, 5, false},
    {MeshField::kQuadGroups, 1, 5, false},
}};

int GroupOf(MeshField field) { return static_cast<int>(field) - 1; }

template <typename T>
void AppendRange(const google::protobuf::RepeatedField<T>& source, std::int64_t begin,
                 std::int64_t end, google::protobuf::RepeatedField<T>& target) {
  target.Add(source.begin() + begin, source.begin() + end);
}

template <typename T>
void AppendRange(const std::vector<T>& source, std::int64_t begin, std::int64_t end,
                 google::protobuf::RepeatedField<T>& target) {
  target.Add(source.begin() + begin, source.begin() + end);
}

}  // namespace

// Where a chunker reads a mesh from: how many values each field has, and a range of them.
class WireMeshSource {
 public:
  virtual ~WireMeshSource() = default;
  virtual std::int64_t Size(MeshField field) const = 0;
  // [begin, end) holds whole items.
  virtual void Copy(MeshField field, std::int64_t begin, std::int64_t end, v1::Mesh& out) const = 0;
};

namespace {

class ProtoMeshSource final : public WireMeshSource {
 public:
  explicit ProtoMeshSource(const v1::Mesh& mesh) : mesh_(mesh) {}

  std::int64_t Size(MeshField field) const override {
    switch (field) {
      case MeshField::kCoordinates:
        return mesh_.coordinates_size();
      case MeshField::kFixedNodes:
        return mesh_.fixed_nodes_size();
      case MeshField::kNodeIds:
        return mesh_.node_ids_size();
      case MeshField::kElementIds:
        return mesh_.element_ids_size();
      case MeshField::kGroupTriangles:
        return mesh_.group_triangles_size();
      case MeshField::kGroupQuads:
        return mesh_.group_quads_size();
      case MeshField::kTriangleGroups:
        return mesh_.triangle_groups_size();
      case MeshField::kQuadGroups:
        return mesh_.quad_groups_size();
      default:
        return Connectivity(mesh_, GroupOf(field)).size();
    }
  }

  void Copy(MeshField field, std::int64_t begin, std::int64_t end, v1::Mesh& out) const override {
    switch (field) {
      case MeshField::kCoordinates:
        return AppendRange(mesh_.coordinates(), begin, end, *out.mutable_coordinates());
      case MeshField::kFixedNodes:
        return AppendRange(mesh_.fixed_nodes(), begin, end, *out.mutable_fixed_nodes());
      case MeshField::kNodeIds:
        return AppendRange(mesh_.node_ids(), begin, end, *out.mutable_node_ids());
      case MeshField::kElementIds:
        return AppendRange(mesh_.element_ids(), begin, end, *out.mutable_element_ids());
      case MeshField::kGroupTriangles:
        return AppendRange(mesh_.group_triangles(), begin, end, *out.mutable_group_triangles());
      case MeshField::kGroupQuads:
        return AppendRange(mesh_.group_quads(), begin, end, *out.mutable_group_quads());
      case MeshField::kTriangleGroups:
        return AppendRange(mesh_.triangle_groups(), begin, end, *out.mutable_triangle_groups());
      case MeshField::kQuadGroups:
        return AppendRange(mesh_.quad_groups(), begin, end, *out.mutable_quad_groups());
      default:
        return AppendRange(Connectivity(mesh_, GroupOf(field)), begin, end,
                           *MutableConnectivity(out, GroupOf(field)));
    }
  }

 private:
  const v1::Mesh& mesh_;
};

// An engine mesh read in the wire's form: coordinates interleaved from the structure of arrays,
// each type's block as its wire field with prisms mirrored back to VTK order.
class EngineMeshSource final : public WireMeshSource {
 public:
  EngineMeshSource(const Mesh& mesh, const WireMeshIds& ids, bool coordinates_only)
      : mesh_(mesh), ids_(ids), coordinates_only_(coordinates_only) {}

  std::int64_t Size(MeshField field) const override {
    switch (field) {
      case MeshField::kCoordinates:
        return 3 * mesh_.node_count();
      case MeshField::kNodeIds:
        return static_cast<std::int64_t>(ids_.node_ids.size());
      case MeshField::kFixedNodes:
        return coordinates_only_ ? 0 : static_cast<std::int64_t>(ids_.fixed_nodes.size());
      case MeshField::kElementIds:
        return coordinates_only_ ? 0 : static_cast<std::int64_t>(ids_.element_ids.size());
      case MeshField::kGroupTriangles:
      case MeshField::kGroupQuads:
      case MeshField::kTriangleGroups:
      case MeshField::kQuadGroups:
        return 0;  // a result does not repeat the caller's surface groups
      default:
        if (coordinates_only_) return 0;
        return static_cast<std::int64_t>(
            mesh_.block(kWireElementGroups[GroupOf(field)].type).nodes.size());
    }
  }

  void Copy(MeshField field, std::int64_t begin, std::int64_t end, v1::Mesh& out) const override {
    switch (field) {
      case MeshField::kCoordinates: {
        google::protobuf::RepeatedField<double>& target = *out.mutable_coordinates();
        target.Reserve(target.size() + static_cast<int>(end - begin));
        for (std::int64_t node = begin / 3; node < end / 3; ++node) {
          target.Add(mesh_.x()[node]);
          target.Add(mesh_.y()[node]);
          target.Add(mesh_.z()[node]);
        }
        return;
      }
      case MeshField::kNodeIds:
        return AppendRange(ids_.node_ids, begin, end, *out.mutable_node_ids());
      case MeshField::kFixedNodes:
        return AppendRange(ids_.fixed_nodes, begin, end, *out.mutable_fixed_nodes());
      case MeshField::kElementIds:
        return AppendRange(ids_.element_ids, begin, end, *out.mutable_element_ids());
      case MeshField::kGroupTriangles:
      case MeshField::kGroupQuads:
      case MeshField::kTriangleGroups:
      case MeshField::kQuadGroups:
        return;
      default: {
        const ElementType type = kWireElementGroups[GroupOf(field)].type;
        const std::vector<NodeId>& nodes = mesh_.block(type).nodes;
        Indices& target = *MutableConnectivity(out, GroupOf(field));
        target.Reserve(target.size() + static_cast<int>(end - begin));
        const int count = NodeCount(type);
        for (std::int64_t start = begin; start < end; start += count) {
          for (int k = 0; k < count; ++k) {
            target.Add(static_cast<std::uint32_t>(nodes[start + VtkToPaperPosition(type, k)]));
          }
        }
        return;
      }
    }
  }

 private:
  const Mesh& mesh_;
  const WireMeshIds& ids_;
  const bool coordinates_only_;
};

}  // namespace

ChunkLimits ResultChunkLimits(std::uint32_t nodes_per_chunk) {
  constexpr std::int64_t kMaxNodesPerChunk = 100'000;
  constexpr std::size_t kBytesPerNode = 3 * 8 + 10;  // coordinates and an id
  if (nodes_per_chunk == 0) return ChunkLimits{};
  const std::int64_t nodes = std::min<std::int64_t>(nodes_per_chunk, kMaxNodesPerChunk);
  return ChunkLimits{.bytes = static_cast<std::size_t>(nodes) * kBytesPerNode, .max_nodes = nodes};
}

MeshChunker::MeshChunker(const v1::Mesh& mesh, std::size_t chunk_bytes)
    : source_(std::make_unique<ProtoMeshSource>(mesh)),
      limits_{.bytes = std::max<std::size_t>(chunk_bytes, 64)} {}

MeshChunker::MeshChunker(const Mesh& mesh, const WireMeshIds& ids, bool coordinates_only,
                         ChunkLimits limits)
    : source_(std::make_unique<EngineMeshSource>(mesh, ids, coordinates_only)),
      limits_{.bytes = std::max<std::size_t>(limits.bytes, 64), .max_nodes = limits.max_nodes} {}

MeshChunker::~MeshChunker() = default;

bool MeshChunker::Next(v1::MeshChunk& chunk) {
  chunk.Clear();
  v1::Mesh& part = *chunk.mutable_mesh();
  std::size_t budget = limits_.bytes;
  bool added = false;
  while (field_ < static_cast<int>(kFields.size())) {
    const FieldLayout& layout = kFields[field_];
    const std::int64_t size = source_->Size(layout.field);
    if (position_ >= size) {
      ++field_;
      position_ = 0;
      continue;
    }
    const std::size_t item_bytes = layout.values_per_item * layout.bytes_per_value;
    std::int64_t items = static_cast<std::int64_t>(budget / item_bytes);
    if (layout.per_node && limits_.max_nodes > 0) items = std::min(items, limits_.max_nodes);
    // At least one item per chunk, however small the budget, so the loop always advances.
    if (items == 0 && !added) items = 1;
    if (items == 0) break;
    const std::int64_t end = std::min(size, position_ + items * layout.values_per_item);
    source_->Copy(layout.field, position_, end, part);
    budget -= std::min(budget, static_cast<std::size_t>(end - position_) * layout.bytes_per_value);
    position_ = end;
    added = true;
    // A node cap ends the chunk with its nodes, so each chunk carries at most that many.
    if (layout.per_node && limits_.max_nodes > 0 && position_ < size) break;
  }
  if (!added && handed_out_any_) return false;
  handed_out_any_ = true;
  return true;
}

}  // namespace getme::wire
