#include "getme/mesh/mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

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

// Builds CSR rows from (row, item) pairs given row counts; items stay in insertion order.
template <typename ForEachPair>
CompressedRows BuildRows(std::int64_t rows, ForEachPair&& for_each_pair) {
  CompressedRows csr;
  csr.offsets.assign(rows + 1, 0);
  for_each_pair([&](std::int64_t row, std::int32_t) { ++csr.offsets[row + 1]; });
  std::partial_sum(csr.offsets.begin(), csr.offsets.end(), csr.offsets.begin());
  csr.items.resize(csr.offsets.back());
  std::vector<std::int64_t> cursor(csr.offsets.begin(), csr.offsets.end() - 1);
  for_each_pair([&](std::int64_t row, std::int32_t item) { csr.items[cursor[row]++] = item; });
  return csr;
}

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

}  // namespace

std::span<const NodeId> Mesh::element_nodes(ElementId element) const {
  const ElementType element_type = element_type_[element];
  const int n = NodeCount(element_type);
  const auto& nodes = blocks_[TypeIndex(element_type)].nodes;
  return {nodes.data() + static_cast<std::int64_t>(block_index_[element]) * n,
          static_cast<std::size_t>(n)};
}

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

void MeshBuilder::Reserve(std::int64_t nodes, std::int64_t elements) {
  mesh_.x_.reserve(nodes);
  mesh_.y_.reserve(nodes);
  mesh_.z_.reserve(nodes);
  mesh_.element_type_.reserve(elements);
  raw_offsets_.reserve(elements + 1);
  raw_nodes_.reserve(elements * 6);
}

NodeId MeshBuilder::AddNode(double x, double y, double z) {
  mesh_.x_.push_back(x);
  mesh_.y_.push_back(y);
  mesh_.z_.push_back(z);
  return static_cast<NodeId>(mesh_.x_.size() - 1);
}

void MeshBuilder::SetFixed(NodeId node, bool fixed) { pending_fixed_.emplace_back(node, fixed); }

void MeshBuilder::AddElement(ElementType type, std::span<const std::int64_t> nodes) {
  mesh_.element_type_.push_back(type);
  raw_nodes_.insert(raw_nodes_.end(), nodes.begin(), nodes.end());
  raw_offsets_.push_back(static_cast<std::int64_t>(raw_nodes_.size()));
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

}  // namespace

