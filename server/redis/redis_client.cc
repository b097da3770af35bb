#include "redis/redis_client.h"

#include <utility>

#include "absl/status/status.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "redis/redis_connection.h"
#include "redis/redis_status.h"

namespace getme::redis {
namespace {

using Commands = std::vector<RedisArgs>;

RedisArgs Views(const std::vector<std::string>& args) {
  return RedisArgs(args.begin(), args.end());
}

// The first top-level error reply as its status; OK when there is none.
absl::Status FirstError(const std::vector<RedisReply>& replies) {
  for (const RedisReply& reply : replies) {
    if (reply.type() == RedisReply::Type::kError) return StatusFromErrorReply(reply.str());
  }
  return absl::OkStatus();
}

absl::Status CheckArgs(const RedisArgs& args) {
  if (args.empty()) return absl::InvalidArgumentError("redis: a command without arguments");
  return absl::OkStatus();
}

absl::StatusOr<RedisReply> SingleReply(absl::StatusOr<std::vector<RedisReply>> replies) {
  if (!replies.ok()) return replies.status();
  if (absl::Status status = FirstError(*replies); !status.ok()) return status;
  return std::move(replies->front());
}

}  // namespace

RedisClient::RedisClient(RedisAddress address, absl::Duration connect_timeout,
                         absl::Duration command_timeout)
    : address_(std::move(address)),
      redacted_url_(RedactedUrl(address_)),
      connect_timeout_(connect_timeout),
      command_timeout_(command_timeout) {}

RedisClient::~RedisClient() = default;

absl::StatusOr<std::unique_ptr<RedisClient>> RedisClient::Connect(RedisAddress address,
                                                                  absl::Duration connect_timeout,
                                                                  absl::Duration command_timeout) {
  std::unique_ptr<RedisClient> client(
      new RedisClient(std::move(address), connect_timeout, command_timeout));
  absl::StatusOr<std::unique_ptr<RedisConnection>> connection = client->Acquire();
  if (!connection.ok()) return connection.status();
  // A server that needs a password we did not send accepts the connection and refuses the first
  // command: PING makes that (and a port that is not Redis at all) fail here, at startup.
  absl::StatusOr<std::vector<RedisReply>> pong = (*connection)->Exchange({{"PING"}});
  if (!pong.ok()) return pong.status();
  const RedisReply& reply = pong->front();
  if (reply.type() == RedisReply::Type::kError) {
    const absl::StatusCode code = absl::StartsWith(reply.str(), "NOAUTH")
                                      ? absl::StatusCode::kUnauthenticated
                                      : absl::StatusCode::kUnavailable;
    return absl::Status(
        code, absl::StrCat("redis: PING on ", client->redacted_url_, " refused: ", reply.str()));
  }
  client->Release(*std::move(connection));
  return client;
}

int RedisClient::open_connections() const {
  std::lock_guard lock(mutex_);
  return open_;
}

absl::StatusOr<std::unique_ptr<RedisConnection>> RedisClient::Acquire() {
  {
    std::lock_guard lock(mutex_);
    if (!idle_.empty()) {
      std::unique_ptr<RedisConnection> connection = std::move(idle_.back());
      idle_.pop_back();
      return connection;
    }
  }
  // Connecting takes a round trip or more: not under the lock, which other calls need.
  absl::StatusOr<std::unique_ptr<RedisConnection>> connection =
      RedisConnection::Open(address_, connect_timeout_, command_timeout_);
  if (connection.ok()) {
    std::lock_guard lock(mutex_);
    ++open_;
  }
  return connection;
}

void RedisClient::Release(std::unique_ptr<RedisConnection> connection) {
  std::lock_guard lock(mutex_);
  if (!connection->broken()) {
    idle_.push_back(std::move(connection));
    return;
  }
  --open_;
  connection.reset();
}

absl::StatusOr<std::vector<RedisReply>> RedisClient::Exchange(const Commands& commands,
                                                              absl::Duration extra_timeout) {
  absl::StatusOr<std::unique_ptr<RedisConnection>> connection = Acquire();
  if (!connection.ok()) return connection.status();
  RedisConnection& used = **connection;
  absl::StatusOr<std::vector<RedisReply>> replies;
  if (extra_timeout > absl::ZeroDuration()) {
    if (absl::Status status = used.SetTimeout(command_timeout_ + extra_timeout); !status.ok()) {
      replies = status;
    }
  }
  if (!used.broken()) replies = used.Exchange(commands);
  if (!used.broken() && extra_timeout > absl::ZeroDuration()) {
    if (absl::Status status = used.SetTimeout(command_timeout_); !status.ok() && replies.ok()) {
      replies = status;
    }
  }
  const bool server_lost = used.broken() && absl::IsUnavailable(replies.status());
  Release(*std::move(connection));
  if (server_lost) {
    // The idle connections lead to the same server: if it died or restarted, each would fail
    // one more call. Closing them makes the next call connect afresh.
    std::vector<std::unique_ptr<RedisConnection>> stale;
    std::lock_guard lock(mutex_);
    stale.swap(idle_);
    open_ -= static_cast<int>(stale.size());
  }
  return replies;
}

absl::StatusOr<RedisReply> RedisClient::Command(std::initializer_list<std::string_view> args) {
  RedisArgs command(args.begin(), args.end());
  if (absl::Status status = CheckArgs(command); !status.ok()) return status;
  return SingleReply(Exchange({std::move(command)}));
}

absl::StatusOr<RedisReply> RedisClient::Command(const std::vector<std::string>& args) {
  RedisArgs command = Views(args);
  if (absl::Status status = CheckArgs(command); !status.ok()) return status;
  return SingleReply(Exchange({std::move(command)}));
}

absl::StatusOr<RedisReply> RedisClient::Blocking(const std::vector<std::string>& args,
                                                 absl::Duration block) {
  RedisArgs command = Views(args);
  if (absl::Status status = CheckArgs(command); !status.ok()) return status;
  // A zero `block` would leave the command timeout alone, which is what a non-blocking call
  // needs anyway; a negative one is a caller's mistake.
  if (block < absl::ZeroDuration()) {
    return absl::InvalidArgumentError("redis: a negative blocking time");
  }
  return SingleReply(Exchange({std::move(command)}, block));
}

absl::StatusOr<std::vector<RedisReply>> RedisClient::Pipeline(
    const std::vector<std::vector<std::string>>& commands) {
  if (commands.empty()) return std::vector<RedisReply>();
  Commands views;
  views.reserve(commands.size());
  for (const std::vector<std::string>& args : commands) {
    views.push_back(Views(args));
    if (absl::Status status = CheckArgs(views.back()); !status.ok()) return status;
  }
  absl::StatusOr<std::vector<RedisReply>> replies = Exchange(views);
  if (!replies.ok()) return replies.status();
  if (absl::Status status = FirstError(*replies); !status.ok()) return status;
  return replies;
}

absl::StatusOr<RedisReply> RedisClient::Eval(const RedisScript& script,
                                             const std::vector<std::string>& keys,
                                             const std::vector<std::string>& args) {
  const std::string key_count = absl::StrCat(keys.size());
  RedisArgs evalsha = {"EVALSHA", script.sha1(), key_count};
  evalsha.insert(evalsha.end(), keys.begin(), keys.end());
  evalsha.insert(evalsha.end(), args.begin(), args.end());
  absl::StatusOr<std::vector<RedisReply>> replies = Exchange({evalsha});
  if (!replies.ok()) return replies.status();
  const RedisReply& first = replies->front();
  if (first.type() != RedisReply::Type::kError || !absl::StartsWith(first.str(), "NOSCRIPT")) {
    return SingleReply(std::move(replies));
  }
  replies = Exchange({{"SCRIPT", "LOAD", script.source()}, evalsha});
  if (!replies.ok()) return replies.status();
  if (absl::Status status = FirstError(*replies); !status.ok()) return status;
  return std::move(replies->back());
}

}  // namespace getme::redis
