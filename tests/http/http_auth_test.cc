// Bearer tokens and job ownership on the HTTP gateway, tokens kept out of the log, and HTTPS
// (with and without client certificates) with certificates made at test time.
#include <sstream>
#include <string>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_replace.h"
#include "auth_test_support.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"
#include "http_test_support.h"
#include "spdlog/sinks/ostream_sink.h"
#include "spdlog/spdlog.h"
#include "test_certificates.h"

namespace getme::server::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

ServerOptions AuthOptions() {
  ServerOptions options = TestOptions();
  options.auth_tokens_file = TokensFile();
  return options;
}

std::unique_ptr<httplib::Client> ClientWithToken(int port, const std::string& token) {
  auto client = std::make_unique<httplib::Client>("127.0.0.1", port);
  client->set_read_timeout(30, 0);
  if (!token.empty()) client->set_bearer_token_auth(token.c_str());
  return client;
}

// The `message` of an error body with the job id replaced, to compare two NOT_FOUND answers.
std::string NotFoundMessage(const HttpReply& reply, const std::string& job_id) {
  EXPECT_EQ(reply.status, 404) << reply.body;
  return absl::StrReplaceAll(reply.body, {{job_id, "ID"}});
}

TEST(HttpAuthTest, ApiNeedsAKnownTokenProbesAndDashboardDoNot) {
  HttpTestServer test = StartHttpTestServer(AuthOptions());
  const int port = test.grpc.server->http_port();
  for (const char* path : {"/healthz", "/readyz", "/", "/dashboard.js"}) {
    EXPECT_EQ(HttpGet(*test.http, path).status, 200) << path;
  }
  for (const std::string& token : {std::string(), std::string(kUnknownToken)}) {
    auto client = ClientWithToken(port, token);
    for (const char* path :
         {"/v1/jobs", "/v1/jobs/000000000000", "/v1/jobs/000000000000/events", "/metrics"}) {
      auto result = client->Get(path);
      ASSERT_TRUE(result) << path;
      EXPECT_EQ(result->status, 401) << path;
      EXPECT_EQ(result->get_header_value("WWW-Authenticate"), "Bearer");
      EXPECT_THAT(result->body, HasSubstr("\"code\": \"UNAUTHENTICATED\""));
      EXPECT_THAT(result->body, Not(HasSubstr(kUnknownToken)));
    }
    const HttpReply posted = HttpPost(*client, "/v1/jobs", "{}");
    EXPECT_EQ(posted.status, 401) << posted.body;
  }
  auto alice = ClientWithToken(port, kAliceToken);
  EXPECT_EQ(HttpGet(*alice, "/v1/jobs").status, 200);
  EXPECT_EQ(HttpGet(*alice, "/metrics").status, 200);
}

