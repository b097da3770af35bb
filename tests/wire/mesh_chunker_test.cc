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
  // Surface groups: a triangle and a quad per hundred nodes.
  for (int f = 0; f < nodes / 100; ++f) {
    for (int k = 0; k < 3; ++k) mesh.add_group_triangles((11 * f + k) % nodes);
    for (int k = 0; k < 4; ++k) mesh.add_group_quads((13 * f + k) % nodes);
    mesh.add_triangle_groups(1 + f % 5);
    mesh.add_quad_groups(7 + f % 3);
  }
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
    EXPECT_EQ(chunk.mesh().group_triangles_size() % 3, 0) << "a grouped triangle was split";
    EXPECT_EQ(chunk.mesh().group_quads_size() % 4, 0) << "a grouped quad was split";
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
