#include "getme_server/tls_files.h"

#include <openssl/err.h>
#include <openssl/pem.h>
#include <openssl/ssl.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>

#include "absl/strings/str_cat.h"

namespace getme::server {
namespace {

struct SslCtxFree {
  void operator()(SSL_CTX* context) const { SSL_CTX_free(context); }
};

// OpenSSL's reason for the last failure (its error queue is per thread), then an empty queue.
std::string OpenSslReason() {
  const unsigned long error = ERR_peek_last_error();
  std::string reason = error == 0 ? "no PEM data found" : ERR_reason_error_string(error);
  ERR_clear_error();
  return reason;
}

absl::StatusOr<std::string> ReadFlagFile(const char* flag, const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    return absl::NotFoundError(
        absl::StrCat("cannot read --", flag, " '", path, "': ", std::strerror(errno)));
  }
  std::ostringstream contents;
  contents << file.rdbuf();
  if (file.bad() || contents.str().empty()) {
    return absl::InvalidArgumentError(
        absl::StrCat("--", flag, " '", path, "' is empty or unreadable"));
  }
  return contents.str();
}

// Refuses a key protected by a pass phrase at once: the default callback would prompt on the
// terminal of a server that may have none.
int NoPassphrase(char*, int, int, void*) { return 0; }

absl::Status CheckWithOpenSsl(const ServerOptions& options) {
  std::unique_ptr<SSL_CTX, SslCtxFree> context(SSL_CTX_new(TLS_server_method()));
  if (context == nullptr) return absl::InternalError("OpenSSL cannot create a TLS context");
  auto invalid = [](const char* flag, const std::string& path, absl::string_view what) {
    return absl::InvalidArgumentError(
        absl::StrCat("--", flag, " '", path, "' ", what, ": ", OpenSslReason()));
  };
  if (SSL_CTX_use_certificate_chain_file(context.get(), options.tls_cert.c_str()) != 1) {
    return invalid("tls_cert", options.tls_cert, "is not a PEM certificate (chain)");
  }
  // Read apart from SSL_CTX_use_PrivateKey, so "not a key" and "not this certificate's key" get
  // their own messages.
  std::unique_ptr<BIO, decltype(&BIO_free)> key_file(BIO_new_file(options.tls_key.c_str(), "r"),
                                                     BIO_free);
  std::unique_ptr<EVP_PKEY, decltype(&EVP_PKEY_free)> key(
      key_file == nullptr ? nullptr
                          : PEM_read_bio_PrivateKey(key_file.get(), nullptr, NoPassphrase, nullptr),
      EVP_PKEY_free);
  if (key == nullptr) {
    return invalid("tls_key", options.tls_key, "is not an unencrypted PEM private key");
  }
  if (SSL_CTX_use_PrivateKey(context.get(), key.get()) != 1 ||
      SSL_CTX_check_private_key(context.get()) != 1) {
    return invalid("tls_key", options.tls_key, "does not belong to --tls_cert's certificate");
  }
  if (!options.tls_client_ca.empty() &&
      SSL_CTX_load_verify_locations(context.get(), options.tls_client_ca.c_str(), nullptr) != 1) {
    return invalid("tls_client_ca", options.tls_client_ca, "holds no PEM CA certificate");
  }
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<std::optional<TlsFiles>> LoadTlsFiles(const ServerOptions& options) {
  const bool cert = !options.tls_cert.empty();
  const bool key = !options.tls_key.empty();
  if (!cert && !key) {
    if (!options.tls_client_ca.empty()) {
      return absl::InvalidArgumentError(
          "--tls_client_ca needs --tls_cert and --tls_key: client certificates are only "
          "checked over TLS");
    }
    return std::nullopt;
  }
  if (cert != key) {
    return absl::InvalidArgumentError(
        cert ? "--tls_cert is given without --tls_key: TLS needs both (PEM files)"
             : "--tls_key is given without --tls_cert: TLS needs both (PEM files)");
  }
  TlsFiles files;
  absl::StatusOr<std::string> chain = ReadFlagFile("tls_cert", options.tls_cert);
  if (!chain.ok()) return chain.status();
  absl::StatusOr<std::string> private_key = ReadFlagFile("tls_key", options.tls_key);
  if (!private_key.ok()) return private_key.status();
  files.cert_chain_pem = *std::move(chain);
  files.private_key_pem = *std::move(private_key);
  if (!options.tls_client_ca.empty()) {
    absl::StatusOr<std::string> ca = ReadFlagFile("tls_client_ca", options.tls_client_ca);
    if (!ca.ok()) return ca.status();
    files.client_ca_pem = *std::move(ca);
  }
  if (auto s = CheckWithOpenSsl(options); !s.ok()) return s;
  return files;
}

}  // namespace getme::server
