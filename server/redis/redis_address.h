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
};

// redis://[[user]:password@]host[:port][/db], e.g. redis://:s3cret@redis:6379/2. The user and
// password may be percent-encoded (RFC 3986), which is how a password holding '@', ':' or '/'
// is written. A user without a password (redis://user@host) is refused: there would be nothing
// to send AUTH with. INVALID_ARGUMENT naming the part that is wrong (scheme, host, port,
// database, percent-encoding); the message never repeats the URL, which may hold the password.
// rediss:// (TLS) is UNIMPLEMENTED: Debian bookworm's hiredis 0.14 has no TLS support.
absl::StatusOr<RedisAddress> ParseRedisUrl(absl::string_view url);

// The address as a URL for logs and error messages, the password replaced by ***.
std::string RedactedUrl(const RedisAddress& address);

}  // namespace getme::redis
