#pragma once

#include <optional>
#include <string>

#include "absl/status/statusor.h"
#include "getme_server/server_options.h"

namespace getme::server {

// The PEM files of --tls_cert, --tls_key and --tls_client_ca, read and checked once at startup
// so that a bad file stops the server with a message naming it, instead of a listener failing
// later without saying why. Both listeners (gRPC and HTTP) serve the same certificate.
struct TlsFiles {
  std::string cert_chain_pem;
  std::string private_key_pem;
  std::string client_ca_pem;  // empty: clients need no certificate (no mTLS)
};

// nullopt when TLS is off (no --tls_cert/--tls_key). INVALID_ARGUMENT naming the flag when only
// one of the pair is given or --tls_client_ca comes without them; INVALID_ARGUMENT or NOT_FOUND
// naming the flag and file when a file cannot be read, holds no usable PEM (certificate chain,
// unencrypted private key, CA certificates), or the key does not belong to the certificate.
absl::StatusOr<std::optional<TlsFiles>> LoadTlsFiles(const ServerOptions& options);

}  // namespace getme::server
