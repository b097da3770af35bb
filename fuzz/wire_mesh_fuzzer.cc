// libFuzzer target: the server's upload path without the network. The input is a stream of
// SmoothRequest messages, each preceded by its length as a varint (what gRPC hands the handler one
// by one); they go through the same steps as SmootherService::Smooth: header checks, chunks
// streamed into wire::MeshUpload against max_elements, expected_size, parameters, the engine
// mesh's build. The fuzzer keeps its own plain concatenation of the chunks to check the result
// against. A mesh the server accepts is then sent back as result chunks (wire::MeshChunker) and
// reassembled as a client does (wire::MeshAssembler).
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "absl/strings/str_cat.h"
#include "fuzz_check.h"
#include "getme/v1/smoother.pb.h"
#include "getme_wire/mesh_assembler.h"
#include "getme_wire/mesh_chunker.h"
#include "getme_wire/mesh_fields.h"
#include "getme_wire/mesh_upload.h"
#include "getme_wire/params.h"
#include "google/protobuf/io/coded_stream.h"

namespace getme::fuzz {
namespace {

// Small enough that the limit is reached by fuzzed inputs, as the server's is by large uploads.
constexpr std::int64_t kMaxElements = 5'000;

// What ReadUpload in smoother_service.cc does with each message; false = the upload is refused.
// `mesh` is the plain concatenation of the chunks (the fuzzer's own view of the upload).
bool ReadUpload(absl::string_view bytes, v1::SmoothHeader& header, wire::MeshUpload& upload,
                v1::Mesh& mesh) {
  google::protobuf::io::CodedInputStream input(reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                               static_cast<int>(bytes.size()));
  v1::SmoothRequest request;
  for (std::int64_t message = 0; !input.ExpectAtEnd(); ++message) {
    std::uint32_t length = 0;
    if (!input.ReadVarint32(&length) || length > bytes.size()) return false;
    const auto limit = input.PushLimit(static_cast<int>(length));
    if (!request.ParseFromCodedStream(&input) || !input.ConsumedEntireMessage()) return false;
    input.PopLimit(limit);
    if (request.has_header()) {
      if (message > 0) return false;
      header = request.header();
      if (header.has_expected_size() &&
          !wire::CheckDeclaredSize(header.expected_size(), kMaxElements).ok()) {
        return false;
      }
    } else if (request.has_chunk()) {
      mesh.MergeFrom(request.chunk().mesh());
      if (!upload.Add(request.chunk()).ok()) {
        Check(wire::WireElementCount(mesh) > kMaxElements,
              "MeshUpload refused a chunk within the limit");
        return false;
      }
    } else {
      return false;
    }
  }
  return !header.has_expected_size() ||
         upload.assembler().CheckExpectedSize(header.expected_size()).ok();
}

bool SameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

void CheckEngineMesh(const v1::Mesh& wire, const Mesh& mesh) {
  Check(mesh.node_count() == wire.coordinates_size() / 3, "ToEngineMesh: wrong node count");
  Check(mesh.element_count() == wire::WireElementCount(wire), "ToEngineMesh: wrong element count");
  for (std::int64_t node = 0; node < mesh.node_count(); ++node) {
    const int i = static_cast<int>(3 * node);
    Check(SameBits(mesh.x()[node], wire.coordinates(i)) &&
              SameBits(mesh.y()[node], wire.coordinates(i + 1)) &&
              SameBits(mesh.z()[node], wire.coordinates(i + 2)),
          absl::StrCat("ToEngineMesh: node ", node, " moved"));
  }
  std::vector<bool> fixed(mesh.node_count(), false);
  for (const std::uint32_t node : wire.fixed_nodes()) fixed[node] = true;
  for (std::int64_t node = 0; node < mesh.node_count(); ++node) {
    Check(mesh.is_fixed(static_cast<NodeId>(node)) == fixed[node],
          absl::StrCat("ToEngineMesh: node ", node, " has the wrong fixed flag"));
  }
  Check(mesh.element_count(ElementType::kTetrahedron) == wire.tetrahedra_size() / 4 &&
            mesh.element_count(ElementType::kHexahedron) == wire.hexahedra_size() / 8 &&
            mesh.element_count(ElementType::kPrism) == wire.wedges_size() / 6 &&
            mesh.element_count(ElementType::kPyramid) == wire.pyramids_size() / 5,
        "ToEngineMesh: wrong element count of a type");
}

// The result chunks reassembled by the client's assembler give back the coordinates and the
// topology.
void CheckResultChunks(const v1::Mesh& wire, const wire::UploadedMesh& uploaded,
                       bool coordinates_only, std::uint32_t nodes_per_chunk) {
  wire::MeshChunker chunker(uploaded.mesh, uploaded.ids, coordinates_only,
                            wire::ResultChunkLimits(nodes_per_chunk));
  wire::MeshAssembler assembler;
  v1::MeshChunk chunk;
  while (chunker.Next(chunk)) CheckOk(assembler.Add(chunk), "MeshAssembler of a result chunk");
  const v1::Mesh& received = assembler.mesh();
  Check(received.coordinates_size() == wire.coordinates_size(),
        "result chunks: wrong number of coordinates");
  for (int i = 0; i < wire.coordinates_size(); ++i) {
    Check(SameBits(received.coordinates(i), wire.coordinates(i)),
          absl::StrCat("result chunks: coordinate ", i, " changed"));
  }
  const bool with_ids = wire.node_ids_size() == wire.coordinates_size() / 3;
  Check(received.node_ids_size() == (with_ids ? wire.node_ids_size() : 0),
        "result chunks: wrong number of node ids");
  if (coordinates_only) return;
  // Field by field: unknown fields of the upload are not part of the mesh and are not sent back.
  const auto same = [](const auto& a, const auto& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  };
  Check(same(received.tetrahedra(), wire.tetrahedra()) &&
            same(received.hexahedra(), wire.hexahedra()) &&
            same(received.wedges(), wire.wedges()) && same(received.pyramids(), wire.pyramids()),
        "result chunks: the connectivity changed");
  Check(same(received.fixed_nodes(), wire.fixed_nodes()), "result chunks: the fixed nodes changed");
  Check(same(received.element_ids(), wire.element_ids()), "result chunks: the element ids changed");
}

}  // namespace
}  // namespace getme::fuzz

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  getme::fuzz::QuietLogging();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace getme;
  v1::SmoothHeader header;
  v1::Mesh wire;
  wire::MeshUpload upload(fuzz::kMaxElements);
  if (!fuzz::ReadUpload(absl::string_view(reinterpret_cast<const char*>(data), size), header,
                        upload, wire)) {
    return 0;
  }
  absl::StatusOr<SmoothingParams> params = wire::ToEngineParams(header.parameters(), 1);
  if (params.ok()) fuzz::CheckOk(params->Validate(), "Validate of ToEngineParams' result");
  absl::StatusOr<wire::UploadedMesh> mesh = std::move(upload).Finish();
  if (!fuzz::Accepted(mesh.status(), "MeshUpload")) return 0;
  fuzz::CheckEngineMesh(wire, mesh->mesh);
  // Small chunks, so that inputs of a few nodes take more than one.
  const std::uint32_t nodes_per_chunk = header.result_options().nodes_per_chunk() % 8;
  fuzz::CheckResultChunks(wire, *mesh, /*coordinates_only=*/false, nodes_per_chunk);
  fuzz::CheckResultChunks(wire, *mesh, /*coordinates_only=*/true, nodes_per_chunk);
  return 0;
}
