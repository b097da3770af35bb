// The `getme` executable against a server with TLS and bearer tokens: --tls-ca, --token-file and
// GETME_TOKEN reach it, a missing token or TLS setting fails with the server's code, and a token
// sees only its own jobs (`getme jobs list`).
#include <stdlib.h>

#include <string>

#include "absl/strings/str_cat.h"
#include "absl/strings/strip.h"
#include "auth_test_support.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"
#include "run_getme.h"
#include "server_test_support.h"
#include "test_certificates.h"

namespace getme::server::testing {
namespace {

using cli::testing::RunGetme;
using cli::testing::RunResult;
using cli::testing::TempPath;
using ::testing::HasSubstr;
using ::testing::Not;

const std::string kHybrid = std::string(GETME_TEST_DATA) + "/hybrid-example.vtk";

class CliAuthTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const TestCertificates& certificates = GetTestCertificates();
    ServerOptions options = TestOptions();
    options.auth_tokens_file = TokensFile();
    options.tls_cert = certificates.server_cert;
    options.tls_key = certificates.server_key;
    test_ = StartTestServer(options);
    ASSERT_NE(test_.server, nullptr);
    server_ = absl::StrCat("127.0.0.1:", test_.server->port());
    alice_file_ = TempPath("alice.token");
    bob_file_ = TempPath("bob.token");
    WriteTextFile(alice_file_, absl::StrCat(kAliceToken, "\n"));
    WriteTextFile(bob_file_, kBobToken);
  }
  void TearDown() override { unsetenv("GETME_TOKEN"); }

  // `args` then --server and --tls-ca (the test CA).
  RunResult Run(std::vector<std::string> args) {
    args.insert(args.end(), {"--server", server_, "--tls-ca", GetTestCertificates().ca_cert});
    return RunGetme(args);
  }

  TestServer test_;
  std::string server_;
  std::string alice_file_;
  std::string bob_file_;
};

TEST_F(CliAuthTest, TokenFileAndTlsCaSmoothAndEvaluate) {
  const std::string out = TempPath("smoothed.vtk");
  const RunResult smoothed = Run({"smooth", kHybrid, out, "--token-file", alice_file_, "--quiet"});
  ASSERT_EQ(smoothed.exit_status, 0) << smoothed.err;
  EXPECT_THAT(ReadTextFile(out), HasSubstr("mean_ratio"));
  const RunResult quality = Run({"quality", kHybrid, "--token-file", alice_file_, "--json"});
  ASSERT_EQ(quality.exit_status, 0) << quality.err;
  EXPECT_THAT(quality.out, HasSubstr("q_mean"));
  // The token never shows (it is not an argument, and no message repeats it).
  EXPECT_THAT(smoothed.err + quality.err, Not(HasSubstr(kAliceToken)));
}

TEST_F(CliAuthTest, MissingTokenOrTlsFailsWithTheServersCode) {
  const RunResult no_token = Run({"quality", kHybrid});
  EXPECT_EQ(no_token.exit_status, 1);
  EXPECT_THAT(no_token.err, HasSubstr("getme: UNAUTHENTICATED"));
  EXPECT_THAT(no_token.err, HasSubstr("--token-file"));

  WriteTextFile(TempPath("wrong.token"), kUnknownToken);
  const RunResult wrong = Run({"quality", kHybrid, "--token-file", TempPath("wrong.token")});
  EXPECT_EQ(wrong.exit_status, 1);
  EXPECT_THAT(wrong.err, HasSubstr("UNAUTHENTICATED"));
  EXPECT_THAT(wrong.err, Not(HasSubstr(kUnknownToken)));

  const RunResult plaintext =
      RunGetme({"jobs", "list", "--server", server_, "--token-file", alice_file_});
  EXPECT_EQ(plaintext.exit_status, 1);
  EXPECT_THAT(plaintext.err, HasSubstr("getme: UNAVAILABLE"));

  const RunResult missing_file = Run({"jobs", "list", "--token-file", TempPath("none.token")});
  EXPECT_EQ(missing_file.exit_status, 1);
  EXPECT_THAT(missing_file.err, HasSubstr("cannot read --token-file '" + TempPath("none.token")));

  const RunResult half_pair = Run({"jobs", "list", "--tls-cert", alice_file_});
  EXPECT_EQ(half_pair.exit_status, 2);
  EXPECT_THAT(half_pair.err, HasSubstr("--tls-cert and --tls-key go together"));
  const RunResult local = RunGetme({"quality", kHybrid, "--token-file", alice_file_});
  EXPECT_EQ(local.exit_status, 2);
  EXPECT_THAT(local.err, HasSubstr("need --server"));
}

TEST_F(CliAuthTest, EnvironmentTokenAndJobsOfOneOwnerOnly) {
  setenv("GETME_TOKEN", kAliceToken, 1);
  const RunResult detached = Run({"smooth", kHybrid, "--detach", "--quiet"});
  ASSERT_EQ(detached.exit_status, 0) << detached.err;
  const std::string id(absl::StripAsciiWhitespace(detached.out));
  ASSERT_FALSE(id.empty());

  const RunResult alice_list = Run({"jobs", "list"});
  ASSERT_EQ(alice_list.exit_status, 0) << alice_list.err;
  EXPECT_THAT(alice_list.out, HasSubstr(id));
  // --token-file wins over GETME_TOKEN.
  const RunResult bob_list = Run({"jobs", "list", "--token-file", bob_file_});
  ASSERT_EQ(bob_list.exit_status, 0) << bob_list.err;
  EXPECT_THAT(bob_list.out, Not(HasSubstr(id)));
  const RunResult bob_cancel = Run({"jobs", "cancel", id, "--token-file", bob_file_});
  EXPECT_EQ(bob_cancel.exit_status, 1);
  EXPECT_THAT(bob_cancel.err, HasSubstr("getme: NOT_FOUND"));
}

TEST(CliMutualTlsTest, ClientCertificateFromTheCaIsNeeded) {
  const TestCertificates& certificates = GetTestCertificates();
  ServerOptions options = TestOptions();
  options.tls_cert = certificates.server_cert;
  options.tls_key = certificates.server_key;
  options.tls_client_ca = certificates.ca_cert;
  TestServer test = StartTestServer(options);
  ASSERT_NE(test.server, nullptr);
  const std::string server = absl::StrCat("127.0.0.1:", test.server->port());
  const RunResult without =
      RunGetme({"jobs", "list", "--server", server, "--tls-ca", certificates.ca_cert});
  EXPECT_EQ(without.exit_status, 1);
  EXPECT_THAT(without.err, HasSubstr("UNAVAILABLE"));
  const RunResult with =
      RunGetme({"jobs", "list", "--server", server, "--tls-ca", certificates.ca_cert, "--tls-cert",
                certificates.client_cert, "--tls-key", certificates.client_key});
  EXPECT_EQ(with.exit_status, 0) << with.err;
}

}  // namespace
}  // namespace getme::server::testing
