#pragma once

#include <initializer_list>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

#include "absl/status/statusor.h"
#include "absl/time/time.h"
#include "redis/redis_address.h"
#include "redis/redis_reply.h"
#include "redis/redis_script.h"

namespace getme::redis {

class RedisConnection;

// A thread-safe Redis client: a pool of blocking connections, opened as concurrent calls need
// them (a call holds one connection for its duration, so a BLPOP waiting in one thread does not
// hold up the others), kept open for the next call.
//
// Failures: an error reply is a status (redis_status.h: scripts choose the code); a connection
// that fails (UNAVAILABLE) or times out (DEADLINE_EXCEEDED) is closed, and on UNAVAILABLE every
// idle connection is closed too, since they most likely lead to the same dead server: the next
// call opens a fresh one. Nothing is retried automatically: whether a command is safe to send
// twice (an INCR, a queue pop) is the caller's knowledge, not this library's.
//
// Connections go back to the pool after each call, so a call must leave its connection as it
// found it: no SELECT, AUTH, SUBSCRIBE, WATCH, or MULTI whose EXEC is not in the same Pipeline.
class RedisClient {
 public:
  // Opens the first connection (with AUTH and SELECT when the address has them) and checks it
  // with PING. UNAVAILABLE naming the redacted address and hiredis's errstr if it cannot be made
  // within `connect_timeout`; UNAUTHENTICATED when the password is wrong or missing;
  // INVALID_ARGUMENT when the database does not exist. `command_timeout` bounds each call
  // (DEADLINE_EXCEEDED after it).
  static absl::StatusOr<std::unique_ptr<RedisClient>> Connect(
      RedisAddress address, absl::Duration connect_timeout = absl::Seconds(5),
      absl::Duration command_timeout = absl::Seconds(10));
  ~RedisClient();
  RedisClient(const RedisClient&) = delete;
  RedisClient& operator=(const RedisClient&) = delete;

  // One command, argv-style: each argument is sent as is (binary-safe, NUL bytes included).
  absl::StatusOr<RedisReply> Command(std::initializer_list<std::string_view> args);
  absl::StatusOr<RedisReply> Command(const std::vector<std::string>& args);

  // A command that waits on the server (BLPOP, BLMOVE, XREAD BLOCK ms) for up to `block`: its
  // connection's timeout is `block` + command_timeout for this call. `block` must match the
  // timeout written in the command; a blocking command sent through Command() instead times
  // out after command_timeout.
  absl::StatusOr<RedisReply> Blocking(const std::vector<std::string>& args, absl::Duration block);

  // Several commands in one round trip, replies in order. Not a transaction (wrap them in
  // MULTI/EXEC for that): every command runs, and the first error reply fails the whole call.
  absl::StatusOr<std::vector<RedisReply>> Pipeline(
      const std::vector<std::vector<std::string>>& commands);

  // Runs a Lua script by EVALSHA; when the server does not have it (NOSCRIPT: restarted, SCRIPT
  // FLUSH) sends SCRIPT LOAD and EVALSHA again, both in one round trip.
  absl::StatusOr<RedisReply> Eval(const RedisScript& script, const std::vector<std::string>& keys,
                                  const std::vector<std::string>& args);

  const RedisAddress& address() const { return address_; }
  // Connections open now, idle or in use (for tests and metrics).
  int open_connections() const;

 private:
  RedisClient(RedisAddress address, absl::Duration connect_timeout, absl::Duration command_timeout);

  absl::StatusOr<std::unique_ptr<RedisConnection>> Acquire();
  void Release(std::unique_ptr<RedisConnection> connection);
  // Runs `commands` on a pooled connection (its timeout raised by `extra_timeout` if not zero)
  // and returns their replies, error replies included as kError elements.
  absl::StatusOr<std::vector<RedisReply>> Exchange(
      const std::vector<std::vector<std::string_view>>& commands,
      absl::Duration extra_timeout = absl::ZeroDuration());

  const RedisAddress address_;
  const std::string redacted_url_;
  const absl::Duration connect_timeout_;
  const absl::Duration command_timeout_;
  // std::mutex, not absl::Mutex: Debian's abseil is not built for ThreadSanitizer, which would
  // then miss the lock and report the pool as racing.
  mutable std::mutex mutex_;
  std::vector<std::unique_ptr<RedisConnection>> idle_;  // guarded by mutex_
  int open_ = 0;                                        // guarded by mutex_
};

}  // namespace getme::redis
