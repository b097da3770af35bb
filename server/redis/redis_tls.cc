#include "redis/redis_tls.h"

#include <hiredis/hiredis.h>
#include <openssl/err.h>
#include <openssl/ssl.h>
#include <openssl/x509v3.h>
#include <sys/socket.h>

#include <algorithm>
#include <cerrno>
#include <system_error>
#include <utility>

#include "absl/strings/str_cat.h"
#include "redis/redis_status.h"

namespace getme::redis {

struct TlsSession::OpenSsl {
  ~OpenSsl() {
    if (ssl != nullptr) SSL_free(ssl);  // frees the BIOs too
    if (context != nullptr) SSL_CTX_free(context);
  }
  SSL_CTX* context = nullptr;
  SSL* ssl = nullptr;
  BIO* from_network = nullptr;  // what recv() got, for OpenSSL to decrypt
  BIO* to_network = nullptr;    // what OpenSSL encrypted, for send()
};

namespace {

// Plaintext is handed to OpenSSL in pieces of this size, each sent before the next is
// encrypted, so a large result does not sit twice in memory.
constexpr size_t kWriteChunk = 64 * 1024;

// OpenSSL's queued reasons (thread-local), oldest first, e.g. "certificate verify failed".
std::string TakeOpenSslErrors() {
  std::string text;
  while (const unsigned long code = ERR_get_error()) {
    const char* reason = ERR_reason_error_string(code);
    absl::StrAppend(&text, text.empty() ? "" : "; ",
                    reason != nullptr ? reason : absl::StrCat("OpenSSL error ", code));
  }
  return text;
}

absl::Status SocketError(int error_number, absl::string_view what) {
  return StatusFromConnectionError(REDIS_ERR_IO, error_number,
                                   std::generic_category().message(error_number), what);
}

absl::Status FileRefused(absl::string_view kind, const std::string& path,
                         absl::string_view redacted_url) {
  return absl::InvalidArgumentError(absl::StrCat("redis: cannot use the TLS ", kind, " file '",
                                                 path, "' for ", redacted_url, ": ",
                                                 TakeOpenSslErrors()));
}

}  // namespace

TlsSession::TlsSession(int socket_fd, std::unique_ptr<OpenSsl> openssl)
    : socket_fd_(socket_fd), openssl_(std::move(openssl)) {}

TlsSession::~TlsSession() {
  // A close_notify, so the server logs a clean close; best effort and never waiting.
  ERR_clear_error();
  if (SSL_is_init_finished(openssl_->ssl) && SSL_shutdown(openssl_->ssl) >= 0) {
    char buffer[512];
    int length = 0;
    while ((length = BIO_read(openssl_->to_network, buffer, sizeof(buffer))) > 0) {
      if (send(socket_fd_, buffer, static_cast<size_t>(length), MSG_NOSIGNAL | MSG_DONTWAIT) !=
          length) {
        break;
      }
    }
  }
  ERR_clear_error();
}

absl::StatusOr<std::unique_ptr<TlsSession>> TlsSession::Handshake(int socket_fd,
                                                                  const RedisAddress& address,
                                                                  absl::string_view redacted_url) {
  ERR_clear_error();
  auto openssl = std::make_unique<OpenSsl>();
  openssl->context = SSL_CTX_new(TLS_client_method());
  if (openssl->context == nullptr) {
    return absl::InternalError(
        absl::StrCat("redis: cannot create a TLS context: ", TakeOpenSslErrors()));
  }
  SSL_CTX* context = openssl->context;
  SSL_CTX_set_min_proto_version(context, TLS1_2_VERSION);
  SSL_CTX_set_verify(context, SSL_VERIFY_PEER, nullptr);
  if (address.tls_ca_file.empty()) {
    if (SSL_CTX_set_default_verify_paths(context) != 1) {
      return absl::InternalError(
          absl::StrCat("redis: cannot load the system's trusted CAs: ", TakeOpenSslErrors()));
    }
  } else if (SSL_CTX_load_verify_locations(context, address.tls_ca_file.c_str(), nullptr) != 1) {
    return FileRefused("CA", address.tls_ca_file, redacted_url);
  }
  if (!address.tls_cert_file.empty()) {
    if (SSL_CTX_use_certificate_chain_file(context, address.tls_cert_file.c_str()) != 1) {
      return FileRefused("certificate", address.tls_cert_file, redacted_url);
    }
    // This also checks that the key is the certificate's ("key values mismatch").
    if (SSL_CTX_use_PrivateKey_file(context, address.tls_key_file.c_str(), SSL_FILETYPE_PEM) != 1) {
      return FileRefused("key", address.tls_key_file, redacted_url);
    }
  }

  openssl->ssl = SSL_new(context);
  openssl->from_network = BIO_new(BIO_s_mem());
  openssl->to_network = BIO_new(BIO_s_mem());
  if (openssl->ssl == nullptr || openssl->from_network == nullptr ||
      openssl->to_network == nullptr) {
    BIO_free(openssl->from_network);
    BIO_free(openssl->to_network);
    return absl::InternalError(
        absl::StrCat("redis: cannot create a TLS session: ", TakeOpenSslErrors()));
  }
  SSL_set_bio(openssl->ssl, openssl->from_network, openssl->to_network);
  SSL* ssl = openssl->ssl;
  // The certificate must name the address dialled (or the server name the URL gives instead):
  // an IP address must be one of its IP subjectAltNames, a host name one of its DNS names
  // (which also goes out as SNI).
  const std::string& name =
      address.tls_server_name.empty() ? address.host : address.tls_server_name;
  X509_VERIFY_PARAM* verify = SSL_get0_param(ssl);
  if (X509_VERIFY_PARAM_set1_ip_asc(verify, name.c_str()) != 1) {
    ERR_clear_error();  // not an IP address
    X509_VERIFY_PARAM_set_hostflags(verify, X509_CHECK_FLAG_NO_PARTIAL_WILDCARDS);
    if (X509_VERIFY_PARAM_set1_host(verify, name.c_str(), name.size()) != 1 ||
        SSL_set_tlsext_host_name(ssl, name.c_str()) != 1) {
      return absl::InvalidArgumentError(absl::StrCat(
          "redis: '", name, "' cannot be checked against a certificate: ", TakeOpenSslErrors()));
    }
  }

  std::unique_ptr<TlsSession> session(new TlsSession(socket_fd, std::move(openssl)));
  const std::string what = absl::StrCat("TLS handshake with ", redacted_url);
  while (true) {
    ERR_clear_error();
    const int result = SSL_connect(ssl);
    absl::Status diagnosis = result == 1 ? absl::OkStatus() : session->Diagnose(result, what);
    // What SSL_connect wrote (its hello, its finished message, or the alert telling the server
    // why it gave up) goes out before waiting for the server or reporting.
    const absl::Status flushed = session->Flush(what);
    if (!diagnosis.ok()) return diagnosis;
    if (!flushed.ok()) return flushed;
    if (result == 1) return session;
    if (absl::Status status = session->Receive(what); !status.ok()) return status;
  }
}

absl::Status TlsSession::WriteAll(absl::string_view bytes, absl::string_view what) {
  while (!bytes.empty()) {
    ERR_clear_error();
    size_t written = 0;
    const int result =
        SSL_write_ex(openssl_->ssl, bytes.data(), std::min(bytes.size(), kWriteChunk), &written);
    if (result != 1) {
      if (absl::Status status = Diagnose(result, what); !status.ok()) return status;
      if (absl::Status status = Flush(what); !status.ok()) return status;
      if (absl::Status status = Receive(what); !status.ok()) return status;
      continue;
    }
    bytes.remove_prefix(written);
    if (absl::Status status = Flush(what); !status.ok()) return status;
  }
  return absl::OkStatus();
}

absl::StatusOr<size_t> TlsSession::Read(char* buffer, size_t capacity, absl::string_view what) {
  while (true) {
    ERR_clear_error();
    size_t read = 0;
    const int result = SSL_read_ex(openssl_->ssl, buffer, capacity, &read);
    if (result == 1) return read;
    if (absl::Status status = Diagnose(result, what); !status.ok()) return status;
    // TLS 1.3 may answer the server (a key update) while reading.
    if (absl::Status status = Flush(what); !status.ok()) return status;
    if (absl::Status status = Receive(what); !status.ok()) return status;
  }
}

absl::Status TlsSession::Flush(absl::string_view what) {
  char buffer[16 * 1024];
  int length = 0;
  while ((length = BIO_read(openssl_->to_network, buffer, sizeof(buffer))) > 0) {
    const char* next = buffer;
    size_t left = static_cast<size_t>(length);
    while (left > 0) {
      const ssize_t sent = send(socket_fd_, next, left, MSG_NOSIGNAL);
      if (sent < 0) {
        if (errno == EINTR) continue;
        return SocketError(errno, what);
      }
      next += sent;
      left -= static_cast<size_t>(sent);
    }
  }
  return absl::OkStatus();
}

absl::Status TlsSession::Receive(absl::string_view what) {
  char buffer[16 * 1024];
  while (true) {
    const ssize_t received = recv(socket_fd_, buffer, sizeof(buffer), 0);
    if (received > 0) {
      if (BIO_write(openssl_->from_network, buffer, static_cast<int>(received)) != received) {
        return absl::InternalError(absl::StrCat("redis: ", what, ": out of memory"));
      }
      return absl::OkStatus();
    }
    if (received == 0) {
      return absl::UnavailableError(
          absl::StrCat("redis: ", what, " failed: the server closed the connection"));
    }
    if (errno != EINTR) return SocketError(errno, what);
  }
}

absl::Status TlsSession::Diagnose(int result, absl::string_view what) {
  const int error = SSL_get_error(openssl_->ssl, result);
  if (error == SSL_ERROR_WANT_READ) return absl::OkStatus();
  if (error == SSL_ERROR_ZERO_RETURN) {
    return absl::UnavailableError(
        absl::StrCat("redis: ", what, " failed: the server closed the TLS connection"));
  }
  std::string reason = TakeOpenSslErrors();
  if (reason.empty()) reason = absl::StrCat("TLS error ", error);
  // "certificate verify failed" alone does not say which check failed.
  if (const long verified = SSL_get_verify_result(openssl_->ssl); verified != X509_V_OK) {
    absl::StrAppend(&reason, " (", X509_verify_cert_error_string(verified), ")");
  }
  return absl::UnavailableError(absl::StrCat("redis: ", what, " failed: ", reason));
}

}  // namespace getme::redis
