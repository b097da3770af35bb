#include "getme_wire/mesh_upload.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "absl/strings/str_cat.h"
#include "getme/elements/node_orders.h"
#include "getme/mesh/mesh_error_names.h"

namespace getme::wire {
namespace {

// MeshBuilder's errors in the wire's words: elements by wire type, index within that type,
// number and caller id; node positions in VTK order; fields as mesh.proto names them.
class WireErrorNames final : public MeshErrorNames {
 public:
  WireErrorNames(const WireMeshIds& ids,
                 const std::array<std::int64_t, kWireElementGroupCount>& group_counts)
      : ids_(ids) {
    std::int64_t offset = 0;
    for (int group = 0; group < kWireElementGroupCount; ++group) {
      group_offset_[group] = offset;
      offset += group_counts[group];
    }
  }

  std::string EmptyMesh(std::int64_t nodes, std::int64_t elements) const override {
    return absl::StrCat("empty mesh: ", nodes, " nodes and ", elements,
                        " volume elements (tetrahedra, hexahedra, wedges, pyramids); both must "
                        "be non-zero");
  }

  std::string NonFiniteCoordinate(std::int64_t node, double x, double y, double z) const override {
    const std::array<double, 3> xyz = {x, y, z};
    int axis = 0;
    while (axis < 2 && std::isfinite(xyz[axis])) ++axis;
    return absl::StrCat(ids_.NodeLabel(node),
                        " has a non-finite coordinate: ", std::string(1, "xyz"[axis]), " = ",
                        xyz[axis]);
  }

  std::string FixedNodeOutOfRange(std::int64_t entry, std::int64_t node,
                                  std::int64_t node_count) const override {
    return absl::StrCat("mesh.fixed_nodes[", entry, "] = ", node, " is out of range: the mesh has ",
                        node_count, " nodes");
  }

  std::string NodeOutOfRange(std::int64_t element, ElementType type, int position,
                             std::int64_t node, std::int64_t node_count) const override {
    return absl::StrCat(Label(element, type), ": node index ", node, " at position ",
                        VtkToPaperPosition(type, position), " is out of range: the mesh has ",
                        node_count, " nodes");
  }

  std::string RepeatedNode(std::int64_t element, ElementType type, std::int64_t node, int first,
                           int second) const override {
    const int a = VtkToPaperPosition(type, first);
    const int b = VtkToPaperPosition(type, second);
    return absl::StrCat(Label(element, type), ": node ", node, " appears twice (positions ",
                        std::min(a, b), " and ", std::max(a, b), ")");
  }

 private:
  std::string Label(std::int64_t element, ElementType type) const {
    const int group = WireGroupOf(type);
    return ids_.ElementLabel(kWireElementGroups[group].name, element - group_offset_[group],
                             element);
  }

  const WireMeshIds& ids_;
  std::array<std::int64_t, kWireElementGroupCount> group_offset_{};
};

}  // namespace

// Hands whole nodes and elements to the builder as they arrive, and keeps the wire's ids.
class MeshUpload::EngineTarget final : public AssemblyTarget {
 public:
  EngineTarget() { builder_.NumberElementsByType(kWireElementOrder); }

  void AddCoordinates(std::span<const double> xyz) override {
    for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) {
      builder_.AddNode(xyz[i], xyz[i + 1], xyz[i + 2]);
    }
  }
  void AddElements(int group, std::span<const std::uint32_t> nodes) override {
    const ElementType type = kWireElementGroups[group].type;
    const std::size_t count = NodeCount(type);
    std::array<std::int64_t, kMaxElementNodes> paper{};
    for (std::size_t start = 0; start < nodes.size(); start += count) {
      MirrorVtkPaperOrder(type, nodes.subspan(start, count),
                          std::span<std::int64_t>(paper.data(), count));
      builder_.AddElement(type, std::span<const std::int64_t>(paper.data(), count));
    }
    group_counts_[group] += static_cast<std::int64_t>(nodes.size() / count);
  }
  void AddFixedNodes(std::span<const std::uint32_t> nodes) override {
    for (const std::uint32_t node : nodes) builder_.SetFixed(node);
    ids_.fixed_nodes.insert(ids_.fixed_nodes.end(), nodes.begin(), nodes.end());
  }
  void AddNodeIds(std::span<const std::uint64_t> ids) override {
    ids_.node_ids.insert(ids_.node_ids.end(), ids.begin(), ids.end());
  }
  void AddElementIds(std::span<const std::uint64_t> ids) override {
    ids_.element_ids.insert(ids_.element_ids.end(), ids.begin(), ids.end());
  }
  void AddSurfaceGroups(const v1::Mesh& part) override { surface_groups_.Append(part); }

  absl::StatusOr<UploadedMesh> Build() && {
    const std::int64_t nodes = builder_.node_count();
    const std::int64_t elements = builder_.element_count();
    const auto node_ids = static_cast<std::int64_t>(ids_.node_ids.size());
    const auto element_ids = static_cast<std::int64_t>(ids_.element_ids.size());
    if (node_ids != 0 && node_ids != nodes) {
      return absl::InvalidArgumentError(absl::StrCat("mesh.node_ids has ", node_ids,
                                                     " entries but the mesh has ", nodes,
                                                     " nodes (give one per node, or none)"));
    }
    if (element_ids != 0 && element_ids != elements) {
      return absl::InvalidArgumentError(absl::StrCat("mesh.element_ids has ", element_ids,
                                                     " entries but the mesh has ", elements,
                                                     " elements (give one per element, or none)"));
    }
    const WireErrorNames names(ids_, group_counts_);
    builder_.SetErrorNames(&names);
    absl::StatusOr<Mesh> mesh = std::move(builder_).Build();
    if (!mesh.ok()) return mesh.status();
    absl::StatusOr<std::vector<surface::GroupedFace>> groups =
        ToSurfaceGroups(surface_groups_, nodes);
    if (!groups.ok()) return groups.status();
    return UploadedMesh{*std::move(mesh), std::move(ids_), *std::move(groups)};
  }

 private:
  MeshBuilder builder_;
  WireMeshIds ids_;
  WireSurfaceGroups surface_groups_;
  std::array<std::int64_t, kWireElementGroupCount> group_counts_{};
};

MeshUpload::MeshUpload(std::int64_t max_elements)
    : target_(std::make_unique<EngineTarget>()), assembler_(*target_, max_elements) {}

MeshUpload::~MeshUpload() = default;

absl::StatusOr<UploadedMesh> MeshUpload::Finish() && {
  if (auto s = assembler_.CheckWhole(); !s.ok()) return s;
  return std::move(*target_).Build();
}

absl::StatusOr<UploadedMesh> ToEngineMesh(const v1::Mesh& wire, std::int64_t max_elements) {
  MeshUpload upload(max_elements);
  if (auto s = upload.Add(wire); !s.ok()) return s;
  return std::move(upload).Finish();
}

}  // namespace getme::wire
