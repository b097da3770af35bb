#include "getme/mesh/mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <vector>

#include "absl/status/status.h"
#include "absl/strings/str_cat.h"
#include "getme/elements/element_tables.h"
#include "getme/mesh/element_neighbours.h"
#include "getme/mesh/mesh_conformity.h"

namespace getme {
namespace {

constexpr std::int64_t kMaxIndex = std::numeric_limits<std::int32_t>::max();
// The mean ratio and the transformation raise lengths to the sixth power (products of squared
// edge norms); beyond about 1e±51 that under- or overflows and the quality silently reads 0 or 1.
// These bounds keep a margin of 1e10 on both sides (docs/reliability.md).
constexpr double kMaxCoordinate = 1e40;
constexpr double kMinElementExtent = 1e-40;

// A face as its sorted node ids (-1 padded for triangles), so both elements sharing it agree.
// Packed into two integers so faces sort and compare as plain integer pairs.
struct FaceKey {
  std::uint64_t low;   // first two sorted ids
  std::uint64_t high;  // last two (all ones for a triangle's missing fourth)
  auto operator<=>(const FaceKey&) const = default;
};

FaceKey PackFace(const std::array<NodeId, 4>& sorted) {
  auto bits = [](NodeId id) { return static_cast<std::uint64_t>(static_cast<std::uint32_t>(id)); };
  return {bits(sorted[0]) << 32 | bits(sorted[1]), bits(sorted[2]) << 32 | bits(sorted[3])};
}

template <ElementType kType>
void CollectFaces(const ElementBlock& block, std::vector<FaceKey>& faces) {
  using Table = ElementTable<kType>;
  const std::size_t count = block.elements.size();
  for (std::size_t i = 0; i < count; ++i) {
    const NodeId* ids = block.nodes.data() + i * Table::kNodes;
    for (const auto& face : Table::kFaces) {
      std::array<NodeId, 4> sorted = {-1, -1, -1, -1};
      for (int k = 0; k < face.size; ++k) sorted[k] = ids[face.nodes[k]];
      // Insertion sort of ≤ 4 ids (std::sort here trips a GCC 12 -Warray-bounds false positive).
      for (int k = 1; k < face.size; ++k) {
        for (int j = k; j > 0 && sorted[j - 1] > sorted[j]; --j)
          std::swap(sorted[j - 1], sorted[j]);
      }
      faces.push_back(PackFace(sorted));
    }
  }
}

// Sorts one bucket's faces: an insertion sort on the keys as 128-bit integers, std::sort for the
// rare large bucket.
void SortBucket(FaceKey* first, FaceKey* last) {
  constexpr std::ptrdiff_t kInsertionLimit = 32;
  if (last - first > kInsertionLimit) {
    std::sort(first, last);
    return;
  }
  __extension__ typedef unsigned __int128 WideKey;  // a GCC and Clang extension
  auto wide = [](const FaceKey& key) { return static_cast<WideKey>(key.low) << 64 | key.high; };
  for (FaceKey* next = first + 1; next < last; ++next) {
    const FaceKey key = *next;
    const WideKey value = wide(key);
    FaceKey* hole = next;
    while (hole > first && wide(hole[-1]) > value) {
      *hole = hole[-1];
      --hole;
    }
    *hole = key;
  }
}

std::uint64_t FaceHash(const FaceKey& face) {
  const std::uint64_t mixed = face.low * 0x9E3779B97F4A7C15ull ^ face.high * 0xC2B2AE3D27D4EB4Full;
  return mixed ^ (mixed >> 29);
}

// The faces with equal ones next to each other: bucketed by a hash of the whole key with a
// counting sort, about four faces a bucket, and each bucket sorted. Equal faces share a bucket,
// so a run of equal faces never crosses one. Bucketing by the smallest node id (sorted order)
// took 24 ms against 17 (medians of 15 runs, 2026-11-29, a slow hour of this VM) on
// cub_wedge_like.vtk's 450k faces: the buckets of its low-numbered nodes held up to ~70 faces.
// A second pass per part of the hash, to scatter in cache, was slower still (21 ms): with the
// faces in one array of a few MB the scatter's misses are not what costs.
std::vector<FaceKey> GroupEqualFaces(const std::vector<FaceKey>& faces) {
  int bits = 0;
  while (bits < 40 && (std::size_t{4} << bits) < faces.size()) ++bits;
  const auto bucket_of = [bits](const FaceKey& face) -> std::size_t {
    if (bits == 0) return 0;
    return static_cast<std::size_t>(FaceHash(face) >> (64 - bits));
  };
  const std::size_t buckets = std::size_t{1} << bits;
  std::vector<std::uint32_t> start(buckets + 1, 0);
  for (const FaceKey& face : faces) ++start[bucket_of(face) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<FaceKey> grouped(faces.size());
  std::vector<std::uint32_t> cursor(start.begin(), start.end() - 1);
  for (const FaceKey& face : faces) grouped[cursor[bucket_of(face)]++] = face;
  for (std::size_t bucket = 0; bucket < buckets; ++bucket) {
    SortBucket(grouped.data() + start[bucket], grouped.data() + start[bucket + 1]);
  }
  return grouped;
}

}  // namespace

std::span<const ElementId> Mesh::element_neighbours(ElementId element) const {
  std::call_once(element_neighbours_->built, [&] {
    CompressedRows& table = element_neighbours_->rows;
    ElementNeighbourFinder finder;
    table.offsets.assign(element_count() + 1, 0);
    for (ElementId e = 0; e < element_count(); ++e) {
      const std::span<const ElementId> row = finder.Find(*this, e);
      table.offsets[e + 1] = table.offsets[e] + static_cast<std::int64_t>(row.size());
    }
    table.items.reserve(table.offsets.back());
    for (ElementId e = 0; e < element_count(); ++e) {
      const std::span<const ElementId> row = finder.Find(*this, e);
      table.items.insert(table.items.end(), row.begin(), row.end());
    }
  });
  return element_neighbours_->rows.Row(element);
}

void MeshBuilder::NumberElementsByType(std::array<ElementType, kElementTypeCount> order) {
  type_order_ = order;
}

void MeshBuilder::SetErrorNames(const MeshErrorNames* names) { names_ = names; }

void MeshBuilder::Reserve(std::int64_t nodes, std::int64_t elements) {
  mesh_.x_.reserve(nodes);
  mesh_.y_.reserve(nodes);
  mesh_.z_.reserve(nodes);
  mesh_.element_type_.reserve(elements);
}

NodeId MeshBuilder::AddNode(double x, double y, double z) {
  mesh_.x_.push_back(x);
  mesh_.y_.push_back(y);
  mesh_.z_.push_back(z);
  return static_cast<NodeId>(mesh_.x_.size() - 1);
}

void MeshBuilder::SetFixed(std::int64_t node, bool fixed) {
  pending_fixed_.emplace_back(node, fixed);
}

void MeshBuilder::AddElement(ElementType type, std::span<const std::int64_t> nodes) {
  const std::int64_t element = mesh_.element_count();
  mesh_.element_type_.push_back(type);
  std::vector<std::int64_t>& staged = staged_nodes_[TypeIndex(type)];
  const auto expected = static_cast<std::size_t>(NodeCount(type));
  if (nodes.size() != expected && !wrong_node_count_.has_value()) {
    wrong_node_count_ =
        absl::InvalidArgumentError(absl::StrCat("element ", element, " (", TypeName(type), ") has ",
                                                nodes.size(), " nodes, expected ", expected));
  }
  // A wrong count is reported by Build; staging a padded copy keeps the blocks aligned.
  for (std::size_t k = 0; k < expected; ++k) staged.push_back(k < nodes.size() ? nodes[k] : 0);
}

namespace {

// A degenerate element (all nodes at one point, extent 0) is allowed: it is invalid, which
// untangling or the caller deals with. A tiny one is not: its quality would underflow to 0.
absl::Status CheckElementExtent(const Mesh& mesh, std::int64_t element, const std::int64_t* nodes,
                                int count) {
  double extent = 0.0;
  for (int k = 1; k < count; ++k) {
    extent = std::max({extent, std::abs(mesh.x()[nodes[k]] - mesh.x()[nodes[0]]),
                       std::abs(mesh.y()[nodes[k]] - mesh.y()[nodes[0]]),
                       std::abs(mesh.z()[nodes[k]] - mesh.z()[nodes[0]])});
  }
  if (extent > 0.0 && extent < kMinElementExtent) {
    return absl::InvalidArgumentError(absl::StrCat(
        "element ", element, " (", TypeName(mesh.type(static_cast<ElementId>(element))),
        ") spans only ", extent, ", below ", kMinElementExtent,
        " where element quality cannot be computed in double precision: rescale the mesh (e.g. "
        "change its length unit)"));
  }
  return absl::OkStatus();
}

// A face used by more than two elements: its nodes and how many use it.
struct FaceFault {
  std::vector<NodeId> nodes;
  std::int64_t uses = 0;
};

// Boundary: faces used by exactly one element mark their nodes in `boundary` and are counted.
// Returns the face of three or more elements (overlapping elements) with the lowest node ids, if
// any: the same one whatever order the grouping leaves the faces in. Reads only the blocks.
std::optional<FaceFault> MarkBoundary(const std::array<ElementBlock, kElementTypeCount>& blocks,
                                      std::int64_t node_count, std::vector<std::uint8_t>& boundary,
                                      std::int64_t& boundary_faces) {
  std::vector<FaceKey> collected;
  std::size_t corners = 0;
  for (const ElementBlock& block : blocks) corners += block.nodes.size();
  collected.reserve(corners);
  for (ElementType type : kAllElementTypes) {
    DispatchElementType(type, [&]<ElementType kType>() {
      CollectFaces<kType>(blocks[TypeIndex(kType)], collected);
    });
  }
  const std::vector<FaceKey> faces = GroupEqualFaces(collected);
  boundary.assign(node_count, 0);
  boundary_faces = 0;
  std::optional<std::size_t> lowest_fault;  // index of its first use in `faces`
  std::int64_t lowest_fault_uses = 0;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j] == faces[i]) ++j;
    if (j - i > 2 && (!lowest_fault.has_value() || faces[i] < faces[*lowest_fault])) {
      lowest_fault = i;
      lowest_fault_uses = static_cast<std::int64_t>(j - i);
    }
    if (j - i == 1) {
      ++boundary_faces;
      for (std::uint64_t word : {faces[i].low, faces[i].high}) {
        for (std::uint64_t id : {word >> 32, word & 0xffffffffu}) {
          if (id != 0xffffffffu) boundary[id] = 1;
        }
      }
    }
    i = j;
  }
  if (!lowest_fault.has_value()) return std::nullopt;
  FaceFault fault;
  fault.uses = lowest_fault_uses;
  const FaceKey& key = faces[*lowest_fault];
  for (std::uint64_t word : {key.low, key.high}) {
    for (std::uint64_t id : {word >> 32, word & 0xffffffffu}) {
      if (id != 0xffffffffu) fault.nodes.push_back(static_cast<NodeId>(id));
    }
  }
  return fault;
}

}  // namespace

