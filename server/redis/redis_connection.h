#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "redis/redis_address.h"
#include "redis/redis_reply.h"
#include "redis/redis_tls.h"

struct redisContext;

namespace getme::redis {

// One argv-style command: its words, binary-safe.
using RedisArgs = std::vector<std::string_view>;

// One blocking hiredis connection, used by one thread at a time (RedisClient's pool hands it
// out). Internal to getme_redis: callers use RedisClient. For rediss:// addresses hiredis opens
// the socket and parses replies while TlsSession carries the bytes.
class RedisConnection {
 public:
  // Connects within `connect_timeout` (the TLS handshake included), then sends AUTH and SELECT when
  // the address asks for them (bounded by the same timeout) and leaves `command_timeout` as the
  // socket timeout. UNAVAILABLE naming the redacted address and hiredis's errstr (or OpenSSL's
  // reason) when the server cannot be reached; INVALID_ARGUMENT naming a TLS file that cannot be
  // used; UNAUTHENTICATED when AUTH is refused; INVALID_ARGUMENT when SELECT is.
  static absl::StatusOr<std::unique_ptr<RedisConnection>> Open(const RedisAddress& address,
                                                               absl::Duration connect_timeout,
                                                               absl::Duration command_timeout);
  ~RedisConnection();
  RedisConnection(const RedisConnection&) = delete;
  RedisConnection& operator=(const RedisConnection&) = delete;

  // The socket's send and receive timeout for the following exchanges.
  absl::Status SetTimeout(absl::Duration timeout);

  // Sends every command in one write and reads their replies in order. A top-level error reply
  // is returned as a kError element, so that one failing command does not leave the others'
  // replies unread. A failed or timed-out exchange (UNAVAILABLE, DEADLINE_EXCEEDED) marks the
  // connection broken: it must then be closed, not reused.
  absl::StatusOr<std::vector<RedisReply>> Exchange(const std::vector<RedisArgs>& commands);

  bool broken() const { return broken_; }

 private:
  absl::StatusOr<std::vector<RedisReply>> ExchangeOverTls(const std::vector<RedisArgs>& commands);

  RedisConnection(redisContext* context, std::string redacted_url)
      : context_(context), redacted_url_(std::move(redacted_url)) {}

  redisContext* context_;
  std::string redacted_url_;
  std::unique_ptr<TlsSession> tls_;  // rediss:// only
  bool broken_ = false;
};

}  // namespace getme::redis
