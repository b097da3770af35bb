#include "getme_server/mesh_conversion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "absl/strings/str_cat.h"
#include "getme/elements/element_type.h"

namespace getme::server {
namespace {

using Indices = google::protobuf::RepeatedField<std::uint32_t>;

// The wire's element fields in element-numbering order.
struct WireType {
  const char* field;  // name of the Mesh field
  const char* name;   // one element of it
  ElementType type;
};
constexpr std::array<WireType, 4> kWireTypes = {{
    {"tetrahedra", "tetrahedron", ElementType::kTetrahedron},
    {"hexahedra", "hexahedron", ElementType::kHexahedron},
    {"wedges", "wedge", ElementType::kPrism},
    {"pyramids", "pyramid", ElementType::kPyramid},
}};

const Indices& Connectivity(const v1::Mesh& mesh, int wire_type) {
  switch (wire_type) {
    case 0:
      return mesh.tetrahedra();
    case 1:
      return mesh.hexahedra();
    case 2:
      return mesh.wedges();
    default:
      return mesh.pyramids();
  }
}

Indices* MutableConnectivity(v1::Mesh& mesh, int wire_type) {
  switch (wire_type) {
    case 0:
      return mesh.mutable_tetrahedra();
    case 1:
      return mesh.mutable_hexahedra();
    case 2:
      return mesh.mutable_wedges();
    default:
      return mesh.mutable_pyramids();
  }
}

// Paper prism (p0..p5) = VTK wedge (v0, v2, v1, v3, v5, v4) (NOTES.md §1).
constexpr std::array<int, 6> kWedgeToPrism = {0, 2, 1, 3, 5, 4};

std::string ElementLabel(const v1::Mesh& wire, int wire_type, std::int64_t index_in_type,
                         std::int64_t element) {
  std::string label =
      absl::StrCat(kWireTypes[wire_type].name, " ", index_in_type, " (element ", element);
  if (wire.element_ids_size() > 0 && element < wire.element_ids_size()) {
    absl::StrAppend(&label, ", id ", wire.element_ids(static_cast<int>(element)));
  }
  return absl::StrCat(label, ")");
}

std::string NodeLabel(const v1::Mesh& wire, std::int64_t node) {
  if (wire.node_ids_size() > 0 && node < wire.node_ids_size()) {
    return absl::StrCat("node ", node, " (id ", wire.node_ids(static_cast<int>(node)), ")");
  }
  return absl::StrCat("node ", node);
}

absl::Status TooLarge(std::int64_t elements, std::int64_t max_elements) {
  return absl::InvalidArgumentError(absl::StrCat("mesh has ", elements,
                                                 " elements, more than the server's limit of ",
                                                 max_elements, " (--max_elements)"));
}

absl::Status CheckSizeField(const char* field, std::uint64_t expected, std::uint64_t actual,
                            const char* unit) {
  if (expected == actual) return absl::OkStatus();
  return absl::InvalidArgumentError(absl::StrCat("expected_size.", field, " = ", expected,
                                                 " but the uploaded chunks carry ", actual, " ",
                                                 unit));
}

}  // namespace

std::int64_t WireElementCount(const v1::Mesh& mesh) {
  std::int64_t count = 0;
  for (int t = 0; t < 4; ++t) count += Connectivity(mesh, t).size() / NodeCount(kWireTypes[t].type);
  return count;
}

absl::Status AppendMeshChunk(const v1::MeshChunk& chunk, std::int64_t max_elements,
                             v1::Mesh& accumulated) {
  accumulated.MergeFrom(chunk.mesh());
  if (const std::int64_t elements = WireElementCount(accumulated); elements > max_elements) {
    return TooLarge(elements, max_elements);
  }
  return absl::OkStatus();
}

absl::Status CheckDeclaredSize(const v1::MeshSize& expected, std::int64_t max_elements) {
  const std::uint64_t elements =
      expected.tetrahedra() + expected.hexahedra() + expected.wedges() + expected.pyramids();
  if (elements > static_cast<std::uint64_t>(max_elements)) {
    return absl::InvalidArgumentError(absl::StrCat("expected_size declares ", elements,
                                                   " elements, more than the server's limit of ",
                                                   max_elements, " (--max_elements)"));
  }
  return absl::OkStatus();
}

absl::Status CheckExpectedSize(const v1::MeshSize& expected, const v1::Mesh& mesh) {
  const std::array<std::uint64_t, 4> declared = {expected.tetrahedra(), expected.hexahedra(),
                                                 expected.wedges(), expected.pyramids()};
  if (auto s = CheckSizeField("nodes", expected.nodes(), mesh.coordinates_size() / 3, "nodes");
      !s.ok()) {
    return s;
  }
  for (int t = 0; t < 4; ++t) {
    const std::uint64_t actual = Connectivity(mesh, t).size() / NodeCount(kWireTypes[t].type);
    if (auto s = CheckSizeField(kWireTypes[t].field, declared[t], actual, kWireTypes[t].field);
        !s.ok()) {
      return s;
    }
  }
  return absl::OkStatus();
}

std::uint64_t WireElementId(const v1::Mesh& wire, std::int64_t element) {
  if (wire.element_ids_size() > 0 && element < wire.element_ids_size()) {
    return wire.element_ids(static_cast<int>(element));
  }
  return static_cast<std::uint64_t>(element);
}

absl::StatusOr<Mesh> ToEngineMesh(const v1::Mesh& wire, std::int64_t max_elements) {
  if (wire.coordinates_size() % 3 != 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("mesh.coordinates has ", wire.coordinates_size(),
                     " values, not a multiple of 3 (x, y, z per node)"));
  }
  const std::int64_t nodes = wire.coordinates_size() / 3;
  for (int t = 0; t < 4; ++t) {
    const int per_element = NodeCount(kWireTypes[t].type);
    if (Connectivity(wire, t).size() % per_element != 0) {
      return absl::InvalidArgumentError(
          absl::StrCat("mesh.", kWireTypes[t].field, " has ", Connectivity(wire, t).size(),
                       " node indices, not a multiple of ", per_element, " (nodes per ",
                       kWireTypes[t].name, "); the last ", kWireTypes[t].name, " is incomplete"));
    }
  }
  const std::int64_t elements = WireElementCount(wire);
  if (nodes == 0 || elements == 0) {
    return absl::InvalidArgumentError(
        absl::StrCat("empty mesh: ", nodes, " nodes and ", elements,
                     " volume elements (tetrahedra, hexahedra, wedges, pyramids); both must be "
                     "non-zero"));
  }
  if (elements > max_elements) return TooLarge(elements, max_elements);
  if (wire.node_ids_size() != 0 && wire.node_ids_size() != nodes) {
    return absl::InvalidArgumentError(absl::StrCat("mesh.node_ids has ", wire.node_ids_size(),
                                                   " entries but the mesh has ", nodes,
                                                   " nodes (give one per node, or none)"));
  }
  if (wire.element_ids_size() != 0 && wire.element_ids_size() != elements) {
    return absl::InvalidArgumentError(absl::StrCat("mesh.element_ids has ", wire.element_ids_size(),
                                                   " entries but the mesh has ", elements,
                                                   " elements (give one per element, or none)"));
  }

