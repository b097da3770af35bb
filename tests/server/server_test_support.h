#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "absl/status/statusor.h"
#include "getme/mesh/mesh.h"
#include "getme/v1/smoother.grpc.pb.h"
#include "getme_server/server.h"
#include "getme_server/server_options.h"
#include "grpcpp/client_context.h"

namespace getme::server::testing {

// A server on an ephemeral loopback port and a stub connected to it.
struct TestServer {
  std::unique_ptr<SmootherServer> server;
  std::shared_ptr<grpc::Channel> channel;
  std::unique_ptr<v1::Smoother::Stub> stub;
};
ServerOptions TestOptions();  // 127.0.0.1:0, small queue, every progress event forwarded
TestServer StartTestServer(const ServerOptions& options = TestOptions());

// The test's own engine → wire conversion (written independently of the server's): VTK order,
// paper prism (p0..p5) → VTK wedge (p0, p2, p1, p3, p5, p4), elements grouped by wire type.
v1::Mesh ToWire(const Mesh& mesh);
// Wire → engine mesh in the wire's element numbering, for local reference runs.
Mesh FromWire(const v1::Mesh& wire);
// Fails the test unless `remote` holds exactly `local`'s coordinates, bit for bit.
void ExpectBitIdenticalCoordinates(const Mesh& local, const v1::Mesh& remote);

// Splits a mesh into chunks of about `bytes` each (one repeated field slice per chunk).
std::vector<v1::MeshChunk> SplitIntoChunks(const v1::Mesh& mesh, std::size_t bytes = 1 << 20);
std::vector<v1::SmoothRequest> SmoothRequests(const v1::Mesh& mesh,
                                              const v1::SmoothingParameters& parameters,
                                              const v1::ResultOptions& result_options = {});

// What a Smooth or GetResult stream delivered.
struct SmoothOutcome {
  grpc::Status status;
  std::vector<v1::ProgressEvent> events;
  bool have_result = false;
  v1::SmoothResult result;
  v1::Mesh mesh;  // the result chunks merged
  int chunks = 0;
  std::size_t largest_message_bytes = 0;
};
SmoothOutcome CallSmooth(v1::Smoother::Stub& stub, const std::vector<v1::SmoothRequest>& requests,
                         grpc::ClientContext* context = nullptr);
SmoothOutcome CallGetResult(v1::Smoother::Stub& stub, const std::string& job_id);
// SubmitJob: the job (or the error status).
absl::StatusOr<v1::Job> Submit(v1::Smoother::Stub& stub,
                               const std::vector<v1::SmoothRequest>& requests);
v1::Job GetJob(v1::Smoother::Stub& stub, const std::string& job_id);
// The jobs ListJobs returns; fails the test if the call fails.
std::vector<v1::Job> ListedJobs(v1::Smoother::Stub& stub);
// Polls GetJob until the job reaches `state` or a final state; fails the test after `timeout`.
v1::Job WaitForState(v1::Smoother::Stub& stub, const std::string& job_id, v1::JobState state,
                     absl::Duration timeout = absl::Seconds(60));
// Polls GetJob until the running job has published a progress event past iteration 0: a fixed
// sleep is no promise of that on a loaded machine. Fails the test after `timeout`.
v1::Job WaitForProgress(v1::Smoother::Stub& stub, const std::string& job_id,
                        absl::Duration timeout = absl::Seconds(60));

// Test meshes from the bench generators.
Mesh SmallHybridMesh();                   // all four types, a few hundred elements
Mesh TetBlock(int cells, double jitter);  // 6 cells^3 jittered tetrahedra
// Parameters for a job that runs for many seconds unless cancelled.
v1::SmoothingParameters LongRunningParameters();

}  // namespace getme::server::testing
