#include "auth_test_support.h"

#include <vector>

#include "absl/strings/str_cat.h"
#include "grpcpp/create_channel.h"
#include "grpcpp/support/client_interceptor.h"
#include "gtest/gtest.h"
#include "server_test_support.h"
#include "temp_files.h"
#include "test_certificates.h"

namespace getme::server::testing {
namespace {

// Adds the authorization metadata to each call, so the shared helpers (Submit, CallSmooth, …),
// which make their own ClientContext, work unchanged against an authenticating server.
class BearerInterceptor final : public grpc::experimental::Interceptor {
 public:
  explicit BearerInterceptor(std::string value) : value_(std::move(value)) {}
  void Intercept(grpc::experimental::InterceptorBatchMethods* methods) override {
    if (methods->QueryInterceptionHookPoint(
            grpc::experimental::InterceptionHookPoints::PRE_SEND_INITIAL_METADATA)) {
      methods->GetSendInitialMetadata()->insert({"authorization", value_});
    }
    methods->Proceed();
  }

 private:
  std::string value_;
};

class BearerInterceptorFactory final
    : public grpc::experimental::ClientInterceptorFactoryInterface {
 public:
  explicit BearerInterceptorFactory(std::string value) : value_(std::move(value)) {}
  grpc::experimental::Interceptor* CreateClientInterceptor(
      grpc::experimental::ClientRpcInfo*) override {
    return new BearerInterceptor(value_);
  }

 private:
  std::string value_;
};

}  // namespace

const std::string& TokensFile() {
  static const std::string path = [] {
    const std::string file = getme::testing::DeleteWhenTheRunPasses(
        ::testing::TempDir() + "/getme-tokens-" + std::to_string(getpid()));
    WriteTextFile(file, absl::StrCat("# test tokens\nalice:", kAliceToken, "\n\n  bob:", kBobToken,
                                     "  \n", kBareToken, "\n"));
    return file;
  }();
  return path;
}

std::shared_ptr<grpc::Channel> ChannelWithToken(
    int port, const std::string& token, std::shared_ptr<grpc::ChannelCredentials> credentials) {
  std::vector<std::unique_ptr<grpc::experimental::ClientInterceptorFactoryInterface>> interceptors;
  if (!token.empty()) {
    interceptors.push_back(std::make_unique<BearerInterceptorFactory>("Bearer " + token));
  }
  grpc::ChannelArguments arguments;
  // A fresh connection per channel: a test's plaintext and TLS channels must not share one.
  arguments.SetInt(GRPC_ARG_USE_LOCAL_SUBCHANNEL_POOL, 1);
  return grpc::experimental::CreateCustomChannelWithInterceptors(
      absl::StrCat("127.0.0.1:", port), std::move(credentials), arguments, std::move(interceptors));
}

std::unique_ptr<v1::Smoother::Stub> StubWithToken(int port, const std::string& token) {
  return v1::Smoother::NewStub(ChannelWithToken(port, token));
}

std::shared_ptr<grpc::ChannelCredentials> TlsCredentials(const std::string& ca_cert,
                                                         const std::string& client_cert,
                                                         const std::string& client_key) {
  grpc::SslCredentialsOptions ssl;
  ssl.pem_root_certs = ReadTextFile(ca_cert);
  if (!client_cert.empty()) {
    ssl.pem_cert_chain = ReadTextFile(client_cert);
    ssl.pem_private_key = ReadTextFile(client_key);
  }
  return grpc::SslCredentials(ssl);
}

ServerOptions TlsServerOptions(bool mutual) {
  const TestCertificates& certificates = GetTestCertificates();
  ServerOptions options = TestOptions();
  options.tls_cert = certificates.server_cert;
  options.tls_key = certificates.server_key;
  if (mutual) options.tls_client_ca = certificates.ca_cert;
  return options;
}

}  // namespace getme::server::testing
