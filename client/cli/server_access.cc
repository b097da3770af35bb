#include "cli/server_access.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "absl/strings/ascii.h"
#include "absl/strings/str_cat.h"
#include "remote/smoother_client.h"

namespace getme::cli {
namespace {

absl::StatusOr<std::string> ReadOptionFile(const char* option, const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    return absl::NotFoundError(
        absl::StrCat("cannot read ", option, " '", path, "': ", std::strerror(errno)));
  }
  std::ostringstream contents;
  contents << file.rdbuf();
  if (file.bad() || contents.str().empty()) {
    return absl::InvalidArgumentError(absl::StrCat(option, " '", path, "' is empty"));
  }
  return contents.str();
}

// One word: the token, without the newline an editor adds. The message never shows the token.
absl::StatusOr<std::string> CheckToken(std::string token, absl::string_view source) {
  absl::StripAsciiWhitespace(&token);
  if (token.empty()) return absl::InvalidArgumentError(absl::StrCat(source, " holds no token"));
  for (char c : token) {
    if (c <= ' ' || c >= 0x7f) {
      return absl::InvalidArgumentError(
          absl::StrCat(source, " must hold one token (printable, no blanks or line breaks)"));
    }
  }
  return token;
}

}  // namespace

absl::StatusOr<std::shared_ptr<grpc::Channel>> OpenServerChannel(
    const std::string& server, const ServerAccessOptions& access) {
  remote::ChannelSecurity security;
  if (!access.token_file.empty()) {
    absl::StatusOr<std::string> contents = ReadOptionFile("--token-file", access.token_file);
    if (!contents.ok()) return contents.status();
    absl::StatusOr<std::string> token =
        CheckToken(*std::move(contents), absl::StrCat("--token-file '", access.token_file, "'"));
    if (!token.ok()) return token.status();
    security.bearer_token = *std::move(token);
  } else if (const char* environment = std::getenv("GETME_TOKEN");
             environment != nullptr && *environment != '\0') {
    absl::StatusOr<std::string> token = CheckToken(environment, "GETME_TOKEN");
    if (!token.ok()) return token.status();
    security.bearer_token = *std::move(token);
  }
  if (!access.tls_ca.empty()) {
    absl::StatusOr<std::string> ca = ReadOptionFile("--tls-ca", access.tls_ca);
    if (!ca.ok()) return ca.status();
    security.tls = true;
    security.tls_ca_pem = *std::move(ca);
  }
  if (!access.tls_cert.empty()) {
    absl::StatusOr<std::string> cert = ReadOptionFile("--tls-cert", access.tls_cert);
    if (!cert.ok()) return cert.status();
    absl::StatusOr<std::string> key = ReadOptionFile("--tls-key", access.tls_key);
    if (!key.ok()) return key.status();
    security.tls = true;
    security.tls_cert_pem = *std::move(cert);
    security.tls_key_pem = *std::move(key);
  }
  return remote::SmootherClient::CreateChannel(server, security);
}

}  // namespace getme::cli
