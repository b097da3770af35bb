// libFuzzer target: the server's upload path without the network. The input is a stream of
// SmoothRequest messages, each preceded by its length as a varint (what gRPC hands the handler one
// by one); they go through the same steps as SmootherService::Smooth: header checks, chunk
// accumulation against max_elements, expected_size, parameters, ToEngineMesh. A mesh the server
// accepts is then sent back as result chunks and reassembled as a client does.
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "absl/strings/str_cat.h"
#include "fuzz_check.h"
#include "getme/v1/smoother.pb.h"
#include "getme_server/mesh_conversion.h"
#include "getme_server/params_conversion.h"
#include "google/protobuf/io/coded_stream.h"

namespace getme::fuzz {
namespace {

// Small enough that the limit is reached by fuzzed inputs, as the server's is by large uploads.
constexpr std::int64_t kMaxElements = 5'000;

// What ReadUpload in smoother_service.cc does with each message; false = the upload is refused.
bool ReadUpload(absl::string_view bytes, v1::SmoothHeader& header, v1::Mesh& mesh) {
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
          !server::CheckDeclaredSize(header.expected_size(), kMaxElements).ok()) {
        return false;
      }
    } else if (request.has_chunk()) {
      if (!server::AppendMeshChunk(request.chunk(), kMaxElements, mesh).ok()) {
        Check(server::WireElementCount(mesh) > kMaxElements,
              "AppendMeshChunk refused a chunk within the limit");
        return false;
      }
    } else {
      return false;
    }
  }
  return !header.has_expected_size() ||
         server::CheckExpectedSize(header.expected_size(), mesh).ok();
}

bool SameBits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

void CheckEngineMesh(const v1::Mesh& wire, const Mesh& mesh) {
  Check(mesh.node_count() == wire.coordinates_size() / 3, "ToEngineMesh: wrong node count");
  Check(mesh.element_count() == server::WireElementCount(wire),
        "ToEngineMesh: wrong element count");
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

// The result chunks reassembled by AppendMeshChunk give back the coordinates and the topology.
void CheckResultChunks(const v1::Mesh& wire, const Mesh& mesh, bool coordinates_only,
                       std::uint32_t nodes_per_chunk) {
  v1::Mesh received;
  const bool sent = server::EmitResultChunks(
      wire, mesh, coordinates_only, nodes_per_chunk, [&](const v1::MeshChunk& chunk) {
        CheckOk(server::AppendMeshChunk(chunk, kMaxElements, received),
                "AppendMeshChunk of a result chunk");
        return true;
      });
  Check(sent, "EmitResultChunks stopped though every chunk was taken");
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
  if (!fuzz::ReadUpload(absl::string_view(reinterpret_cast<const char*>(data), size), header,
                        wire)) {
    return 0;
  }
  absl::StatusOr<SmoothingParams> params = server::ToEngineParams(header.parameters(), 1);
  if (params.ok()) fuzz::CheckOk(params->Validate(), "Validate of ToEngineParams' result");
  absl::StatusOr<Mesh> mesh = server::ToEngineMesh(wire, fuzz::kMaxElements);
  if (!fuzz::Accepted(mesh.status(), "ToEngineMesh")) return 0;
  fuzz::CheckEngineMesh(wire, *mesh);
  // Small chunks, so that inputs of a few nodes take more than one.
  const std::uint32_t nodes_per_chunk = header.result_options().nodes_per_chunk() % 8;
  fuzz::CheckResultChunks(wire, *mesh, /*coordinates_only=*/false, nodes_per_chunk);
  fuzz::CheckResultChunks(wire, *mesh, /*coordinates_only=*/true, nodes_per_chunk);
  return 0;
}
