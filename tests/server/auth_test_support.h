#pragma once

#include <memory>
#include <string>

#include "getme/v1/smoother.grpc.pb.h"
#include "getme_server/server_options.h"
#include "grpcpp/channel.h"
#include "grpcpp/security/credentials.h"

namespace getme::server::testing {

// Tokens of the test tokens file (tokens_file()): two owners and one token on a bare line.
inline constexpr char kAliceToken[] = "alice-0123456789abcdef0123456789";
inline constexpr char kBobToken[] = "bob-fedcba9876543210fedcba98765";
inline constexpr char kBareToken[] = "bare-token-00112233445566778899";
// A well-formed token the server does not know.
inline constexpr char kUnknownToken[] = "mallory-55555555555555555555555";

// Writes the tokens file (alice:…, bob:…, a comment, a blank line and the bare token) once per
// process and returns its path.
const std::string& TokensFile();

// A channel to 127.0.0.1:port whose every call carries `authorization: Bearer <token>` (none when
// `token` is empty), with plaintext or the given TLS credentials.
std::shared_ptr<grpc::Channel> ChannelWithToken(
    int port, const std::string& token,
    std::shared_ptr<grpc::ChannelCredentials> credentials = grpc::InsecureChannelCredentials());
std::unique_ptr<v1::Smoother::Stub> StubWithToken(int port, const std::string& token);

// TLS credentials trusting `ca_cert` (a PEM file), with a client certificate when given.
std::shared_ptr<grpc::ChannelCredentials> TlsCredentials(const std::string& ca_cert,
                                                         const std::string& client_cert = "",
                                                         const std::string& client_key = "");

// TestOptions() with TLS from the test certificates on both listeners; with `mutual`, clients
// must present a certificate of the test CA.
ServerOptions TlsServerOptions(bool mutual);

}  // namespace getme::server::testing
