#pragma once

#include <cstdint>
#include <functional>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "getme/mesh/mesh.h"
#include "getme/v1/mesh.pb.h"
#include "getme/v1/smoother.pb.h"

namespace getme::server {

// Wire meshes (getme.v1.Mesh, VTK node order, uploaded in chunks) to engine meshes and back.
// Element numbering on the wire and in the engine is the same: tetrahedra, hexahedra, wedges,
// pyramids, each in the order given, because elements are added to the engine in that order.

// Complete elements in the wire mesh (a trailing partial element is not counted).
std::int64_t WireElementCount(const v1::Mesh& mesh);

// Appends a chunk to the mesh uploaded so far; fails as soon as the mesh exceeds max_elements,
// so an oversized upload is refused without buffering all of it.
absl::Status AppendMeshChunk(const v1::MeshChunk& chunk, std::int64_t max_elements,
                             v1::Mesh& accumulated);

// A declared size (SmoothHeader.expected_size) over the limit is refused before the upload.
absl::Status CheckDeclaredSize(const v1::MeshSize& expected, std::int64_t max_elements);
// The uploaded chunks must add up to the declared size, when one was given.
absl::Status CheckExpectedSize(const v1::MeshSize& expected, const v1::Mesh& mesh);

// Validates the wire mesh (field lengths, index ranges, finite coordinates, ids) with messages
// naming the node, element (type, index within its type, global number, caller id) or field,
// and builds the engine mesh, mirroring VTK wedges into the paper's prism order.
absl::StatusOr<Mesh> ToEngineMesh(const v1::Mesh& wire, std::int64_t max_elements);

// The caller's id of an engine element (Mesh.element_ids when given, else its number).
std::uint64_t WireElementId(const v1::Mesh& wire, std::int64_t element);

// Sends the smoothed mesh as chunks of about 1 MB: coordinates (with node_ids) first, then, unless
// coordinates_only, the topology of `wire` (connectivity, fixed nodes, element ids) unchanged.
// nodes_per_chunk 0 = the server's choice. Stops and returns false when `emit` returns false.
bool EmitResultChunks(const v1::Mesh& wire, const Mesh& smoothed, bool coordinates_only,
                      std::uint32_t nodes_per_chunk,
                      const std::function<bool(const v1::MeshChunk&)>& emit);

}  // namespace getme::server
