#include "remote/channel_security.h"

#include <utility>
#include <vector>

#include "grpcpp/create_channel.h"
#include "grpcpp/security/credentials.h"
#include "grpcpp/support/client_interceptor.h"

namespace getme::remote {
namespace {

// Call credentials would be simpler, but gRPC sends them over TLS only; an interceptor also
// serves a server on loopback that checks tokens without TLS.
class BearerTokenInterceptor final : public grpc::experimental::Interceptor {
 public:
  explicit BearerTokenInterceptor(std::string authorization)
      : authorization_(std::move(authorization)) {}

  void Intercept(grpc::experimental::InterceptorBatchMethods* methods) override {
    if (methods->QueryInterceptionHookPoint(
            grpc::experimental::InterceptionHookPoints::PRE_SEND_INITIAL_METADATA)) {
      methods->GetSendInitialMetadata()->insert({"authorization", authorization_});
    }
    methods->Proceed();
  }

 private:
  const std::string authorization_;
};

class BearerTokenInterceptorFactory final
    : public grpc::experimental::ClientInterceptorFactoryInterface {
 public:
  explicit BearerTokenInterceptorFactory(const std::string& token)
      : authorization_("Bearer " + token) {}

  grpc::experimental::Interceptor* CreateClientInterceptor(
      grpc::experimental::ClientRpcInfo*) override {
    return new BearerTokenInterceptor(authorization_);
  }

 private:
  const std::string authorization_;
};

}  // namespace

std::shared_ptr<grpc::Channel> CreateSecureChannel(const std::string& target,
                                                   const ChannelSecurity& security) {
  grpc::ChannelArguments arguments;
  // Results come in ~1 MB chunks; the default 4 MB receive limit is plenty, but a server may
  // choose larger chunks (ResultOptions.nodes_per_chunk), so do not refuse those.
  arguments.SetMaxReceiveMessageSize(-1);
  // A server that went away (restart, crash) is found again quickly enough for CallOptions.retry.
  // gRPC 1.51 waits for the longer of its reconnect backoff and its minimum connect timeout
  // between connection attempts, and re-resolves the target's name before one: their defaults
  // (1 s growing to 120 s, 20 s, 30 s) kept a client off a server restarted at once for 5-10 s.
  // Here: 0.2 s growing to 2 s, 1 s (also the shortest time one TCP connect may take: enough on
  // a LAN, short on a slow WAN), 0.5 s; a restart is then seen within about 1.5 s.
  arguments.SetInt(GRPC_ARG_INITIAL_RECONNECT_BACKOFF_MS, 200);
  arguments.SetInt(GRPC_ARG_MAX_RECONNECT_BACKOFF_MS, 2000);
  arguments.SetInt(GRPC_ARG_MIN_RECONNECT_BACKOFF_MS, 1000);
  arguments.SetInt(GRPC_ARG_DNS_MIN_TIME_BETWEEN_RESOLUTIONS_MS, 500);
  std::shared_ptr<grpc::ChannelCredentials> credentials = grpc::InsecureChannelCredentials();
  if (security.tls || !security.tls_ca_pem.empty() || !security.tls_cert_pem.empty()) {
    grpc::SslCredentialsOptions ssl;
    ssl.pem_root_certs = security.tls_ca_pem;
    ssl.pem_cert_chain = security.tls_cert_pem;
    ssl.pem_private_key = security.tls_key_pem;
    credentials = grpc::SslCredentials(ssl);
  }
  std::vector<std::unique_ptr<grpc::experimental::ClientInterceptorFactoryInterface>> interceptors;
  if (!security.bearer_token.empty()) {
    interceptors.push_back(std::make_unique<BearerTokenInterceptorFactory>(security.bearer_token));
  }
  return grpc::experimental::CreateCustomChannelWithInterceptors(
      target, std::move(credentials), arguments, std::move(interceptors));
}

}  // namespace getme::remote
