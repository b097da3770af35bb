// Bearer tokens on the gRPC service: the tokens file's format, UNAUTHENTICATED without a known
// token (health checks stay open), and jobs visible only to the owner that created them.
#include <string>

#include "absl/strings/str_cat.h"
#include "absl/strings/str_replace.h"
#include "auth_test_support.h"
#include "getme_server/access_tokens.h"
#include "getme_server/authenticator.h"
#include "gmock/gmock.h"
#include "grpcpp/generic/generic_stub.h"
#include "gtest/gtest.h"
#include "server_test_support.h"
#include "test_certificates.h"

namespace getme::server::testing {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

constexpr char kToken16[] = "0123456789abcdef";

// grpc.health.v1.Health/Check for the whole server (Debian ships no stubs for it: an empty
// request through the generic stub).
grpc::Status HealthCheck(const std::shared_ptr<grpc::Channel>& channel) {
  grpc::GenericStub stub(channel);
  grpc::CompletionQueue queue;
  grpc::ClientContext context;
  grpc::Slice empty("");
  grpc::ByteBuffer request(&empty, 1), response;  // a default ByteBuffer is no message at all
  grpc::Status status;
  auto call = stub.PrepareUnaryCall(&context, "/grpc.health.v1.Health/Check", request, &queue);
  call->StartCall();
  int tag_value = 0;
  call->Finish(&response, &status, &tag_value);
  void* tag = nullptr;
  bool ok = false;
  EXPECT_TRUE(queue.Next(&tag, &ok));
  queue.Shutdown();
  while (queue.Next(&tag, &ok)) {
  }
  return status;
}

TEST(AccessTokensTest, NamedAndBareTokensWithCommentsAndBlankLines) {
  auto tokens = AccessTokens::Parse(absl::StrCat("# comment\n\n  alice:", kAliceToken, "\r\n",
                                                 kBareToken, "\nteam.x@y-1:", kToken16, "\n   \n"),
                                    "test");
  ASSERT_TRUE(tokens.ok()) << tokens.status();
  EXPECT_EQ(tokens->size(), 3u);
  EXPECT_EQ(tokens->OwnerOf(kAliceToken), "alice");
  EXPECT_EQ(tokens->OwnerOf(kBareToken), "line4");  // a bare token's owner is its line
  EXPECT_EQ(tokens->OwnerOf(kToken16), "team.x@y-1");
  EXPECT_EQ(tokens->OwnerOf(kUnknownToken), std::nullopt);
  EXPECT_EQ(tokens->OwnerOf(""), std::nullopt);
  // Prefixes, extensions and the NAME:TOKEN line itself are not the token.
  EXPECT_EQ(tokens->OwnerOf(std::string(kAliceToken).substr(0, 20)), std::nullopt);
  EXPECT_EQ(tokens->OwnerOf(std::string(kAliceToken) + "x"), std::nullopt);
  EXPECT_EQ(tokens->OwnerOf(absl::StrCat("alice:", kAliceToken)), std::nullopt);
}

TEST(AccessTokensTest, OneOwnerMayHaveTwoTokens) {
  auto tokens = AccessTokens::Parse(
      absl::StrCat("alice:", kAliceToken, "\nalice:", kBareToken, "\n"), "test");
  ASSERT_TRUE(tokens.ok()) << tokens.status();
  EXPECT_EQ(tokens->OwnerOf(kAliceToken), "alice");
  EXPECT_EQ(tokens->OwnerOf(kBareToken), "alice");
}

TEST(AccessTokensTest, MalformedFilesAreRefusedNamingTheLineButNotTheToken) {
  struct Case {
    std::string contents;
    std::string message;
  };
  const std::string short_token = "short-token";
  const std::string spaced = "has a blank in the middle ok";
  const Case cases[] = {
      {"", "src has no token"},
      {"# only a comment\n\n", "src has no token"},
      {absl::StrCat("alice:", short_token), "src line 1: the token is shorter than 16"},
      {absl::StrCat("\n", spaced), "src line 2: the token contains a blank"},
      {absl::StrCat(":", kAliceToken), "src line 1: empty NAME"},
      {absl::StrCat("al ice:", kAliceToken), "src line 1: NAME may only contain"},
      {absl::StrCat("a:", kAliceToken, "\nb:", kAliceToken), "src line 2: the token repeats"},
  };
  for (const Case& c : cases) {
    auto tokens = AccessTokens::Parse(c.contents, "src");
    ASSERT_FALSE(tokens.ok()) << c.contents;
    EXPECT_EQ(tokens.status().code(), absl::StatusCode::kInvalidArgument);
    EXPECT_THAT(std::string(tokens.status().message()), HasSubstr(c.message));
    for (const std::string& secret : {short_token, spaced, std::string(kAliceToken)}) {
      EXPECT_THAT(std::string(tokens.status().message()), Not(HasSubstr(secret)));
    }
  }
}

TEST(AccessTokensTest, UnreadableFileIsRefusedNamingIt) {
  const std::string missing = ::testing::TempDir() + "/no-such-tokens-file";
  auto tokens = AccessTokens::ReadFile(missing);
  ASSERT_FALSE(tokens.ok());
  EXPECT_EQ(tokens.status().code(), absl::StatusCode::kNotFound);
  EXPECT_THAT(std::string(tokens.status().message()),
              HasSubstr("--auth_tokens_file '" + missing + "'"));
}

TEST(AccessTokensTest, BearerTokenOfAnAuthorizationValue) {
  EXPECT_EQ(BearerToken("Bearer abc"), "abc");
  EXPECT_EQ(BearerToken("bearer   abc "), "abc");
  EXPECT_EQ(BearerToken("Basic abc"), std::nullopt);
  EXPECT_EQ(BearerToken("Bearer "), std::nullopt);
  EXPECT_EQ(BearerToken("Bearerabc"), std::nullopt);
}

TEST(AuthServerTest, StartRefusesAMissingOrEmptyTokensFile) {
  ServerOptions options = TestOptions();
  options.auth_tokens_file = ::testing::TempDir() + "/no-such-tokens-file";
  auto missing = SmootherServer::Start(options);
  ASSERT_FALSE(missing.ok());
  EXPECT_THAT(std::string(missing.status().message()), HasSubstr(options.auth_tokens_file));

  options.auth_tokens_file = ::testing::TempDir() + "/empty-tokens-file";
  WriteTextFile(options.auth_tokens_file, "# nothing yet\n");
  auto empty = SmootherServer::Start(options);
  ASSERT_FALSE(empty.ok());
  EXPECT_THAT(std::string(empty.status().message()), HasSubstr("has no token"));
}

ServerOptions AuthOptions() {
  ServerOptions options = TestOptions();
  options.auth_tokens_file = TokensFile();
  return options;
}

TEST(AuthServerTest, CallsWithoutAKnownTokenAreUnauthenticated) {
  TestServer test = StartTestServer(AuthOptions());
  const int port = test.server->port();
  const auto requests = SmoothRequests(ToWire(SmallHybridMesh()), {});
  for (const std::string& token : {std::string(), std::string(kUnknownToken)}) {
    SCOPED_TRACE(token.empty() ? "no token" : "unknown token");
    auto stub = StubWithToken(port, token);
    absl::StatusOr<v1::Job> submitted = Submit(*stub, requests);
    ASSERT_EQ(submitted.status().code(), absl::StatusCode::kUnauthenticated);
    EXPECT_THAT(std::string(submitted.status().message()), Not(HasSubstr(kUnknownToken)));
    EXPECT_EQ(CallSmooth(*stub, requests).status.error_code(), grpc::StatusCode::UNAUTHENTICATED);
    grpc::ClientContext list_context;
    v1::ListJobsResponse list;
    EXPECT_EQ(stub->ListJobs(&list_context, {}, &list).error_code(),
              grpc::StatusCode::UNAUTHENTICATED);
    grpc::ClientContext get_context;
    v1::GetJobRequest get;
    get.set_job_id("000000000000");
    v1::Job job;
    EXPECT_EQ(stub->GetJob(&get_context, get, &job).error_code(),
              grpc::StatusCode::UNAUTHENTICATED);
  }
  // A non-bearer scheme is refused too, and a bare-line token is accepted.
  grpc::ClientContext basic;
  basic.AddMetadata("authorization", absl::StrCat("Basic ", kAliceToken));
  v1::ListJobsResponse list;
  EXPECT_EQ(test.stub->ListJobs(&basic, {}, &list).error_code(), grpc::StatusCode::UNAUTHENTICATED);
  grpc::ClientContext bare;
  bare.AddMetadata("authorization", absl::StrCat("Bearer ", kBareToken));
  EXPECT_TRUE(test.stub->ListJobs(&bare, {}, &list).ok());
  // Health checking needs no token (load balancers and probes have none).
  const grpc::Status health = HealthCheck(test.channel);
  EXPECT_TRUE(health.ok()) << health.error_message();
}

// Another owner's job is NOT_FOUND, in the words an unknown id gets; it stays untouched.
TEST(AuthServerTest, AnotherOwnersJobIsInvisible) {
  TestServer test = StartTestServer(AuthOptions());
  const int port = test.server->port();
  auto alice = StubWithToken(port, kAliceToken);
  auto bob = StubWithToken(port, kBobToken);
  absl::StatusOr<v1::Job> job =
      Submit(*alice, SmoothRequests(ToWire(TetBlock(6, 0.3)), LongRunningParameters()));
  ASSERT_TRUE(job.ok()) << job.status();
  const std::string id = job->job_id();
  const std::string unknown = "ffffffffffff";
  auto not_found_message = [](const grpc::Status& status, const std::string& job_id) {
    EXPECT_EQ(status.error_code(), grpc::StatusCode::NOT_FOUND) << status.error_message();
    return absl::StrReplaceAll(status.error_message(), {{job_id, "ID"}});
  };

  grpc::ClientContext c1, c2;
  v1::GetJobRequest get;
  v1::Job out;
  get.set_job_id(id);
  const std::string bob_get = not_found_message(bob->GetJob(&c1, get, &out), id);
  get.set_job_id(unknown);
  EXPECT_EQ(bob_get, not_found_message(bob->GetJob(&c2, get, &out), unknown));

  grpc::ClientContext c3;
  v1::CancelJobRequest cancel;
  cancel.set_job_id(id);
  EXPECT_EQ(bob_get, not_found_message(bob->CancelJob(&c3, cancel, &out), id));

  grpc::ClientContext c4;
  v1::WatchJobRequest watch;
  watch.set_job_id(id);
  auto watcher = bob->WatchJob(&c4, watch);
  v1::ProgressEvent event;
  EXPECT_FALSE(watcher->Read(&event));
  EXPECT_EQ(bob_get, not_found_message(watcher->Finish(), id));

  EXPECT_EQ(bob_get, not_found_message(CallGetResult(*bob, id).status, id));

  grpc::ClientContext c5, c6;
  v1::ListJobsResponse bob_list, alice_list;
  ASSERT_TRUE(bob->ListJobs(&c5, {}, &bob_list).ok());
  EXPECT_EQ(bob_list.jobs_size(), 0);
  ASSERT_TRUE(alice->ListJobs(&c6, {}, &alice_list).ok());
  ASSERT_EQ(alice_list.jobs_size(), 1);
  EXPECT_EQ(alice_list.jobs(0).job_id(), id);

  // Bob's cancel did nothing; alice's does.
  EXPECT_NE(GetJob(*alice, id).state(), v1::JOB_STATE_CANCELLED);
  grpc::ClientContext c7;
  ASSERT_TRUE(alice->CancelJob(&c7, cancel, &out).ok());
  EXPECT_EQ(WaitForState(*alice, id, v1::JOB_STATE_CANCELLED).state(), v1::JOB_STATE_CANCELLED);
}

// A real job end to end with a token; without authentication everyone shares the jobs.
TEST(AuthServerTest, OwnerSmoothsAndFetchesItsResult) {
  TestServer test = StartTestServer(AuthOptions());
  auto alice = StubWithToken(test.server->port(), kAliceToken);
  v1::SmoothingParameters parameters;
  parameters.set_method(v1::METHOD_SIMULTANEOUS);
  const auto requests = SmoothRequests(ToWire(SmallHybridMesh()), parameters);
  SmoothOutcome smoothed = CallSmooth(*alice, requests);
  ASSERT_TRUE(smoothed.status.ok()) << smoothed.status.error_message();
  EXPECT_GT(smoothed.result.after().q_mean(), smoothed.result.before().q_mean());

  absl::StatusOr<v1::Job> job = Submit(*alice, requests);
  ASSERT_TRUE(job.ok()) << job.status();
  WaitForState(*alice, job->job_id(), v1::JOB_STATE_SUCCEEDED);
  SmoothOutcome fetched = CallGetResult(*alice, job->job_id());
  ASSERT_TRUE(fetched.status.ok()) << fetched.status.error_message();
  EXPECT_EQ(fetched.mesh.coordinates_size(), smoothed.mesh.coordinates_size());
}

TEST(AuthServerTest, WithoutTokensFileEveryCallerSeesEveryJob) {
  TestServer test = StartTestServer();
  auto first = StubWithToken(test.server->port(), "");
  auto second = StubWithToken(test.server->port(), kAliceToken);  // ignored: auth is off
  absl::StatusOr<v1::Job> job = Submit(*first, SmoothRequests(ToWire(SmallHybridMesh()), {}));
  ASSERT_TRUE(job.ok()) << job.status();
  EXPECT_EQ(GetJob(*second, job->job_id()).job_id(), job->job_id());
}

}  // namespace
}  // namespace getme::server::testing
