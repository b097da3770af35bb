// Chunked transfer: chunks stay under their byte budget, keep nodes and elements whole, and
// concatenate back to the original mesh; the assembler checks completeness.

#include "getme_wire/mesh_chunker.h"

#include <gtest/gtest.h>

#include <vector>

#include "getme_wire/mesh_assembler.h"
#include "getme_wire/mesh_fields.h"

namespace getme::wire {
namespace {

v1::Mesh SampleMesh(int nodes, int tets, int hexes) {
  v1::Mesh mesh;
  for (int i = 0; i < 3 * nodes; ++i) mesh.add_coordinates(0.5 * i);
  for (int i = 0; i < 4 * tets; ++i) mesh.add_tetrahedra(i % nodes);
  for (int i = 0; i < 8 * hexes; ++i) mesh.add_hexahedra((7 * i) % nodes);
  for (int i = 0; i < nodes; i += 3) mesh.add_fixed_nodes(i);
  for (int i = 0; i < nodes; ++i) mesh.add_node_ids(1000 + i);
  return mesh;
}

std::vector<v1::MeshChunk> AllChunks(const v1::Mesh& mesh, std::size_t bytes) {
  MeshChunker chunker(mesh, bytes);
  std::vector<v1::MeshChunk> chunks;
  v1::MeshChunk chunk;
  while (chunker.Next(chunk)) chunks.push_back(chunk);
  return chunks;
}

TEST(MeshChunker, ChunksConcatenateToTheMeshAndStayUnderBudget) {
  const v1::Mesh mesh = SampleMesh(20000, 5000, 3000);
  constexpr std::size_t kBudget = 64 * 1024;
  const std::vector<v1::MeshChunk> chunks = AllChunks(mesh, kBudget);
  // 480 kB of coordinates alone: several chunks.
  ASSERT_GT(chunks.size(), 8u);
  v1::Mesh joined;
  for (const v1::MeshChunk& chunk : chunks) {
    EXPECT_LE(chunk.ByteSizeLong(), kBudget + 64) << "a chunk exceeds its budget";
    EXPECT_EQ(chunk.mesh().coordinates_size() % 3, 0) << "a node was split across chunks";
    EXPECT_EQ(chunk.mesh().tetrahedra_size() % 4, 0) << "a tetrahedron was split";
    EXPECT_EQ(chunk.mesh().hexahedra_size() % 8, 0) << "a hexahedron was split";
    joined.MergeFrom(chunk.mesh());
  }
  EXPECT_EQ(joined.SerializeAsString(), mesh.SerializeAsString());
}

TEST(MeshChunker, EmptyMeshStillSendsOneChunk) {
  const std::vector<v1::MeshChunk> chunks = AllChunks(v1::Mesh(), kDefaultChunkBytes);
  ASSERT_EQ(chunks.size(), 1u);
  EXPECT_EQ(chunks[0].mesh().ByteSizeLong(), 0u);
}

TEST(MeshChunker, SmallMeshIsOneChunk) {
  const v1::Mesh mesh = SampleMesh(10, 2, 1);
  const std::vector<v1::MeshChunk> chunks = AllChunks(mesh, kDefaultChunkBytes);
  ASSERT_EQ(chunks.size(), 1u);
  EXPECT_EQ(chunks[0].mesh().SerializeAsString(), mesh.SerializeAsString());
}

TEST(MeshChunker, SizeOfCountsNodesAndElements) {
  const v1::MeshSize size = SizeOf(SampleMesh(30, 7, 5));
  EXPECT_EQ(size.nodes(), 30u);
  EXPECT_EQ(size.tetrahedra(), 7u);
  EXPECT_EQ(size.hexahedra(), 5u);
  EXPECT_EQ(size.wedges(), 0u);
  EXPECT_EQ(size.pyramids(), 0u);
}

TEST(MeshAssembler, NamesMissingCoordinates) {
  MeshAssembler assembler;
  v1::MeshChunk chunk;
  for (int i = 0; i < 6; ++i) chunk.mutable_mesh()->add_coordinates(i);
  ASSERT_TRUE(assembler.Add(chunk).ok());
  EXPECT_TRUE(assembler.CheckComplete(2).ok());
  const absl::Status incomplete = assembler.CheckComplete(3);
  EXPECT_EQ(incomplete.code(), absl::StatusCode::kFailedPrecondition);
  EXPECT_NE(incomplete.message().find("6 coordinates"), std::string::npos) << incomplete;
  EXPECT_NE(incomplete.message().find("3 nodes"), std::string::npos) << incomplete;
}

}  // namespace
}  // namespace getme::wire
