#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include "getme/mesh/mesh.h"
#include "getme/v1/mesh.pb.h"
#include "getme/v1/smoother.pb.h"
#include "getme_wire/mesh_ids.h"

namespace getme::wire {

// About 1 MB per message: far below gRPC's 4 MB default limit, large enough that per-message
// overhead does not matter.
inline constexpr std::size_t kDefaultChunkBytes = std::size_t{1} << 20;

// How a chunker cuts: at most about `bytes` encoded bytes per chunk and, when max_nodes > 0, at
// most that many nodes' coordinates (and node ids) per chunk.
struct ChunkLimits {
  std::size_t bytes = kDefaultChunkBytes;
  std::int64_t max_nodes = 0;
};
// ResultOptions.nodes_per_chunk as limits: 0 is the server's choice (about 1 MB), a caller's
// choice is capped at 100,000 nodes so a chunk stays below gRPC's default 4 MB.
ChunkLimits ResultChunkLimits(std::uint32_t nodes_per_chunk);

class WireMeshSource;

// The one chunker, for uploads (client) and results (server) alike: cuts a mesh into MeshChunk
// messages field by field in the order of mesh.proto, keeping whole nodes (3 coordinates) and
// whole elements together, so every chunk is meaningful on its own. Concatenating the chunks'
// fields gives the mesh back. A mesh with no data at all still yields one (empty) chunk, so the
// server sees it and can name the empty mesh.
class MeshChunker {
 public:
  // A wire mesh (an upload). `mesh` must outlive the chunker.
  explicit MeshChunker(const v1::Mesh& mesh, std::size_t chunk_bytes = kDefaultChunkBytes);
  // An engine mesh in the wire's form (VTK node order, elements grouped by type as numbered on
  // the wire) with the caller's ids and fixed-node list; coordinates_only sends the coordinates
  // and node ids alone. `mesh` and `ids` must outlive the chunker.
  MeshChunker(const Mesh& mesh, const WireMeshIds& ids, bool coordinates_only, ChunkLimits limits);
  ~MeshChunker();

  // Fills `chunk` with the next part; false when every part has been handed out.
  bool Next(v1::MeshChunk& chunk);

 private:
  std::unique_ptr<const WireMeshSource> source_;
  ChunkLimits limits_;
  int field_ = 0;              // next field of mesh.proto's order
  std::int64_t position_ = 0;  // next value of that field
  bool handed_out_any_ = false;
};

}  // namespace getme::wire
