#pragma once

#include <string>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"

namespace getme::redis {

// Where a Redis server listens and how to log in to it: the parsed form of a redis:// URL.
struct RedisAddress {
  std::string host;  // a name or an IP address (IPv6 without its URL brackets)
  int port = 6379;
  // Redis 6+ ACL user. Empty: a password alone is sent as `AUTH password`, which logs in as the
  // `default` user (and is all that Redis before 6 understands); with a user the login is
  // `AUTH user password`.
  std::string user;
  std::string password;  // empty: no AUTH
  int db = 0;            // sent as SELECT when not 0

  // rediss://: the connection is TLS (1.2 or later); the server's certificate must chain to
  // `tls_ca_file` (PEM) or, when that is empty, to the system's trusted CAs, and name
  // `tls_server_name` or, when that is empty, `host` (a DNS name or an IP address in its
  // subjectAltName). A client certificate is sent when `tls_cert_file` and `tls_key_file` are
  // set (Redis's tls-auth-clients, on by default).
  bool tls = false;
  std::string tls_ca_file;
  std::string tls_cert_file;
  std::string tls_key_file;
  // The name sent as SNI and checked against the certificate, for a server reached by another
  // address than the one its certificate names (an IP address, a tunnel); redis-cli's --sni.
  std::string tls_server_name;
};

// redis://[[user]:password@]host[:port][/db], e.g. redis://:s3cret@redis:6379/2, or the same
// with rediss:// for TLS, which takes the files as query parameters named like redis-cli's
// flags: rediss://host:6380/0?cacert=/etc/ca.pem&cert=/etc/client.pem&key=/etc/client.key
// (cert and key together or neither; sni=NAME for tls_server_name). The user, password and
// parameter values may be percent-encoded (RFC 3986), which is how a password holding '@', ':' or
// '/' is written. A user without a password (redis://user@host) is refused: there would be nothing
// to send AUTH with. INVALID_ARGUMENT naming the part that is wrong (scheme, host, port, database,
// percent-encoding, parameter); the message never repeats the URL, which may hold the password.
absl::StatusOr<RedisAddress> ParseRedisUrl(absl::string_view url);

// The address as a URL for logs and error messages, the password replaced by *** (the TLS files
// are left out: they are not secret, but long).
std::string RedactedUrl(const RedisAddress& address);

}  // namespace getme::redis
