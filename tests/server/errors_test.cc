// Every error at the service edge with its exact status code and a message naming the node,
// element or field at fault.
#include <cmath>
#include <limits>
#include <string>

#include "gmock/gmock.h"
#include "gtest/gtest.h"
#include "server_test_support.h"

namespace getme::server::testing {
namespace {

using ::testing::HasSubstr;

class ErrorsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ServerOptions options = TestOptions();
    options.max_elements = 1000;
    test_ = StartTestServer(options);
    ASSERT_NE(test_.stub, nullptr);
  }

  // Two tetrahedra sharing a face, a hexahedron, a wedge and a pyramid: element numbers 0-1 tets,
  // 2 hex, 3 wedge, 4 pyramid.
  static v1::Mesh ValidMesh() {
    const double nodes[][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1},
                               {2, 0, 0}, {3, 0, 0}, {3, 1, 0}, {2, 1, 0}, {2, 0, 1},
                               {3, 0, 1}, {3, 1, 1}, {2, 1, 1}};
    v1::Mesh mesh;
    for (const auto& p : nodes) {
      for (double c : p) mesh.add_coordinates(c);
    }
    for (std::uint32_t i : {0, 1, 2, 3, 1, 2, 3, 4}) mesh.add_tetrahedra(i);
    for (std::uint32_t i = 5; i <= 12; ++i) mesh.add_hexahedra(i);
    // VTK wedge: triangle (0, 1, 2) clockwise seen from (3, 4, 5) (docs/node-orders.md).
    for (std::uint32_t i : {5, 8, 6, 9, 12, 10}) mesh.add_wedges(i);
    for (std::uint32_t i : {5, 6, 7, 8, 11}) mesh.add_pyramids(i);
    return mesh;
  }

  grpc::Status SmoothStatus(const v1::Mesh& mesh, const v1::SmoothingParameters& parameters = {},
                            const v1::ResultOptions& result_options = {}) {
    return CallSmooth(*test_.stub, SmoothRequests(mesh, parameters, result_options)).status;
  }

  void ExpectInvalidMesh(const v1::Mesh& mesh, const std::string& message_part) {
    grpc::Status status = SmoothStatus(mesh);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT) << status.error_message();
    EXPECT_THAT(status.error_message(), HasSubstr(message_part));
    // EvaluateQuality checks meshes the same way.
    grpc::ClientContext context;
    v1::QualityReport report;
    auto writer = test_.stub->EvaluateQuality(&context, &report);
    for (v1::MeshChunk& chunk : SplitIntoChunks(mesh)) {
      v1::EvaluateQualityRequest request;
      *request.mutable_chunk() = std::move(chunk);
      writer->Write(request);
    }
    writer->WritesDone();
    grpc::Status quality_status = writer->Finish();
    EXPECT_EQ(quality_status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
    EXPECT_THAT(quality_status.error_message(), HasSubstr(message_part));
  }

  void ExpectInvalidParameters(const v1::SmoothingParameters& parameters,
                               const std::string& field) {
    grpc::Status status = SmoothStatus(ValidMesh(), parameters);
    EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT) << status.error_message();
    EXPECT_THAT(status.error_message(), HasSubstr(field));
  }

  TestServer test_;
};

TEST_F(ErrorsTest, TheValidMeshIsAccepted) {
  grpc::Status status = SmoothStatus(ValidMesh());
  EXPECT_TRUE(status.ok()) << status.error_message();
}

TEST_F(ErrorsTest, NodeIndexOutOfRangeNamesTheElement) {
  v1::Mesh mesh = ValidMesh();
  mesh.set_wedges(4, 13);
  ExpectInvalidMesh(mesh, "wedge 0 (element 3): node index 13 at position 4 is out of range");
  for (std::uint64_t id = 100; id < 105; ++id) mesh.add_element_ids(id);
  ExpectInvalidMesh(mesh, "wedge 0 (element 3, id 103)");
}

TEST_F(ErrorsTest, NonFiniteCoordinatesNameTheNode) {
  v1::Mesh mesh = ValidMesh();
  mesh.set_coordinates(3 * 4 + 1, std::numeric_limits<double>::quiet_NaN());
  ExpectInvalidMesh(mesh, "node 4 has a non-finite coordinate: y = nan");
  mesh = ValidMesh();
  mesh.set_coordinates(3 * 2 + 2, -std::numeric_limits<double>::infinity());
  for (std::uint64_t id = 0; id < 13; ++id) mesh.add_node_ids(1000 + id);
  ExpectInvalidMesh(mesh, "node 2 (id 1002) has a non-finite coordinate: z = -inf");
}