absl::StatusOr<Mesh> MeshBuilder::Build() && {
  static const MeshErrorNames kDefaultNames;
  const MeshErrorNames& names = names_ != nullptr ? *names_ : kDefaultNames;
  Mesh& mesh = mesh_;
  const std::int64_t node_count = mesh.node_count();
  const std::int64_t element_count = mesh.element_count();
  if (node_count == 0 || element_count == 0) {
    return absl::InvalidArgumentError(names.EmptyMesh(node_count, element_count));
  }
  if (node_count > kMaxIndex || element_count > kMaxIndex) {
    return absl::InvalidArgumentError(absl::StrCat("mesh too large: ", node_count, " nodes, ",
                                                   element_count, " elements (limit ", kMaxIndex,
                                                   " each)"));
  }
  for (std::int64_t i = 0; i < node_count; ++i) {
    if (!std::isfinite(mesh.x_[i]) || !std::isfinite(mesh.y_[i]) || !std::isfinite(mesh.z_[i])) {
      return absl::InvalidArgumentError(
          names.NonFiniteCoordinate(i, mesh.x_[i], mesh.y_[i], mesh.z_[i]));
    }
    const double magnitude =
        std::max({std::abs(mesh.x_[i]), std::abs(mesh.y_[i]), std::abs(mesh.z_[i])});
    if (magnitude > kMaxCoordinate) {
      return absl::InvalidArgumentError(absl::StrCat(
          "node ", i, " has a coordinate of magnitude ", magnitude, ", beyond ", kMaxCoordinate,
          " where element quality cannot be computed in double precision: rescale or translate "
          "the mesh (e.g. change its length unit)"));
    }
  }
  mesh.fixed_.assign(node_count, 0);
  // Applied in call order, so the last SetFixed of a node wins.
  for (std::size_t entry = 0; entry < pending_fixed_.size(); ++entry) {
    const auto& [node, fixed] = pending_fixed_[entry];
    if (node < 0 || node >= node_count) {
      return absl::InvalidArgumentError(
          names.FixedNodeOutOfRange(static_cast<std::int64_t>(entry), node, node_count));
    }
    mesh.fixed_[node] = fixed ? 1 : 0;
  }
  if (wrong_node_count_.has_value()) return *wrong_node_count_;

  // Number the elements: in insertion order (each element's position within its type block is
  // its rank among the elements of its type added before it), or type by type in type_order_.
  mesh.block_index_.resize(element_count);
  std::array<std::int32_t, kElementTypeCount> added{};
  for (std::int64_t e = 0; e < element_count; ++e) {
    mesh.block_index_[e] = added[TypeIndex(mesh.element_type_[e])]++;
  }
  if (type_order_.has_value()) {
    std::int64_t next = 0;
    for (const ElementType type : *type_order_) {
      for (std::int32_t i = 0; i < added[TypeIndex(type)]; ++i, ++next) {
        mesh.element_type_[next] = type;
        mesh.block_index_[next] = i;
      }
    }
  }

  // Validate connectivity (by element number, so the first fault named is the lowest) and fill
  // the per-type blocks.
  for (ElementType type : kAllElementTypes) {
    ElementBlock& block = mesh.blocks_[TypeIndex(type)];
    block.elements.resize(staged_nodes_[TypeIndex(type)].size() / NodeCount(type));
    block.nodes.resize(staged_nodes_[TypeIndex(type)].size());
  }
  for (std::int64_t e = 0; e < element_count; ++e) {
    const ElementType type = mesh.element_type_[e];
    const int count = NodeCount(type);
    const std::int64_t index = mesh.block_index_[e];
    const std::int64_t* staged = staged_nodes_[TypeIndex(type)].data() + index * count;
    ElementBlock& block = mesh.blocks_[TypeIndex(type)];
    block.elements[index] = static_cast<ElementId>(e);
    for (int k = 0; k < count; ++k) {
      const std::int64_t node = staged[k];
      if (node < 0 || node >= node_count) {
        return absl::InvalidArgumentError(names.NodeOutOfRange(e, type, k, node, node_count));
      }
      for (int j = 0; j < k; ++j) {
        if (staged[j] == node) {
          return absl::InvalidArgumentError(names.RepeatedNode(e, type, node, j, k));
        }
      }
      block.nodes[index * count + k] = static_cast<NodeId>(node);
    }
    if (auto status = CheckElementExtent(mesh, e, staged, count); !status.ok()) return status;
  }
  staged_nodes_ = {};

  std::int64_t corners = 0;
  for (ElementType type : kAllElementTypes) {
    const ElementBlock& block = mesh.blocks_[TypeIndex(type)];
    mesh.corner_offset_[TypeIndex(type)] = corners;
    corners += static_cast<std::int64_t>(block.nodes.size());
    mesh.canonical_order_.insert(mesh.canonical_order_.end(), block.elements.begin(),
                                 block.elements.end());
  }
  bool identity = true;
  for (std::int64_t rank = 0; rank < element_count && identity; ++rank) {
    identity = mesh.canonical_order_[rank] == rank;
  }
  if (!identity) {
    mesh.canonical_rank_.resize(element_count);
    for (std::int64_t rank = 0; rank < element_count; ++rank) {
      mesh.canonical_rank_[mesh.canonical_order_[rank]] = static_cast<std::int32_t>(rank);
    }
  }
  mesh.corner_offset_[kElementTypeCount] = corners;

  // Node → element rows (canonical order).
  mesh.node_elements_ = BuildRows(node_count, [&](auto&& emit) {
    for (ElementId e : mesh.canonical_order_) {
      for (NodeId node : mesh.element_nodes(e)) emit(node, e);
    }
  });
  if (auto status = CheckNoRepeatedElements(mesh); !status.ok()) return status;
  const std::optional<FaceFault> face_fault =
      MarkBoundary(mesh.blocks_, node_count, mesh.boundary_, mesh.boundary_face_count_);
  if (face_fault.has_value()) {
    return NonManifoldFaceError(mesh, face_fault->nodes, face_fault->uses);
  }
  return std::move(mesh);
}

}  // namespace getme