TEST(HttpAuthTest, AnotherOwnersJobIsInvisible) {
  HttpTestServer test = StartHttpTestServer(AuthOptions());
  const int port = test.grpc.server->http_port();
  auto alice = ClientWithToken(port, kAliceToken);
  auto bob = ClientWithToken(port, kBobToken);
  const HttpReply created = HttpPost(
      *alice, "/v1/jobs", CreateJobJson(ToWire(TetBlock(6, 0.3)), LongRunningParameters()));
  ASSERT_EQ(created.status, 200) << created.body;
  const std::string id = ParseJson<v1::Job>(created.body).job_id();
  const std::string unknown = "ffffffffffff";

  const std::string expected = NotFoundMessage(HttpGet(*bob, "/v1/jobs/" + unknown), unknown);
  EXPECT_EQ(NotFoundMessage(HttpGet(*bob, "/v1/jobs/" + id), id), expected);
  EXPECT_EQ(NotFoundMessage(HttpPost(*bob, "/v1/jobs/" + id + ":cancel", ""), id), expected);
  EXPECT_EQ(NotFoundMessage(HttpGet(*bob, "/v1/jobs/" + id + "/report"), id), expected);
  EXPECT_EQ(NotFoundMessage(HttpGet(*bob, "/v1/jobs/" + id + "/trace"), id), expected);
  EXPECT_EQ(NotFoundMessage(HttpGet(*bob, "/v1/jobs/" + id + "/events"), id), expected);
  // The same through the dashboard's query-parameter token for event streams.
  auto anonymous = ClientWithToken(port, "");
  EXPECT_EQ(NotFoundMessage(HttpGet(*anonymous, absl::StrCat("/v1/jobs/", id,
                                                             "/events?access_token=", kBobToken)),
                            id),
            expected);
  EXPECT_EQ(ParseJson<v1::ListJobsResponse>(HttpGet(*bob, "/v1/jobs").body).jobs_size(), 0);
  // Over gRPC too: the owner is the token's, whichever front end created the job.
  auto bob_grpc = StubWithToken(test.grpc.server->port(), kBobToken);
  grpc::ClientContext context;
  v1::GetJobRequest get;
  get.set_job_id(id);
  v1::Job job;
  EXPECT_EQ(bob_grpc->GetJob(&context, get, &job).error_code(), grpc::StatusCode::NOT_FOUND);

  const auto alice_list = ParseJson<v1::ListJobsResponse>(HttpGet(*alice, "/v1/jobs").body);
  ASSERT_EQ(alice_list.jobs_size(), 1);
  EXPECT_EQ(alice_list.jobs(0).job_id(), id);
  EXPECT_NE(ParseJson<v1::Job>(HttpGet(*alice, "/v1/jobs/" + id).body).state(),
            v1::JOB_STATE_CANCELLED);
  const HttpReply cancelled = HttpPost(*alice, "/v1/jobs/" + id + ":cancel", "");
  EXPECT_EQ(cancelled.status, 200) << cancelled.body;
}

// The event stream takes its token from the query (EventSource cannot send headers); the
// log shows neither that nor any header token, and does show what was logged for the calls.
TEST(HttpAuthTest, TokensNeverReachTheLog) {
  std::ostringstream log;
  auto sink = std::make_shared<spdlog::sinks::ostream_sink_mt>(log);
  auto logger = spdlog::default_logger();
  const auto previous_level = logger->level();
  logger->sinks().push_back(sink);
  logger->set_level(spdlog::level::trace);
  {
    HttpTestServer test = StartHttpTestServer(AuthOptions());
    const int port = test.grpc.server->http_port();
    auto alice = ClientWithToken(port, kAliceToken);
    v1::SmoothingParameters parameters;
    parameters.set_method(v1::METHOD_SIMULTANEOUS);
    const HttpReply created =
        HttpPost(*alice, "/v1/jobs", CreateJobJson(ToWire(SmallHybridMesh()), parameters));
    ASSERT_EQ(created.status, 200) << created.body;
    const std::string id = ParseJson<v1::Job>(created.body).job_id();
    auto anonymous = ClientWithToken(port, "");
    const HttpReply events =
        HttpGet(*anonymous, absl::StrCat("/v1/jobs/", id, "/events?access_token=", kAliceToken));
    EXPECT_EQ(events.status, 200);
    EXPECT_THAT(events.body, HasSubstr("event: end"));
    EXPECT_EQ(
        HttpGet(*anonymous, absl::StrCat("/v1/jobs/", id, "/events?access_token=", kUnknownToken))
            .status,
        401);
    EXPECT_EQ(HttpGet(*ClientWithToken(port, kUnknownToken), "/v1/jobs").status, 401);
    auto grpc_alice = StubWithToken(test.grpc.server->port(), kAliceToken);
    EXPECT_EQ(WaitForState(*grpc_alice, id, v1::JOB_STATE_SUCCEEDED).state(),
              v1::JOB_STATE_SUCCEEDED);
    auto grpc_mallory = StubWithToken(test.grpc.server->port(), kUnknownToken);
    grpc::ClientContext context;
    v1::ListJobsResponse list;
    EXPECT_FALSE(grpc_mallory->ListJobs(&context, {}, &list).ok());
    test.grpc.server->Shutdown(absl::Seconds(1));
  }
  logger->flush();
  std::erase(logger->sinks(), sink);
  logger->set_level(previous_level);
  const std::string text = log.str();
  EXPECT_THAT(text, HasSubstr("owner=alice"));         // the capture works
  EXPECT_THAT(text, HasSubstr("/events status=200"));  // and saw the event stream
  for (const char* token : {kAliceToken, kBobToken, kBareToken, kUnknownToken}) {
    EXPECT_THAT(text, Not(HasSubstr(token)));
  }
  EXPECT_THAT(text, Not(HasSubstr("access_token")));
}