absl::StatusOr<Mesh> MeshBuilder::Build() && {
  Mesh& mesh = mesh_;
  const std::int64_t node_count = mesh.node_count();
  const std::int64_t element_count = mesh.element_count();
  if (node_count == 0 || element_count == 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("empty mesh: ", node_count, " nodes and ", element_count, " volume elements"));
  }
  if (node_count > kMaxIndex || element_count > kMaxIndex) {
    return absl::InvalidArgumentError(absl::StrCat("mesh too large: ", node_count, " nodes, ",
                                                   element_count, " elements (limit ", kMaxIndex,
                                                   " each)"));
  }
  for (std::int64_t i = 0; i < node_count; ++i) {
    if (!std::isfinite(mesh.x_[i]) || !std::isfinite(mesh.y_[i]) || !std::isfinite(mesh.z_[i])) {
      return absl::InvalidArgumentError(absl::StrCat("node ", i, " has a non-finite coordinate (",
                                                     mesh.x_[i], ", ", mesh.y_[i], ", ", mesh.z_[i],
                                                     ")"));
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
  for (const auto& [node, fixed] : pending_fixed_) {
    if (node < 0 || node >= node_count) {
      return absl::InvalidArgumentError(
          absl::StrCat("fixed node id ", node, " out of range [0, ", node_count, ")"));
    }
    mesh.fixed_[node] = fixed ? 1 : 0;
  }

  // Validate connectivity and sort elements into per-type blocks.
  mesh.block_index_.resize(element_count);
  for (std::int64_t e = 0; e < element_count; ++e) {
    const ElementType type = mesh.element_type_[e];
    const int expected = NodeCount(type);
    const std::int64_t begin = raw_offsets_[e];
    const std::int64_t given = raw_offsets_[e + 1] - begin;
    if (given != expected) {
      return absl::InvalidArgumentError(absl::StrCat("element ", e, " (", TypeName(type), ") has ",
                                                     given, " nodes, expected ", expected));
    }
    ElementBlock& block = mesh.blocks_[TypeIndex(type)];
    mesh.block_index_[e] = static_cast<std::int32_t>(block.elements.size());
    block.elements.push_back(static_cast<ElementId>(e));
    for (int k = 0; k < expected; ++k) {
      const std::int64_t node = raw_nodes_[begin + k];
      if (node < 0 || node >= node_count) {
        return absl::InvalidArgumentError(absl::StrCat("element ", e, " (", TypeName(type),
                                                       ") node ", k, " has id ", node,
                                                       ", out of range [0, ", node_count, ")"));
      }
      for (int j = 0; j < k; ++j) {
        if (raw_nodes_[begin + j] == node) {
          return absl::InvalidArgumentError(
              absl::StrCat("element ", e, " (", TypeName(type), ") uses node ", node,
                           " twice (local nodes ", j, " and ", k, ")"));
        }
      }
      block.nodes.push_back(static_cast<NodeId>(node));
    }
    if (auto status = CheckElementExtent(mesh, e, &raw_nodes_[begin], expected); !status.ok()) {
      return status;
    }
  }
  raw_nodes_ = {};
  raw_offsets_ = {};

  std::int64_t corners = 0;
  for (ElementType type : kAllElementTypes) {
    const ElementBlock& block = mesh.blocks_[TypeIndex(type)];
    mesh.corner_offset_[TypeIndex(type)] = corners;
    corners += static_cast<std::int64_t>(block.nodes.size());
    mesh.block_rank_offset_[TypeIndex(type)] =
        static_cast<std::int64_t>(mesh.canonical_order_.size());
    mesh.canonical_order_.insert(mesh.canonical_order_.end(), block.elements.begin(),
                                 block.elements.end());
  }
  mesh.corner_offset_[kElementTypeCount] = corners;

  // Node → corner rows (corners ascend within a row), and node → element rows (canonical order).
  mesh.node_corners_ = BuildRows(node_count, [&](auto&& emit) {
    for (ElementType type : kAllElementTypes) {
      const auto& nodes = mesh.blocks_[TypeIndex(type)].nodes;
      const std::int64_t offset = mesh.corner_offset_[TypeIndex(type)];
      for (std::size_t c = 0; c < nodes.size(); ++c) {
        emit(nodes[c], static_cast<std::int32_t>(offset + static_cast<std::int64_t>(c)));
      }
    }
  });
  mesh.node_elements_ = BuildRows(node_count, [&](auto&& emit) {
    for (ElementId e : mesh.canonical_order_) {
      for (NodeId node : mesh.element_nodes(e)) emit(node, e);
    }
  });

  if (auto status = CheckNoRepeatedElements(mesh); !status.ok()) return status;

  // Boundary: faces used by exactly one element (sorting groups equal faces together); a face of
  // three or more elements is refused (overlapping elements).
  std::vector<FaceKey> faces;
  faces.reserve(mesh.corner_count());
  for (ElementType type : kAllElementTypes) {
    DispatchElementType(type, [&]<ElementType kType>() {
      CollectFaces<kType>(mesh.blocks_[TypeIndex(kType)], faces);
    });
  }
  std::sort(faces.begin(), faces.end());
  mesh.boundary_.assign(node_count, 0);
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j] == faces[i]) ++j;
    if (j - i > 2) {
      std::vector<NodeId> face_nodes;
      for (std::uint64_t word : {faces[i].low, faces[i].high}) {
        for (std::uint64_t id : {word >> 32, word & 0xffffffffu}) {
          if (id != 0xffffffffu) face_nodes.push_back(static_cast<NodeId>(id));
        }
      }
      return NonManifoldFaceError(mesh, face_nodes, static_cast<std::int64_t>(j - i));
    }
    if (j - i == 1) {
      ++mesh.boundary_face_count_;
      for (std::uint64_t word : {faces[i].low, faces[i].high}) {
        for (std::uint64_t id : {word >> 32, word & 0xffffffffu}) {
          if (id != 0xffffffffu) mesh.boundary_[id] = 1;
        }
      }
    }
    i = j;
  }
  return std::move(mesh);
}

}  // namespace getme
