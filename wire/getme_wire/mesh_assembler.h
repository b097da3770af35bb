#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "absl/status/status.h"
#include "getme/v1/mesh.pb.h"
#include "getme/v1/smoother.pb.h"
#include "getme_wire/mesh_fields.h"

namespace getme::wire {

// Where a MeshAssembler puts what arrives: always whole nodes (x, y, z) and whole elements (in
// the wire's VTK node order), in arrival order.
class AssemblyTarget {
 public:
  virtual ~AssemblyTarget() = default;
  virtual void AddCoordinates(std::span<const double> xyz) = 0;
  virtual void AddElements(int group, std::span<const std::uint32_t> nodes) = 0;
  virtual void AddFixedNodes(std::span<const std::uint32_t> nodes) = 0;
  virtual void AddNodeIds(std::span<const std::uint64_t> ids) = 0;
  virtual void AddElementIds(std::span<const std::uint64_t> ids) = 0;
  // The part's tagged boundary faces and their tags, as they came (checked when the mesh is built).
  virtual void AddSurfaceGroups(const v1::Mesh& part) = 0;
};

// Appends to a wire mesh: how a client gathers a result.
class WireMeshTarget final : public AssemblyTarget {
 public:
  void AddCoordinates(std::span<const double> xyz) override;
  void AddElements(int group, std::span<const std::uint32_t> nodes) override;
  void AddFixedNodes(std::span<const std::uint32_t> nodes) override;
  void AddNodeIds(std::span<const std::uint64_t> ids) override;
  void AddElementIds(std::span<const std::uint64_t> ids) override;
  void AddSurfaceGroups(const v1::Mesh& part) override;
  v1::Mesh& mesh() { return mesh_; }

 private:
  v1::Mesh mesh_;
};

// The one assembler, for uploads (server, into the engine's MeshBuilder: mesh_upload.h) and
// results (client, into a wire mesh) alike. Every repeated field of a part is appended to the
// same field of the earlier parts (mesh.proto); a node or element cut between two parts is held
// back until it is whole, so the target only ever sees whole items. Refuses a mesh as soon as it
// passes max_elements, so an oversized upload is never buffered whole.
class MeshAssembler {
 public:
  // Collects into a wire mesh of its own (mesh()).
  MeshAssembler() : MeshAssembler(own_target_) {}
  // `target` must outlive the assembler.
  explicit MeshAssembler(AssemblyTarget& target,
                         std::int64_t max_elements = std::numeric_limits<std::int64_t>::max())
      : target_(target), max_elements_(max_elements) {}
  MeshAssembler(const MeshAssembler&) = delete;
  MeshAssembler& operator=(const MeshAssembler&) = delete;

  absl::Status Add(const v1::MeshChunk& chunk) { return Add(chunk.mesh()); }
  absl::Status Add(const v1::Mesh& part);

  // Values received per field, whole or not (the wire's counts, e.g. for expected_size).
  std::int64_t coordinate_values() const { return coordinate_values_; }
  std::int64_t nodes() const { return coordinate_values_ / 3; }
  std::int64_t elements() const;  // complete elements so far
  std::int64_t node_ids() const { return node_ids_; }
  std::int64_t element_ids() const { return element_ids_; }
  // Encoded bytes of the parts so far.
  std::int64_t encoded_bytes() const { return encoded_bytes_; }

  // INVALID_ARGUMENT naming the field when a node or element was left incomplete.
  absl::Status CheckWhole() const;
  // INVALID_ARGUMENT naming the first field whose count differs from the declared size.
  absl::Status CheckExpectedSize(const v1::MeshSize& expected) const;
  // For results: FAILED_PRECONDITION (naming both counts) unless the coordinates of `nodes` nodes
  // arrived.
  absl::Status CheckComplete(std::uint64_t nodes) const;

  // The collecting assembler's mesh.
  v1::Mesh& mesh() { return own_target_.mesh(); }

 private:
  WireMeshTarget own_target_;
  AssemblyTarget& target_;
  const std::int64_t max_elements_;
  std::int64_t coordinate_values_ = 0;
  std::array<std::int64_t, kWireElementGroupCount> element_values_{};
  std::int64_t node_ids_ = 0;
  std::int64_t element_ids_ = 0;
  std::int64_t encoded_bytes_ = 0;
  // Values of a node or element not yet whole.
  std::vector<double> partial_node_;
  std::array<std::vector<std::uint32_t>, kWireElementGroupCount> partial_elements_;
};

// A declared size (SmoothHeader.expected_size) over the limit is refused before the upload.
absl::Status CheckDeclaredSize(const v1::MeshSize& expected, std::int64_t max_elements);

}  // namespace getme::wire