// An HTTPS client trusting the test CA, with a client certificate when asked.
std::unique_ptr<httplib::SSLClient> HttpsClient(int port, bool client_certificate) {
  const TestCertificates& certificates = GetTestCertificates();
  auto client = client_certificate
                    ? std::make_unique<httplib::SSLClient>(
                          "127.0.0.1", port, certificates.client_cert, certificates.client_key)
                    : std::make_unique<httplib::SSLClient>("127.0.0.1", port);
  client->set_ca_cert_path(certificates.ca_cert.c_str());
  client->enable_server_certificate_verification(true);
  client->set_connection_timeout(5, 0);
  client->set_read_timeout(10, 0);
  return client;
}

TEST(HttpsTest, PlainHttpIsRefusedHttpsWithTheCaServesAJob) {
  ServerOptions options = TlsServerOptions(/*mutual=*/false);
  options.http_listen = "127.0.0.1:0";
  TestServer test = StartTestServer(options);
  ASSERT_NE(test.server, nullptr);
  const int port = test.server->http_port();
  ASSERT_GT(port, 0);

  httplib::Client plain("127.0.0.1", port);
  plain.set_read_timeout(5, 0);
  auto refused = plain.Get("/healthz");
  EXPECT_FALSE(refused && refused->status == 200) << "plain HTTP answered";

  auto https = HttpsClient(port, /*client_certificate=*/false);
  auto health = https->Get("/healthz");
  ASSERT_TRUE(health) << httplib::to_string(health.error());
  EXPECT_EQ(health->status, 200);
  v1::SmoothingParameters parameters;
  parameters.set_method(v1::METHOD_SIMULTANEOUS);
  auto created = https->Post("/v1/jobs", CreateJobJson(ToWire(SmallHybridMesh()), parameters),
                             "application/json");
  ASSERT_TRUE(created);
  ASSERT_EQ(created->status, 200) << created->body;
  const std::string id = ParseJson<v1::Job>(created->body).job_id();
  auto stub = v1::Smoother::NewStub(
      ChannelWithToken(test.server->port(), "", TlsCredentials(GetTestCertificates().ca_cert)));
  EXPECT_EQ(WaitForState(*stub, id, v1::JOB_STATE_SUCCEEDED).state(), v1::JOB_STATE_SUCCEEDED);
  // A client that trusts another CA does not talk to this server.
  httplib::SSLClient untrusting("127.0.0.1", port);
  untrusting.set_ca_cert_path(GetTestCertificates().other_ca_cert.c_str());
  untrusting.enable_server_certificate_verification(true);
  EXPECT_FALSE(untrusting.Get("/healthz"));
}

TEST(HttpsTest, MutualTlsNeedsAClientCertificate) {
  ServerOptions options = TlsServerOptions(/*mutual=*/true);
  options.http_listen = "127.0.0.1:0";
  TestServer test = StartTestServer(options);
  ASSERT_NE(test.server, nullptr);
  const int port = test.server->http_port();
  auto without = HttpsClient(port, /*client_certificate=*/false)->Get("/healthz");
  EXPECT_FALSE(without && without->status == 200);
  auto with = HttpsClient(port, /*client_certificate=*/true)->Get("/healthz");
  ASSERT_TRUE(with) << httplib::to_string(with.error());
  EXPECT_EQ(with->status, 200);
}

}  // namespace
}  // namespace getme::server::testing
