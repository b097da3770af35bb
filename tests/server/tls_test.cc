// TLS and mutual TLS on the gRPC listener with certificates made at test time: plaintext and
// untrusting clients are refused, a client trusting the CA smooths a mesh end to end, and bad
// flag combinations or files stop the server with a message naming them.
#include <string>

#include "absl/strings/str_cat.h"
#include "auth_test_support.h"
#include "gmock/gmock.h"
#include "gtest/gtest.h"
#include "server_test_support.h"
#include "test_certificates.h"

namespace getme::server::testing {
namespace {

using ::testing::HasSubstr;

grpc::Status ListJobs(const std::shared_ptr<grpc::Channel>& channel) {
  auto stub = v1::Smoother::NewStub(channel);
  grpc::ClientContext context;
  context.set_deadline(std::chrono::system_clock::now() + std::chrono::seconds(10));
  v1::ListJobsResponse list;
  return stub->ListJobs(&context, {}, &list);
}

TEST(TlsTest, PlaintextAndUntrustingClientsAreRefusedTrustingOnesSmooth) {
  const TestCertificates& certificates = GetTestCertificates();
  ServerOptions options = TlsServerOptions(/*mutual=*/false);
  options.auth_tokens_file = TokensFile();
  TestServer test = StartTestServer(options);
  ASSERT_NE(test.server, nullptr);
  const int port = test.server->port();

  EXPECT_EQ(ListJobs(ChannelWithToken(port, kAliceToken)).error_code(),
            grpc::StatusCode::UNAVAILABLE);
  EXPECT_EQ(
      ListJobs(ChannelWithToken(port, kAliceToken, TlsCredentials(certificates.other_ca_cert)))
          .error_code(),
      grpc::StatusCode::UNAVAILABLE);
  // TLS is not authentication: a trusting client still needs a token.
  EXPECT_EQ(ListJobs(ChannelWithToken(port, "", TlsCredentials(certificates.ca_cert))).error_code(),
            grpc::StatusCode::UNAUTHENTICATED);

  auto channel = ChannelWithToken(port, kAliceToken, TlsCredentials(certificates.ca_cert));
  auto stub = v1::Smoother::NewStub(channel);
  v1::SmoothingParameters parameters;
  parameters.set_method(v1::METHOD_SIMULTANEOUS);
  const Mesh mesh = SmallHybridMesh();
  SmoothOutcome smoothed = CallSmooth(*stub, SmoothRequests(ToWire(mesh), parameters));
  ASSERT_TRUE(smoothed.status.ok()) << smoothed.status.error_message();
  EXPECT_EQ(smoothed.mesh.coordinates_size(), 3 * static_cast<int>(mesh.node_count()));
  EXPECT_GT(smoothed.result.after().q_mean(), smoothed.result.before().q_mean());
}

TEST(TlsTest, MutualTlsRefusesClientsWithoutACertificateFromTheCa) {
  const TestCertificates& certificates = GetTestCertificates();
  TestServer test = StartTestServer(TlsServerOptions(/*mutual=*/true));
  ASSERT_NE(test.server, nullptr);
  const int port = test.server->port();
  EXPECT_EQ(ListJobs(ChannelWithToken(port, "", TlsCredentials(certificates.ca_cert))).error_code(),
            grpc::StatusCode::UNAVAILABLE);
  // The server certificate is no client certificate (its key usage says serverAuth only).
  EXPECT_EQ(ListJobs(ChannelWithToken(port, "",
                                      TlsCredentials(certificates.ca_cert, certificates.server_cert,
                                                     certificates.server_key)))
                .error_code(),
            grpc::StatusCode::UNAVAILABLE);
  const grpc::Status with_certificate = ListJobs(ChannelWithToken(
      port, "",
      TlsCredentials(certificates.ca_cert, certificates.client_cert, certificates.client_key)));
  EXPECT_TRUE(with_certificate.ok()) << with_certificate.error_message();
}

TEST(TlsTest, BadTlsFlagsStopTheServerNamingTheFlagOrFile) {
  const TestCertificates& certificates = GetTestCertificates();
  const std::string garbage = ::testing::TempDir() + "/getme-not-a-pem";
  WriteTextFile(garbage, "not a certificate\n");
  const std::string missing = ::testing::TempDir() + "/getme-no-such.pem";
  struct Case {
    std::string cert, key, client_ca;
    std::string message;
  };
  const Case cases[] = {
      {certificates.server_cert, "", "", "--tls_cert is given without --tls_key"},
      {"", certificates.server_key, "", "--tls_key is given without --tls_cert"},
      {"", "", certificates.ca_cert, "--tls_client_ca needs --tls_cert and --tls_key"},
      {missing, certificates.server_key, "", "cannot read --tls_cert '" + missing + "'"},
      {certificates.server_cert, missing, "", "cannot read --tls_key '" + missing + "'"},
      {garbage, certificates.server_key, "", "--tls_cert '" + garbage + "' is not a PEM"},
      {certificates.server_cert, garbage, "", "--tls_key '" + garbage + "' is not an"},
      {certificates.server_cert, certificates.client_key, "", "does not belong to --tls_cert"},
      {certificates.server_cert, certificates.server_key, garbage,
       "--tls_client_ca '" + garbage + "' holds no PEM CA"},
  };
  for (const Case& c : cases) {
    ServerOptions options = TestOptions();
    options.tls_cert = c.cert;
    options.tls_key = c.key;
    options.tls_client_ca = c.client_ca;
    auto server = SmootherServer::Start(options);
    ASSERT_FALSE(server.ok()) << c.message;
    EXPECT_THAT(std::string(server.status().message()), HasSubstr(c.message));
  }
}

}  // namespace
}  // namespace getme::server::testing
