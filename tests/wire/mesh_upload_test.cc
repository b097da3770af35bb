// The one chunker and the one assembler end to end: an engine mesh cut into result chunks
// (whatever the limits) and streamed back through wire::MeshUpload is the same mesh, element for
// element; an upload whose chunks split nodes and elements, or interleave element types, is
// numbered as mesh.proto says (all tetrahedra, then hexahedra, wedges, pyramids); errors use the
// wire's words.

#include "getme_wire/mesh_upload.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <vector>

#include "getme/meshgen/hybrid_block.h"
#include "getme_wire/engine_mesh.h"
#include "getme_wire/mesh_chunker.h"

namespace getme::wire {
namespace {

using ::testing::HasSubstr;

Mesh Hybrid() {
  absl::StatusOr<Mesh> mesh = meshgen::HybridBlock(3, 3, 4, 0.1, 7);
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  return *std::move(mesh);
}

// The mesh of `wire` as a list of (type, nodes) in element-number order, VTK node order.
std::vector<std::vector<std::uint32_t>> ElementsInWireOrder(const v1::Mesh& wire) {
  std::vector<std::vector<std::uint32_t>> elements;
  for (int group = 0; group < kWireElementGroupCount; ++group) {
    const Indices& field = Connectivity(wire, group);
    const int count = NodeCount(kWireElementGroups[group].type);
    for (int begin = 0; begin < field.size(); begin += count) {
      elements.emplace_back(field.begin() + begin, field.begin() + begin + count);
      elements.back().push_back(static_cast<std::uint32_t>(group));
    }
  }
  return elements;
}

TEST(MeshUpload, ResultChunksStreamBackToTheSameMeshForAnyLimits) {
  const Mesh mesh = Hybrid();
  const v1::Mesh whole = ToWireMesh(mesh);
  ASSERT_GT(whole.wedges_size(), 0);
  ASSERT_GT(whole.pyramids_size(), 0);
  WireMeshIds ids;
  ids.fixed_nodes = {whole.fixed_nodes().begin(), whole.fixed_nodes().end()};
  for (std::int64_t n = 0; n < mesh.node_count(); ++n) ids.node_ids.push_back(5000 + n);
  for (const std::uint32_t nodes_per_chunk : {0u, 1u, 7u, 200u}) {
    MeshChunker chunker(mesh, ids, /*coordinates_only=*/false, ResultChunkLimits(nodes_per_chunk));
    MeshUpload upload(1'000'000);
    v1::MeshChunk chunk;
    int chunks = 0;
    while (chunker.Next(chunk)) {
      ++chunks;
      if (nodes_per_chunk > 0) {
        EXPECT_LE(chunk.mesh().coordinates_size(), 3 * nodes_per_chunk);
      }
      ASSERT_TRUE(upload.Add(chunk).ok());
    }
    if (nodes_per_chunk > 0) {
      EXPECT_GE(chunks, mesh.node_count() / nodes_per_chunk);
    }
    absl::StatusOr<UploadedMesh> back = std::move(upload).Finish();
    ASSERT_TRUE(back.ok()) << back.status();
    EXPECT_EQ(ToWireMesh(back->mesh).SerializeAsString(), whole.SerializeAsString());
    EXPECT_EQ(back->ids.node_ids, ids.node_ids);
    EXPECT_EQ(back->ids.fixed_nodes, ids.fixed_nodes);
  }
}

TEST(MeshUpload, CoordinatesOnlyResultsCarryNoTopology) {
  const Mesh mesh = Hybrid();
  WireMeshIds ids;
  ids.element_ids.assign(mesh.element_count(), 3);
  MeshChunker chunker(mesh, ids, /*coordinates_only=*/true, ResultChunkLimits(0));
  MeshAssembler collected;
  v1::MeshChunk chunk;
  while (chunker.Next(chunk)) ASSERT_TRUE(collected.Add(chunk).ok());
  EXPECT_EQ(collected.mesh().coordinates_size(), 3 * mesh.node_count());
  EXPECT_EQ(WireElementCount(collected.mesh()), 0);
  EXPECT_EQ(collected.mesh().element_ids_size(), 0);
}

// Sends every value of `values` in a part of its own, into `field` (a v1::Mesh mutable_ getter).
template <typename Field, typename Values>
void SendOneByOne(MeshUpload& upload, Field field, const Values& values) {
  for (const auto value : values) {
    v1::Mesh part;
    (part.*field)()->Add(value);
    ASSERT_TRUE(upload.Add(part).ok());
  }
}

// The hybrid block's nodes and elements, every value in a part of its own, hexahedra before
// tetrahedra, pyramids before wedges.
void SendHybridOneByOne(MeshUpload& upload, const v1::Mesh& whole) {
  SendOneByOne(upload, &v1::Mesh::mutable_coordinates, whole.coordinates());
  SendOneByOne(upload, &v1::Mesh::mutable_hexahedra, whole.hexahedra());
  SendOneByOne(upload, &v1::Mesh::mutable_tetrahedra, whole.tetrahedra());
  SendOneByOne(upload, &v1::Mesh::mutable_pyramids, whole.pyramids());
  SendOneByOne(upload, &v1::Mesh::mutable_wedges, whole.wedges());
}

TEST(MeshUpload, SplitNodesAndElementsAndInterleavedTypesKeepTheWireNumbering) {
  const v1::Mesh whole = ToWireMesh(Hybrid());
  MeshUpload upload(1'000'000);
  SendHybridOneByOne(upload, whole);
  SendOneByOne(upload, &v1::Mesh::mutable_fixed_nodes, whole.fixed_nodes());
  absl::StatusOr<UploadedMesh> back = std::move(upload).Finish();
  ASSERT_TRUE(back.ok()) << back.status();
  EXPECT_EQ(ElementsInWireOrder(ToWireMesh(back->mesh)), ElementsInWireOrder(whole));
  // Element numbers are the wire's: the first hexahedron follows the last tetrahedron.
  const std::int64_t tetrahedra = whole.tetrahedra_size() / 4;
  EXPECT_EQ(back->mesh.type(static_cast<ElementId>(tetrahedra - 1)), ElementType::kTetrahedron);
  EXPECT_EQ(back->mesh.type(static_cast<ElementId>(tetrahedra)), ElementType::kHexahedron);
}

TEST(MeshUpload, SurfaceGroupTagsBecomeDenseGroupsTrianglesFirst) {
  // Tags 40, 7, 40 on triangles and 9 on a quad: groups in ascending tag order from 1 (7 → 1,
  // 9 → 2, 40 → 3), group 0 left to the faces not listed; every value sent in a part of its own.
  MeshUpload upload(1'000'000);
  SendHybridOneByOne(upload, ToWireMesh(Hybrid()));
  SendOneByOne(upload, &v1::Mesh::mutable_quad_groups, std::vector<std::uint32_t>{9});
  SendOneByOne(upload, &v1::Mesh::mutable_group_quads, std::vector<std::uint32_t>{4, 5, 6, 7});
  SendOneByOne(upload, &v1::Mesh::mutable_group_triangles,
               std::vector<std::uint32_t>{0, 1, 2, 1, 2, 3, 2, 3, 0});
  SendOneByOne(upload, &v1::Mesh::mutable_triangle_groups, std::vector<std::uint32_t>{40, 7, 40});
  absl::StatusOr<UploadedMesh> back = std::move(upload).Finish();
  ASSERT_TRUE(back.ok()) << back.status();
  ASSERT_EQ(back->surface_groups.size(), 4u);
  const int expected_groups[] = {3, 1, 3, 2};
  const int expected_sizes[] = {3, 3, 3, 4};
  for (int f = 0; f < 4; ++f) {
    EXPECT_EQ(back->surface_groups[f].group, expected_groups[f]) << "face " << f;
    EXPECT_EQ(back->surface_groups[f].size, expected_sizes[f]) << "face " << f;
  }
  EXPECT_EQ(back->surface_groups[1].nodes[0], 1);
  EXPECT_EQ(back->surface_groups[3].nodes[3], 7);
}

TEST(MeshUpload, AHalfElementAtTheEndNamesItsField) {
  v1::Mesh wire = ToWireMesh(Hybrid());
  wire.add_pyramids(0);
  absl::StatusOr<UploadedMesh> mesh = ToEngineMesh(wire, 1'000'000);
  ASSERT_FALSE(mesh.ok());
  EXPECT_EQ(mesh.status().code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(mesh.status().message(), HasSubstr("mesh.pyramids has"));
  EXPECT_THAT(mesh.status().message(), HasSubstr("not a multiple of 5"));
}

TEST(MeshUpload, RepeatedWedgeNodeIsNamedInVtkPositions) {
  v1::Mesh wire = ToWireMesh(Hybrid());
  // VTK positions 1 and 2 are paper positions 2 and 1: the message must give the wire's.
  const int tetrahedra = wire.tetrahedra_size() / 4;
  const int hexahedra = wire.hexahedra_size() / 8;
  wire.set_wedges(2, wire.wedges(1));
  absl::StatusOr<UploadedMesh> mesh = ToEngineMesh(wire, 1'000'000);
  ASSERT_FALSE(mesh.ok());
  EXPECT_THAT(mesh.status().message(),
              HasSubstr(absl::StrCat("wedge 0 (element ", tetrahedra + hexahedra, "): node ",
                                     wire.wedges(1), " appears twice (positions 1 and 2)")));
}

TEST(MeshUpload, RefusesAsSoonAsTheElementLimitPasses) {
  const v1::Mesh wire = ToWireMesh(Hybrid());
  MeshUpload upload(WireElementCount(wire) / 4);
  MeshChunker chunker(wire, 256);
  v1::MeshChunk chunk;
  absl::Status status;
  int parts = 0;
  while (status.ok() && chunker.Next(chunk)) {
    status = upload.Add(chunk);
    ++parts;
  }
  EXPECT_EQ(status.code(), absl::StatusCode::kInvalidArgument);
  EXPECT_THAT(status.message(), HasSubstr("(--max_elements)"));
  EXPECT_TRUE(chunker.Next(chunk)) << "refused only after all " << parts << " parts";
}

}  // namespace
}  // namespace getme::wire