TEST_F(ErrorsTest, WrongConnectivityLengthNamesTheField) {
  v1::Mesh mesh = ValidMesh();
  mesh.add_hexahedra(0);
  ExpectInvalidMesh(mesh, "mesh.hexahedra has 9 node indices, not a multiple of 8");
  mesh = ValidMesh();
  mesh.add_coordinates(1.0);
  ExpectInvalidMesh(mesh, "mesh.coordinates has 40 values, not a multiple of 3");
}

TEST_F(ErrorsTest, RepeatedNodeInAnElementNamesIt) {
  v1::Mesh mesh = ValidMesh();
  mesh.set_pyramids(4, 5);
  ExpectInvalidMesh(mesh, "pyramid 0 (element 4): node 5 appears twice (positions 0 and 4)");
}

TEST_F(ErrorsTest, EmptyMeshIsRefused) {
  v1::Mesh nodes_only;
  for (int i = 0; i < 12; ++i) nodes_only.add_coordinates(i);
  ExpectInvalidMesh(nodes_only, "empty mesh: 4 nodes and 0 volume elements");
  ExpectInvalidMesh(v1::Mesh(), "empty mesh: 0 nodes");
}

TEST_F(ErrorsTest, MeshOverMaxElementsIsRefused) {
  v1::Mesh mesh = ValidMesh();
  for (int e = 0; e < 1000; ++e) {
    for (std::uint32_t i : {0, 1, 2, 3}) mesh.add_tetrahedra(i);
  }
  // Refused while uploading, as soon as the chunks exceed the limit.
  ExpectInvalidMesh(mesh, "elements, more than the server's limit of 1000 (--max_elements)");
  // A declared size over the limit is refused before any chunk is read.
  std::vector<v1::SmoothRequest> requests = SmoothRequests(ValidMesh(), {});
  requests[0].mutable_header()->mutable_expected_size()->set_tetrahedra(5000);
  SmoothOutcome outcome = CallSmooth(*test_.stub, requests);
  EXPECT_EQ(outcome.status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_THAT(outcome.status.error_message(), HasSubstr("expected_size declares 5000 elements"));
}

TEST_F(ErrorsTest, ExpectedSizeMustMatchTheChunks) {
  std::vector<v1::SmoothRequest> requests = SmoothRequests(ValidMesh(), {});
  v1::MeshSize* size = requests[0].mutable_header()->mutable_expected_size();
  size->set_nodes(13);
  size->set_tetrahedra(2);
  size->set_hexahedra(1);
  size->set_wedges(1);
  size->set_pyramids(1);
  EXPECT_TRUE(CallSmooth(*test_.stub, requests).status.ok());
  size->set_wedges(2);
  SmoothOutcome outcome = CallSmooth(*test_.stub, requests);
  EXPECT_EQ(outcome.status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_THAT(outcome.status.error_message(),
              HasSubstr("expected_size.wedges = 2 but the uploaded chunks carry 1 wedges"));
}

TEST_F(ErrorsTest, FixedNodeOutOfRangeAndIdCountsNameTheField) {
  v1::Mesh mesh = ValidMesh();
  mesh.add_fixed_nodes(3);
  mesh.add_fixed_nodes(99);
  ExpectInvalidMesh(mesh, "mesh.fixed_nodes[1] = 99 is out of range: the mesh has 13 nodes");
  mesh = ValidMesh();
  mesh.add_node_ids(7);
  ExpectInvalidMesh(mesh, "mesh.node_ids has 1 entries but the mesh has 13 nodes");
  mesh = ValidMesh();
  mesh.add_element_ids(7);
  ExpectInvalidMesh(mesh, "mesh.element_ids has 1 entries but the mesh has 5 elements");
}

TEST_F(ErrorsTest, HeaderMustComeFirst) {
  std::vector<v1::SmoothRequest> requests = SmoothRequests(ValidMesh(), {});
  requests.push_back(requests[0]);
  SmoothOutcome outcome = CallSmooth(*test_.stub, requests);
  EXPECT_EQ(outcome.status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_THAT(outcome.status.error_message(), HasSubstr("the header must be the first message"));
}

TEST_F(ErrorsTest, BadParametersNameTheField) {
  v1::SmoothingParameters parameters;
  parameters.set_simultaneous_rho(1.5);
  ExpectInvalidParameters(parameters, "parameters: parameter simultaneous_rho = 1.5");
  parameters = {};
  parameters.mutable_sequential_sigma()->set_hexahedron(-2);
  ExpectInvalidParameters(parameters, "sequential_sigma[hexahedron] = -2");
  parameters = {};
  parameters.set_method(static_cast<v1::Method>(42));
  ExpectInvalidParameters(parameters, "parameters.method = 42");
  parameters = {};
  parameters.set_threads(-3);
  ExpectInvalidParameters(parameters, "parameters.threads = -3");
  parameters = {};
  parameters.set_sequential_cycle(0);
  ExpectInvalidParameters(parameters, "sequential_cycle");
  parameters = {};
  parameters.set_sequential_batch(100000);
  ExpectInvalidParameters(parameters, "parameters: parameter sequential_batch = 100000");
  parameters = {};
  parameters.set_sequential_batch_elements(0);
  ExpectInvalidParameters(parameters, "parameters: parameter sequential_batch_elements = 0");
  parameters = {};
  parameters.set_sequential_batch_band(-1.0);
  ExpectInvalidParameters(parameters, "parameters: parameter sequential_batch_band = -1");
  v1::ResultOptions result_options;
  result_options.set_histogram_bins(1'000'000);
  grpc::Status status = SmoothStatus(ValidMesh(), {}, result_options);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::INVALID_ARGUMENT);
  EXPECT_THAT(status.error_message(), HasSubstr("result_options.histogram_bins = 1000000"));
}

TEST_F(ErrorsTest, InvertedInputWithoutUntanglingIsAFailedPrecondition) {
  v1::Mesh mesh = ValidMesh();
  // Swapping two nodes inverts the second tetrahedron.
  mesh.set_tetrahedra(4, 2);
  mesh.set_tetrahedra(5, 1);
  for (std::uint64_t id = 500; id < 505; ++id) mesh.add_element_ids(id);
  v1::SmoothingParameters parameters;
  parameters.set_untangle(false);
  grpc::Status status = SmoothStatus(mesh, parameters);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::FAILED_PRECONDITION) << status.error_message();
  EXPECT_THAT(status.error_message(), HasSubstr("1 invalid"));
  EXPECT_THAT(status.error_message(), HasSubstr("first: 1"));
  EXPECT_THAT(status.error_message(), HasSubstr("element_ids: 501"));

  // The same as a job: FAILED with the status it failed with.
  auto job = Submit(*test_.stub, SmoothRequests(mesh, parameters));
  ASSERT_TRUE(job.ok()) << job.status();
  v1::Job failed = WaitForState(*test_.stub, job->job_id(), v1::JOB_STATE_FAILED);
  EXPECT_EQ(failed.error_code(), static_cast<int>(grpc::StatusCode::FAILED_PRECONDITION));
  EXPECT_THAT(failed.error_message(), HasSubstr("first: 1"));
  EXPECT_FALSE(failed.result_available());
  SmoothOutcome result = CallGetResult(*test_.stub, job->job_id());
  EXPECT_EQ(result.status.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
}

TEST_F(ErrorsTest, UnknownJobIdsAreNotFound) {
  const std::string unknown = "no-such-job";
  grpc::ClientContext get_context, cancel_context, watch_context;
  v1::Job job;
  v1::GetJobRequest get;
  get.set_job_id(unknown);
  grpc::Status status = test_.stub->GetJob(&get_context, get, &job);
  EXPECT_EQ(status.error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_THAT(status.error_message(), HasSubstr("no job with id 'no-such-job'"));
  v1::CancelJobRequest cancel;
  cancel.set_job_id(unknown);
  EXPECT_EQ(test_.stub->CancelJob(&cancel_context, cancel, &job).error_code(),
            grpc::StatusCode::NOT_FOUND);
  v1::WatchJobRequest watch;
  watch.set_job_id(unknown);
  auto reader = test_.stub->WatchJob(&watch_context, watch);
  v1::ProgressEvent event;
  EXPECT_FALSE(reader->Read(&event));
  EXPECT_EQ(reader->Finish().error_code(), grpc::StatusCode::NOT_FOUND);
  EXPECT_EQ(CallGetResult(*test_.stub, unknown).status.error_code(), grpc::StatusCode::NOT_FOUND);
}

TEST_F(ErrorsTest, ResultOfARunningJobIsAFailedPrecondition) {
  auto job = Submit(*test_.stub, SmoothRequests(ToWire(TetBlock(5, 0.3)), LongRunningParameters()));
  ASSERT_TRUE(job.ok()) << job.status();
  WaitForState(*test_.stub, job->job_id(), v1::JOB_STATE_RUNNING);
  SmoothOutcome result = CallGetResult(*test_.stub, job->job_id());
  EXPECT_EQ(result.status.error_code(), grpc::StatusCode::FAILED_PRECONDITION);
  EXPECT_THAT(result.status.error_message(), HasSubstr("is RUNNING"));
  test_.server->Shutdown(absl::ZeroDuration());
}

}  // namespace
}  // namespace getme::server::testing
