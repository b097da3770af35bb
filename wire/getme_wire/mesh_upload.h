#pragma once

#include <array>
#include <cstdint>
#include <memory>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "getme/mesh/mesh.h"
#include "getme/v1/mesh.pb.h"
#include "getme/v1/smoother.pb.h"
#include "getme_wire/mesh_assembler.h"
#include "getme_wire/mesh_ids.h"
#include "getme_wire/surface_groups.h"

namespace getme::wire {

// An uploaded mesh, held once: the engine mesh (elements numbered as on the wire) and what the
// wire carried beside it.
struct UploadedMesh {
  Mesh mesh;
  WireMeshIds ids;
  // The caller's tagged boundary faces as surface groups (surface_groups.h); empty if none.
  std::vector<surface::GroupedFace> surface_groups;
};

// Streams an upload's chunks straight into the engine's MeshBuilder: nodes and elements are
// handed over as they arrive (wedges mirrored into the paper's prism order), no wire copy of the
// mesh is kept. The wire-level checks (lengths, limits, ids) are made here; every check of the
// mesh itself is made once, by MeshBuilder::Build, worded in the wire's terms (the caller's ids,
// VTK node positions, mesh.proto's field names).
class MeshUpload {
 public:
  explicit MeshUpload(std::int64_t max_elements);
  ~MeshUpload();

  absl::Status Add(const v1::MeshChunk& chunk) { return assembler_.Add(chunk); }
  absl::Status Add(const v1::Mesh& part) { return assembler_.Add(part); }
  const MeshAssembler& assembler() const { return assembler_; }

  // Validates and builds; INVALID_ARGUMENT naming the node, element (type, index within its
  // type, number, caller id) or field at fault.
  absl::StatusOr<UploadedMesh> Finish() &&;

 private:
  class EngineTarget;
  std::unique_ptr<EngineTarget> target_;
  MeshAssembler assembler_;
};

// A whole wire mesh (e.g. an HTTP request's) as an engine mesh: one part through MeshUpload.
absl::StatusOr<UploadedMesh> ToEngineMesh(const v1::Mesh& wire, std::int64_t max_elements);

}  // namespace getme::wire
