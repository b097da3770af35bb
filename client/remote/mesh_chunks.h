#pragma once

#include <cstddef>
#include <cstdint>

#include "absl/status/status.h"
#include "getme/v1/mesh.pb.h"
#include "getme/v1/smoother.pb.h"

namespace getme::remote {

// About 1 MB per message: far below gRPC's 4 MB default limit, large enough that per-message
// overhead does not matter.
inline constexpr std::size_t kDefaultChunkBytes = std::size_t{1} << 20;

// The sizes a mesh's chunks add up to (SmoothHeader.expected_size).
v1::MeshSize SizeOf(const v1::Mesh& mesh);

// Cuts a mesh into MeshChunk messages of at most about `chunk_bytes` encoded bytes each, field by
// field in declaration order, keeping whole nodes (3 coordinates) and whole elements together so
// every chunk is meaningful on its own. Concatenating the chunks' fields gives the mesh back.
// A mesh with no data at all still yields one (empty) chunk, so the server sees it and can name
// the empty mesh.
class MeshChunker {
 public:
  explicit MeshChunker(const v1::Mesh& mesh, std::size_t chunk_bytes = kDefaultChunkBytes);

  // Fills `chunk` with the next part; false when every part has been handed out.
  bool Next(v1::MeshChunk& chunk);

 private:
  const v1::Mesh& mesh_;
  std::size_t chunk_bytes_;
  int field_ = 0;              // index into the field table in mesh_chunks.cc
  std::int64_t position_ = 0;  // next value of that field
  bool handed_out_any_ = false;
};

// Collects result chunks: appends each chunk's fields to the mesh gathered so far.
class MeshAssembler {
 public:
  void Add(const v1::MeshChunk& chunk) { mesh_.MergeFrom(chunk.mesh()); }
  // FailedPrecondition (naming both counts) unless the coordinates of `nodes` nodes arrived.
  absl::Status CheckComplete(std::uint64_t nodes) const;
  v1::Mesh& mesh() { return mesh_; }

 private:
  v1::Mesh mesh_;
};

}  // namespace getme::remote