  MeshBuilder builder;
  builder.Reserve(nodes, elements);
  const double* xyz = wire.coordinates().data();
  for (std::int64_t n = 0; n < nodes; ++n) {
    const double* p = xyz + 3 * n;
    for (int axis = 0; axis < 3; ++axis) {
      if (!std::isfinite(p[axis])) {
        return absl::InvalidArgumentError(absl::StrCat(
            NodeLabel(wire, n), " has a non-finite coordinate: ", "xyz"[axis] + std::string(),
            " = ", p[axis]));
      }
    }
    builder.AddNode(p[0], p[1], p[2]);
  }
  for (int i = 0; i < wire.fixed_nodes_size(); ++i) {
    const std::uint32_t node = wire.fixed_nodes(i);
    if (node >= nodes) {
      return absl::InvalidArgumentError(absl::StrCat("mesh.fixed_nodes[", i, "] = ", node,
                                                     " is out of range: the mesh has ", nodes,
                                                     " nodes"));
    }
    builder.SetFixed(static_cast<NodeId>(node));
  }

  std::int64_t element = 0;
  std::array<std::int64_t, kMaxElementNodes> engine_nodes{};
  for (int t = 0; t < 4; ++t) {
    const ElementType type = kWireTypes[t].type;
    const int per_element = NodeCount(type);
    const Indices& indices = Connectivity(wire, t);
    const std::int64_t count = indices.size() / per_element;
    for (std::int64_t i = 0; i < count; ++i, ++element) {
      const std::uint32_t* local = indices.data() + i * per_element;
      for (int k = 0; k < per_element; ++k) {
        if (local[k] >= nodes) {
          return absl::InvalidArgumentError(
              absl::StrCat(ElementLabel(wire, t, i, element), ": node index ", local[k],
                           " at position ", k, " is out of range: the mesh has ", nodes, " nodes"));
        }
        for (int j = 0; j < k; ++j) {
          if (local[j] == local[k]) {
            return absl::InvalidArgumentError(
                absl::StrCat(ElementLabel(wire, t, i, element), ": node ", local[k],
                             " appears twice (positions ", j, " and ", k, ")"));
          }
        }
      }
      for (int k = 0; k < per_element; ++k) {
        engine_nodes[k] = type == ElementType::kPrism ? local[kWedgeToPrism[k]] : local[k];
      }
      builder.AddElement(type, std::span<const std::int64_t>(engine_nodes.data(), per_element));
    }
  }
  return std::move(builder).Build();
}

