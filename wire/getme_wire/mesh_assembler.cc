#include "getme_wire/mesh_assembler.h"

#include <algorithm>

#include "absl/strings/str_cat.h"

namespace getme::wire {
namespace {

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

// Hands the whole items of `values` (with what `partial` held back) to `deliver`, keeping the
// rest in `partial`.
template <typename T, typename Deliver>
void DeliverWhole(std::span<const T> values, int per_item, std::vector<T>& partial,
                  Deliver&& deliver) {
  if (!partial.empty()) {
    const std::size_t missing = per_item - partial.size();
    const std::size_t take = std::min(missing, values.size());
    partial.insert(partial.end(), values.begin(), values.begin() + take);
    values = values.subspan(take);
    if (partial.size() < static_cast<std::size_t>(per_item)) return;
    deliver(std::span<const T>(partial));
    partial.clear();
  }
  const std::size_t whole = values.size() / per_item * per_item;
  if (whole > 0) deliver(values.first(whole));
  partial.assign(values.begin() + whole, values.end());
}

template <typename T>
std::span<const T> AsSpan(const google::protobuf::RepeatedField<T>& field) {
  return {field.data(), static_cast<std::size_t>(field.size())};
}

}  // namespace

void WireMeshTarget::AddCoordinates(std::span<const double> xyz) {
  mesh_.mutable_coordinates()->Add(xyz.begin(), xyz.end());
}
void WireMeshTarget::AddElements(int group, std::span<const std::uint32_t> nodes) {
  MutableConnectivity(mesh_, group)->Add(nodes.begin(), nodes.end());
}
void WireMeshTarget::AddFixedNodes(std::span<const std::uint32_t> nodes) {
  mesh_.mutable_fixed_nodes()->Add(nodes.begin(), nodes.end());
}
void WireMeshTarget::AddNodeIds(std::span<const std::uint64_t> ids) {
  mesh_.mutable_node_ids()->Add(ids.begin(), ids.end());
}
void WireMeshTarget::AddElementIds(std::span<const std::uint64_t> ids) {
  mesh_.mutable_element_ids()->Add(ids.begin(), ids.end());
}

void WireMeshTarget::AddSurfaceGroups(const v1::Mesh& part) {
  mesh_.mutable_group_triangles()->MergeFrom(part.group_triangles());
  mesh_.mutable_group_quads()->MergeFrom(part.group_quads());
  mesh_.mutable_triangle_groups()->MergeFrom(part.triangle_groups());
  mesh_.mutable_quad_groups()->MergeFrom(part.quad_groups());
}

std::int64_t MeshAssembler::elements() const {
  std::int64_t count = 0;
  for (int group = 0; group < kWireElementGroupCount; ++group) {
    count += element_values_[group] / NodeCount(kWireElementGroups[group].type);
  }
  return count;
}

absl::Status MeshAssembler::Add(const v1::Mesh& part) {
  encoded_bytes_ += static_cast<std::int64_t>(part.ByteSizeLong());
  coordinate_values_ += part.coordinates_size();
  DeliverWhole(AsSpan(part.coordinates()), 3, partial_node_,
               [this](std::span<const double> xyz) { target_.AddCoordinates(xyz); });
  for (int group = 0; group < kWireElementGroupCount; ++group) {
    const Indices& field = Connectivity(part, group);
    if (field.empty()) continue;
    element_values_[group] += field.size();
    DeliverWhole(
        AsSpan(field), NodeCount(kWireElementGroups[group].type), partial_elements_[group],
        [this, group](std::span<const std::uint32_t> nodes) { target_.AddElements(group, nodes); });
  }
  if (const std::int64_t count = elements(); count > max_elements_) {
    return TooLarge(count, max_elements_);
  }
  if (!part.fixed_nodes().empty()) target_.AddFixedNodes(AsSpan(part.fixed_nodes()));
  if (!part.node_ids().empty()) {
    node_ids_ += part.node_ids_size();
    target_.AddNodeIds(AsSpan(part.node_ids()));
  }
  if (!part.element_ids().empty()) {
    element_ids_ += part.element_ids_size();
    target_.AddElementIds(AsSpan(part.element_ids()));
  }
  if (!part.group_triangles().empty() || !part.group_quads().empty() ||
      !part.triangle_groups().empty() || !part.quad_groups().empty()) {
    target_.AddSurfaceGroups(part);
  }
  return absl::OkStatus();
}

absl::Status MeshAssembler::CheckWhole() const {
  if (coordinate_values_ % 3 != 0) {
    return absl::InvalidArgumentError(absl::StrCat("mesh.coordinates has ", coordinate_values_,
                                                   " values, not a multiple of 3 (x, y, z per "
                                                   "node)"));
  }
  for (int group = 0; group < kWireElementGroupCount; ++group) {
    const WireElementGroup& g = kWireElementGroups[group];
    const int per_element = NodeCount(g.type);
    if (element_values_[group] % per_element != 0) {
      return absl::InvalidArgumentError(absl::StrCat(
          "mesh.", g.field, " has ", element_values_[group], " node indices, not a multiple of ",
          per_element, " (nodes per ", g.name, "); the last ", g.name, " is incomplete"));
    }
  }
  return absl::OkStatus();
}

absl::Status MeshAssembler::CheckExpectedSize(const v1::MeshSize& expected) const {
  const std::array<std::uint64_t, kWireElementGroupCount> declared = {
      expected.tetrahedra(), expected.hexahedra(), expected.wedges(), expected.pyramids()};
  if (auto s = CheckSizeField("nodes", expected.nodes(), nodes(), "nodes"); !s.ok()) return s;
  for (int group = 0; group < kWireElementGroupCount; ++group) {
    const WireElementGroup& g = kWireElementGroups[group];
    const std::uint64_t actual = element_values_[group] / NodeCount(g.type);
    if (auto s = CheckSizeField(g.field, declared[group], actual, g.field); !s.ok()) return s;
  }
  return absl::OkStatus();
}

absl::Status MeshAssembler::CheckComplete(std::uint64_t nodes) const {
  if (static_cast<std::uint64_t>(coordinate_values_) != 3 * nodes) {
    return absl::FailedPreconditionError(absl::StrCat(
        "the result stream ended with ", coordinate_values_,
        " coordinates, but the result announced ", nodes, " nodes (", 3 * nodes, " coordinates)"));
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

}  // namespace getme::wire
