#include "server_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <thread>

#include "absl/time/clock.h"
#include "getme/meshgen/hybrid_block.h"
#include "getme/meshgen/jittered_tet_block.h"
#include "grpcpp/create_channel.h"
#include "grpcpp/security/credentials.h"
#include "gtest/gtest.h"

namespace getme::server::testing {
namespace {

constexpr std::array<ElementType, 4> kWireOrder = {ElementType::kTetrahedron,
                                                   ElementType::kHexahedron, ElementType::kPrism,
                                                   ElementType::kPyramid};
constexpr std::array<int, 6> kPrismToWedge = {0, 2, 1, 3, 5, 4};

google::protobuf::RepeatedField<std::uint32_t>* WireField(v1::Mesh& mesh, ElementType type) {
  switch (type) {
    case ElementType::kTetrahedron:
      return mesh.mutable_tetrahedra();
    case ElementType::kHexahedron:
      return mesh.mutable_hexahedra();
    case ElementType::kPrism:
      return mesh.mutable_wedges();
    case ElementType::kPyramid:
      return mesh.mutable_pyramids();
  }
  return nullptr;
}

}  // namespace

ServerOptions TestOptions() {
  ServerOptions options;
  options.listen = "127.0.0.1:0";
  options.workers = 2;
  options.threads_per_job = 1;
  options.max_queued_jobs = 8;
  options.progress_interval = absl::ZeroDuration();
  options.shutdown_grace = absl::Seconds(5);
  return options;
}

TestServer StartTestServer(const ServerOptions& options) {
  TestServer test;
  auto server = SmootherServer::Start(options);
  EXPECT_TRUE(server.ok()) << server.status();
  if (!server.ok()) return test;
  test.server = *std::move(server);
  grpc::ChannelArguments arguments;
  arguments.SetMaxReceiveMessageSize(4 << 20);  // gRPC's default: results must come in chunks
  test.channel = grpc::CreateCustomChannel(absl::StrCat("127.0.0.1:", test.server->port()),
                                           grpc::InsecureChannelCredentials(), arguments);
  test.stub = v1::Smoother::NewStub(test.channel);
  return test;
}

v1::Mesh ToWire(const Mesh& mesh) {
  v1::Mesh wire;
  for (std::int64_t n = 0; n < mesh.node_count(); ++n) {
    wire.add_coordinates(mesh.x()[n]);
    wire.add_coordinates(mesh.y()[n]);
    wire.add_coordinates(mesh.z()[n]);
    if (mesh.is_fixed(static_cast<NodeId>(n))) wire.add_fixed_nodes(static_cast<std::uint32_t>(n));
  }
  for (ElementType type : kWireOrder) {
    for (std::int64_t e = 0; e < mesh.element_count(); ++e) {
      if (mesh.type(static_cast<ElementId>(e)) != type) continue;
      auto nodes = mesh.element_nodes(static_cast<ElementId>(e));
      for (int k = 0; k < NodeCount(type); ++k) {
        const int source = type == ElementType::kPrism ? kPrismToWedge[k] : k;
        WireField(wire, type)->Add(static_cast<std::uint32_t>(nodes[source]));
      }
    }
  }
  return wire;
}

Mesh FromWire(const v1::Mesh& wire) {
  MeshBuilder builder;
  for (int i = 0; i + 2 < wire.coordinates_size(); i += 3) {
    builder.AddNode(wire.coordinates(i), wire.coordinates(i + 1), wire.coordinates(i + 2));
  }
  for (std::uint32_t node : wire.fixed_nodes()) builder.SetFixed(static_cast<NodeId>(node));
  v1::Mesh copy = wire;
  for (ElementType type : kWireOrder) {
    const auto& field = *WireField(copy, type);
    const int count = NodeCount(type);
    for (int begin = 0; begin + count <= field.size(); begin += count) {
      std::array<std::int64_t, 8> nodes{};
      // The wedge permutation is its own inverse.
      for (int k = 0; k < count; ++k) {
        nodes[k] = field[begin + (type == ElementType::kPrism ? kPrismToWedge[k] : k)];
      }
      builder.AddElement(type, std::span<const std::int64_t>(nodes.data(), count));
    }
  }
  auto mesh = std::move(builder).Build();
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  return *std::move(mesh);
}

std::vector<v1::MeshChunk> SplitIntoChunks(const v1::Mesh& mesh, std::size_t bytes) {
  std::vector<v1::MeshChunk> chunks;
  auto slice = [&](const auto& field, auto target, std::size_t item_bytes) {
    const int per_chunk = static_cast<int>(std::max<std::size_t>(1, bytes / item_bytes));
    for (int begin = 0; begin < field.size(); begin += per_chunk) {
      v1::MeshChunk chunk;
      const int end = std::min(field.size(), begin + per_chunk);
      target(*chunk.mutable_mesh())->Add(field.begin() + begin, field.begin() + end);
      chunks.push_back(std::move(chunk));
    }
  };
  slice(
      mesh.coordinates(), [](v1::Mesh& m) { return m.mutable_coordinates(); }, 8);
  slice(
      mesh.tetrahedra(), [](v1::Mesh& m) { return m.mutable_tetrahedra(); }, 5);
  slice(
      mesh.hexahedra(), [](v1::Mesh& m) { return m.mutable_hexahedra(); }, 5);
  slice(
      mesh.wedges(), [](v1::Mesh& m) { return m.mutable_wedges(); }, 5);
  slice(
      mesh.pyramids(), [](v1::Mesh& m) { return m.mutable_pyramids(); }, 5);
  slice(
      mesh.fixed_nodes(), [](v1::Mesh& m) { return m.mutable_fixed_nodes(); }, 5);
  slice(
      mesh.node_ids(), [](v1::Mesh& m) { return m.mutable_node_ids(); }, 10);
  slice(
      mesh.element_ids(), [](v1::Mesh& m) { return m.mutable_element_ids(); }, 10);
  slice(
      mesh.group_triangles(), [](v1::Mesh& m) { return m.mutable_group_triangles(); }, 5);
  slice(
      mesh.group_quads(), [](v1::Mesh& m) { return m.mutable_group_quads(); }, 5);
  slice(
      mesh.triangle_groups(), [](v1::Mesh& m) { return m.mutable_triangle_groups(); }, 5);
  slice(
      mesh.quad_groups(), [](v1::Mesh& m) { return m.mutable_quad_groups(); }, 5);
  return chunks;
}

std::vector<v1::SmoothRequest> SmoothRequests(const v1::Mesh& mesh,
                                              const v1::SmoothingParameters& parameters,
                                              const v1::ResultOptions& result_options) {
  std::vector<v1::SmoothRequest> requests(1);
  *requests[0].mutable_header()->mutable_parameters() = parameters;
  *requests[0].mutable_header()->mutable_result_options() = result_options;
  for (v1::MeshChunk& chunk : SplitIntoChunks(mesh)) {
    v1::SmoothRequest request;
    *request.mutable_chunk() = std::move(chunk);
    requests.push_back(std::move(request));
  }
  return requests;
}

namespace {

template <typename Reader>
void ReadSmoothResponses(Reader& reader, SmoothOutcome& outcome) {
  v1::SmoothResponse response;
  while (reader.Read(&response)) {
    outcome.largest_message_bytes =
        std::max(outcome.largest_message_bytes, response.ByteSizeLong());
    switch (response.kind_case()) {
      case v1::SmoothResponse::kProgress:
        EXPECT_FALSE(outcome.have_result) << "progress after the result";
        outcome.events.push_back(response.progress());
        break;
      case v1::SmoothResponse::kResult:
        EXPECT_FALSE(outcome.have_result) << "two results";
        outcome.have_result = true;
        outcome.result = response.result();
        break;
      case v1::SmoothResponse::kChunk:
        EXPECT_TRUE(outcome.have_result) << "mesh chunk before the result";
        outcome.mesh.MergeFrom(response.chunk().mesh());
        ++outcome.chunks;
        break;
      default:
        ADD_FAILURE() << "empty SmoothResponse";
    }
  }
}

}  // namespace

SmoothOutcome CallSmooth(v1::Smoother::Stub& stub, const std::vector<v1::SmoothRequest>& requests,
                         grpc::ClientContext* context) {
  grpc::ClientContext default_context;
  if (context == nullptr) context = &default_context;
  SmoothOutcome outcome;
  auto stream = stub.Smooth(context);
  for (const auto& request : requests) {
    if (!stream->Write(request)) break;
  }
  stream->WritesDone();
  ReadSmoothResponses(*stream, outcome);
  outcome.status = stream->Finish();
  return outcome;
}

SmoothOutcome CallGetResult(v1::Smoother::Stub& stub, const std::string& job_id) {
  grpc::ClientContext context;
  v1::GetResultRequest request;
  request.set_job_id(job_id);
  SmoothOutcome outcome;
  auto reader = stub.GetResult(&context, request);
  ReadSmoothResponses(*reader, outcome);
  outcome.status = reader->Finish();
  return outcome;
}

absl::StatusOr<v1::Job> Submit(v1::Smoother::Stub& stub,
                               const std::vector<v1::SmoothRequest>& requests) {
  grpc::ClientContext context;
  v1::Job job;
  auto writer = stub.SubmitJob(&context, &job);
  for (const auto& request : requests) {
    if (!writer->Write(request)) break;
  }
  writer->WritesDone();
  grpc::Status status = writer->Finish();
  if (!status.ok()) {
    return absl::Status(static_cast<absl::StatusCode>(status.error_code()), status.error_message());
  }
  return job;
}

v1::Job GetJob(v1::Smoother::Stub& stub, const std::string& job_id) {
  grpc::ClientContext context;
  v1::GetJobRequest request;
  request.set_job_id(job_id);
  v1::Job job;
  grpc::Status status = stub.GetJob(&context, request, &job);
  EXPECT_TRUE(status.ok()) << status.error_message();
  return job;
}

v1::Job WaitForState(v1::Smoother::Stub& stub, const std::string& job_id, v1::JobState state,
                     absl::Duration timeout) {
  const absl::Time deadline = absl::Now() + timeout;
  while (true) {
    v1::Job job = GetJob(stub, job_id);
    const bool final = job.state() >= v1::JOB_STATE_SUCCEEDED;
    if (job.state() == state || final || absl::Now() > deadline) {
      EXPECT_EQ(job.state(), state) << job.DebugString();
      return job;
    }
    absl::SleepFor(absl::Milliseconds(5));
  }
}

std::vector<v1::Job> ListedJobs(v1::Smoother::Stub& stub) {
  grpc::ClientContext context;
  v1::ListJobsResponse list;
  EXPECT_TRUE(stub.ListJobs(&context, {}, &list).ok());
  return {list.jobs().begin(), list.jobs().end()};
}

v1::Job WaitForProgress(v1::Smoother::Stub& stub, const std::string& job_id,
                        absl::Duration timeout) {
  const absl::Time deadline = absl::Now() + timeout;
  while (true) {
    v1::Job job = GetJob(stub, job_id);
    if (job.latest_progress().iteration() > 0 || job.state() >= v1::JOB_STATE_SUCCEEDED ||
        absl::Now() > deadline) {
      EXPECT_EQ(job.state(), v1::JOB_STATE_RUNNING) << job.DebugString();
      EXPECT_GT(job.latest_progress().iteration(), 0) << job.DebugString();
      return job;
    }
    absl::SleepFor(absl::Milliseconds(5));
  }
}

Mesh SmallHybridMesh() {
  auto mesh = meshgen::HybridBlock(4, 4, 4, 0.3, 7);
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  return *std::move(mesh);
}

Mesh TetBlock(int cells, double jitter) {
  auto mesh = meshgen::JitteredTetBlock(cells, cells, cells, jitter, 11);
  EXPECT_TRUE(mesh.ok()) << mesh.status();
  return *std::move(mesh);
}

v1::SmoothingParameters LongRunningParameters() {
  // Sequential picks with no stall stop and a huge cap: runs until cancelled.
  v1::SmoothingParameters parameters;
  parameters.set_method(v1::METHOD_SEQUENTIAL);
  parameters.set_sequential_max_iterations(std::int64_t{1} << 40);
  parameters.set_sequential_stall_iterations(std::int64_t{1} << 40);
  parameters.set_sequential_improvement_tolerance(0.0);
  parameters.set_sequential_cycle(200);
  return parameters;
}

void ExpectBitIdenticalCoordinates(const Mesh& local, const v1::Mesh& remote) {
  ASSERT_EQ(remote.coordinates_size(), 3 * local.node_count());
  for (std::int64_t n = 0; n < local.node_count(); ++n) {
    const double expected[3] = {local.x()[n], local.y()[n], local.z()[n]};
    for (int axis = 0; axis < 3; ++axis) {
      const double actual = remote.coordinates(static_cast<int>(3 * n + axis));
      ASSERT_EQ(std::memcmp(&expected[axis], &actual, sizeof(double)), 0)
          << "node " << n << " axis " << axis << ": local " << expected[axis] << " remote "
          << actual;
    }
  }
}

}  // namespace getme::server::testing