bool EmitResultChunks(const v1::Mesh& wire, const Mesh& smoothed, bool coordinates_only,
                      std::uint32_t nodes_per_chunk,
                      const std::function<bool(const v1::MeshChunk&)>& emit) {
  // About 1 MB per chunk: 24 bytes of coordinates per node (plus up to 10 bytes of id), and at
  // most 5 bytes per varint index. The cap keeps a caller's choice below gRPC's default 4 MB.
  constexpr std::uint32_t kDefaultNodesPerChunk = 40'000;
  constexpr std::uint32_t kMaxNodesPerChunk = 100'000;
  constexpr int kIndicesPerChunk = 200'000;
  const std::int64_t chunk_nodes =
      nodes_per_chunk == 0 ? kDefaultNodesPerChunk : std::min(nodes_per_chunk, kMaxNodesPerChunk);

  const std::int64_t nodes = smoothed.node_count();
  const bool with_ids = wire.node_ids_size() == nodes;
  for (std::int64_t begin = 0; begin < nodes; begin += chunk_nodes) {
    const std::int64_t end = std::min(nodes, begin + chunk_nodes);
    v1::MeshChunk chunk;
    v1::Mesh* mesh = chunk.mutable_mesh();
    mesh->mutable_coordinates()->Reserve(static_cast<int>(3 * (end - begin)));
    for (std::int64_t n = begin; n < end; ++n) {
      mesh->add_coordinates(smoothed.x()[n]);
      mesh->add_coordinates(smoothed.y()[n]);
      mesh->add_coordinates(smoothed.z()[n]);
      if (with_ids) mesh->add_node_ids(wire.node_ids(static_cast<int>(n)));
    }
    if (!emit(chunk)) return false;
  }
  if (coordinates_only) return true;

  // Topology: each field in slices, in the order of the element numbering.
  auto emit_slices = [&](const auto& field, auto target, int per_chunk) {
    for (int begin = 0; begin < field.size(); begin += per_chunk) {
      const int end = std::min(field.size(), begin + per_chunk);
      v1::MeshChunk chunk;
      auto* out = target(*chunk.mutable_mesh());
      out->Add(field.begin() + begin, field.begin() + end);
      if (!emit(chunk)) return false;
    }
    return true;
  };
  for (int t = 0; t < 4; ++t) {
    const Indices& indices = Connectivity(wire, t);
    for (int begin = 0; begin < indices.size(); begin += kIndicesPerChunk) {
      const int end = std::min(indices.size(), begin + kIndicesPerChunk);
      v1::MeshChunk chunk;
      MutableConnectivity(*chunk.mutable_mesh(), t)
          ->Add(indices.begin() + begin, indices.begin() + end);
      if (!emit(chunk)) return false;
    }
  }
  if (!emit_slices(
          wire.fixed_nodes(), [](v1::Mesh& m) { return m.mutable_fixed_nodes(); },
          kIndicesPerChunk)) {
    return false;
  }
  return emit_slices(
      wire.element_ids(), [](v1::Mesh& m) { return m.mutable_element_ids(); },
      kIndicesPerChunk / 2);
}

}  // namespace getme::server
