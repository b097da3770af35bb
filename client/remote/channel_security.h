#pragma once

#include <memory>
#include <string>

#include "grpcpp/channel.h"

namespace getme::remote {

// How a client reaches a getme-server with access control on (docs/reliability.md). The
// default is a plaintext channel without credentials, as to a server on loopback.
struct ChannelSecurity {
  // Sent as metadata `authorization: Bearer <token>` on every call; empty = none.
  std::string bearer_token;
  // TLS: trust the server certificate if tls_ca_pem (PEM CA certificates) signed it, or, when
  // that is empty, one of the system's root CAs.
  bool tls = false;
  std::string tls_ca_pem;
  // The client certificate chain and private key for a server that requires one (mutual TLS);
  // both or neither. They imply TLS.
  std::string tls_cert_pem;
  std::string tls_key_pem;
};

// A channel to `target` (host:port or any gRPC target) with `security` applied.
std::shared_ptr<grpc::Channel> CreateSecureChannel(const std::string& target,
                                                   const ChannelSecurity& security);

}  // namespace getme::remote
