#include "getme_wire/engine_mesh.h"

#include "absl/strings/str_cat.h"
#include "getme_wire/mesh_chunker.h"
#include "getme_wire/mesh_ids.h"

namespace getme::wire {

v1::Mesh ToWireMesh(const Mesh& mesh) {
  WireMeshIds ids;
  for (NodeId node = 0; node < mesh.node_count(); ++node) {
    if (mesh.is_fixed(node)) ids.fixed_nodes.push_back(static_cast<std::uint32_t>(node));
  }
  // One chunk holds everything: the chunker is the one place that writes the wire's form.
  MeshChunker chunker(mesh, ids, /*coordinates_only=*/false,
                      ChunkLimits{.bytes = std::size_t{1} << 62});
  v1::MeshChunk whole;
  chunker.Next(whole);
  return std::move(*whole.mutable_mesh());
}

absl::Status CheckCoordinateCount(std::span<const double> coordinates, std::int64_t nodes) {
  if (static_cast<std::int64_t>(coordinates.size()) != 3 * nodes) {
    return absl::InvalidArgumentError(absl::StrCat("the result has ", coordinates.size(),
                                                   " coordinates, but ", nodes, " nodes need ",
                                                   3 * nodes));
  }
  return absl::OkStatus();
}

absl::Status ApplyCoordinates(std::span<const double> coordinates, Mesh& mesh) {
  if (absl::Status status = CheckCoordinateCount(coordinates, mesh.node_count()); !status.ok()) {
    return status;
  }
  for (std::int64_t node = 0; node < mesh.node_count(); ++node) {
    mesh.x()[node] = coordinates[3 * node];
    mesh.y()[node] = coordinates[3 * node + 1];
    mesh.z()[node] = coordinates[3 * node + 2];
  }
  return absl::OkStatus();
}

}  // namespace getme::wire
