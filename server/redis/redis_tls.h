#pragma once

#include <memory>
#include <string>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "redis/redis_address.h"

namespace getme::redis {

// TLS over a connected, blocking socket that hiredis opened, for rediss:// addresses. Debian
// bookworm's hiredis 0.14 predates hiredis's own TLS (1.0), so the bytes go through OpenSSL
// here and hiredis only formats commands and parses replies (RedisConnection).
//
// OpenSSL reads and writes memory buffers and this class moves them over the socket with
// send(MSG_NOSIGNAL) and recv: a server that closed the connection then fails the write with
// EPIPE instead of killing the process with SIGPIPE, and the socket's SO_RCVTIMEO/SO_SNDTIMEO
// (RedisConnection::SetTimeout) bound every wait, the handshake's included.
class TlsSession {
 public:
  // Verifies the server's certificate against the address's CA file (or the system's CAs) and
  // its host name or IP address, and sends the client certificate when the address has one.
  // UNAVAILABLE naming the server and OpenSSL's reason (e.g. "certificate verify failed") when
  // the handshake fails; DEADLINE_EXCEEDED when the socket timeout expires during it;
  // INVALID_ARGUMENT naming the file when a CA, certificate or key file cannot be loaded.
  static absl::StatusOr<std::unique_ptr<TlsSession>> Handshake(int socket_fd,
                                                               const RedisAddress& address,
                                                               absl::string_view redacted_url);
  ~TlsSession();
  TlsSession(const TlsSession&) = delete;
  TlsSession& operator=(const TlsSession&) = delete;

  // Encrypts and sends all of `bytes`. `what` names the exchange for the status, as in
  // StatusFromConnectionError: DEADLINE_EXCEEDED on a socket timeout, UNAVAILABLE otherwise.
  absl::Status WriteAll(absl::string_view bytes, absl::string_view what);

  // Decrypted bytes into `buffer`, at least one, waiting for the server as needed; the same
  // statuses as WriteAll, UNAVAILABLE when the server closed the connection.
  absl::StatusOr<size_t> Read(char* buffer, size_t capacity, absl::string_view what);

 private:
  struct OpenSsl;  // SSL_CTX, SSL and the two memory BIOs, kept out of this header
  TlsSession(int socket_fd, std::unique_ptr<OpenSsl> openssl);

  // Sends what OpenSSL has written into its outgoing buffer.
  absl::Status Flush(absl::string_view what);
  // Receives what the socket has (waiting up to its timeout) into OpenSSL's incoming buffer.
  absl::Status Receive(absl::string_view what);
  // Why the last SSL_* call returned `result`; OK when it only needs more bytes from the server
  // (SSL_ERROR_WANT_READ), which the caller then receives.
  absl::Status Diagnose(int result, absl::string_view what);

  int socket_fd_;
  std::unique_ptr<OpenSsl> openssl_;
};

}  // namespace getme::redis
