#include "redis/redis_connection.h"

#include <hiredis/hiredis.h>

#include <cerrno>
#include <utility>

#include "absl/strings/str_cat.h"
#include "redis/redis_status.h"

namespace getme::redis {
namespace {

RedisReply CopyReply(const redisReply& reply) {
  switch (reply.type) {
    case REDIS_REPLY_INTEGER:
      return RedisReply::Integer(reply.integer);
    case REDIS_REPLY_STRING:
      return RedisReply::String(std::string(reply.str, reply.len));
    case REDIS_REPLY_STATUS:
      return RedisReply::Status(std::string(reply.str, reply.len));
    case REDIS_REPLY_ERROR:
      return RedisReply::Error(std::string(reply.str, reply.len));
    case REDIS_REPLY_ARRAY: {
      std::vector<RedisReply> elements;
      elements.reserve(reply.elements);
      for (size_t i = 0; i < reply.elements; ++i) elements.push_back(CopyReply(*reply.element[i]));
      return RedisReply::Array(std::move(elements));
    }
    default:  // REDIS_REPLY_NIL; RESP2 has no other types
      return RedisReply::Nil();
  }
}

// A command's words as hiredis's argv functions take them.
struct CommandArgv {
  explicit CommandArgv(const RedisArgs& command) {
    for (std::string_view word : command) {
      words.push_back(word.data());
      lengths.push_back(word.size());
    }
  }
  int count() const { return static_cast<int>(words.size()); }
  std::vector<const char*> words;
  std::vector<size_t> lengths;
};

struct ReplyDeleter {
  void operator()(void* reply) const { freeReplyObject(reply); }
};

// What a failed exchange was doing, for its status: the command names, never their arguments
// (values may be large or secret, e.g. AUTH's password).
std::string Describe(const std::vector<RedisArgs>& commands, absl::string_view redacted_url) {
  if (commands.size() == 1) {
    // Debian's abseil has its own string_view, which StrCat takes and std::string_view is not.
    const std::string_view name = commands[0][0];
    return absl::StrCat(absl::string_view(name.data(), name.size()), " on ", redacted_url);
  }
  return absl::StrCat("pipeline of ", commands.size(), " commands on ", redacted_url);
}

}  // namespace

absl::StatusOr<std::unique_ptr<RedisConnection>> RedisConnection::Open(
    const RedisAddress& address, absl::Duration connect_timeout, absl::Duration command_timeout) {
  const std::string redacted_url = RedactedUrl(address);
  redisContext* context =
      redisConnectWithTimeout(address.host.c_str(), address.port, absl::ToTimeval(connect_timeout));
  if (context == nullptr) {
    return absl::UnavailableError(
        absl::StrCat("redis: cannot connect to ", redacted_url, ": out of memory"));
  }
  if (context->err != 0) {
    absl::Status status = absl::UnavailableError(
        absl::StrCat("redis: cannot connect to ", redacted_url, ": ", context->errstr));
    redisFree(context);
    return status;
  }
  std::unique_ptr<RedisConnection> connection(new RedisConnection(context, redacted_url));
  // hiredis 0.14 applies the connect timeout to connect() only; AUTH and SELECT belong to
  // connecting too, so they get the same bound.
  if (absl::Status status = connection->SetTimeout(connect_timeout); !status.ok()) return status;
  redisEnableKeepAlive(context);  // notices a vanished server during a long BLPOP
  if (address.tls) {
    absl::StatusOr<std::unique_ptr<TlsSession>> session =
        TlsSession::Handshake(context->fd, address, redacted_url);
    if (absl::IsDeadlineExceeded(session.status())) {
      return absl::UnavailableError(session.status().message());  // as for AUTH below
    }
    if (!session.ok()) return session.status();
    connection->tls_ = *std::move(session);
  }

  auto login_step = [&](const RedisArgs& command, absl::StatusCode refused_code,
                        absl::string_view name) -> absl::Status {
    absl::StatusOr<std::vector<RedisReply>> replies = connection->Exchange({command});
    // Its message names the command and the server; a timeout while connecting is UNAVAILABLE
    // like any other failure to connect.
    if (!replies.ok()) return absl::UnavailableError(replies.status().message());
    const RedisReply& reply = replies->front();
    if (reply.type() == RedisReply::Type::kError) {
      return absl::Status(refused_code, absl::StrCat("redis: ", name, " on ", redacted_url,
                                                     " refused: ", reply.str()));
    }
    return absl::OkStatus();
  };
  if (!address.password.empty()) {
    RedisArgs auth = {"AUTH"};
    if (!address.user.empty()) auth.push_back(address.user);
    auth.push_back(address.password);
    if (absl::Status status = login_step(auth, absl::StatusCode::kUnauthenticated, "AUTH");
        !status.ok()) {
      return status;
    }
  }
  if (address.db != 0) {
    const std::string db = absl::StrCat(address.db);
    if (absl::Status status = login_step({"SELECT", db}, absl::StatusCode::kInvalidArgument,
                                         absl::StrCat("SELECT ", address.db));
        !status.ok()) {
      return status;
    }
  }
  if (absl::Status status = connection->SetTimeout(command_timeout); !status.ok()) return status;
  return connection;
}

RedisConnection::~RedisConnection() {
  tls_.reset();  // its close_notify goes out before hiredis closes the socket
  redisFree(context_);
}

absl::Status RedisConnection::SetTimeout(absl::Duration timeout) {
  if (redisSetTimeout(context_, absl::ToTimeval(timeout)) != REDIS_OK) {
    broken_ = true;
    return absl::UnavailableError(absl::StrCat("redis: cannot set the socket timeout on ",
                                               redacted_url_, ": ", context_->errstr));
  }
  return absl::OkStatus();
}

absl::StatusOr<std::vector<RedisReply>> RedisConnection::Exchange(
    const std::vector<RedisArgs>& commands) {
  if (broken_) {
    return absl::UnavailableError(
        absl::StrCat("redis: connection to ", redacted_url_, " is broken"));
  }
  if (tls_ != nullptr) return ExchangeOverTls(commands);
  for (const RedisArgs& command : commands) {
    CommandArgv argv(command);  // not const: hiredis takes a const char**
    // Appending only fills hiredis's output buffer; the first redisGetReply writes it all.
    if (redisAppendCommandArgv(context_, argv.count(), argv.words.data(), argv.lengths.data()) !=
        REDIS_OK) {
      broken_ = true;
      return StatusFromConnectionError(context_->err, errno, context_->errstr,
                                       Describe(commands, redacted_url_));
    }
  }
  std::vector<RedisReply> replies;
  replies.reserve(commands.size());
  for (size_t i = 0; i < commands.size(); ++i) {
    void* raw = nullptr;
    errno = 0;
    if (redisGetReply(context_, &raw) != REDIS_OK || raw == nullptr) {
      const int error_number = errno;
      broken_ = true;
      return StatusFromConnectionError(context_->err, error_number, context_->errstr,
                                       Describe(commands, redacted_url_));
    }
    std::unique_ptr<void, ReplyDeleter> owned(raw);
    replies.push_back(CopyReply(*static_cast<const redisReply*>(raw)));
  }
  return replies;
}

absl::StatusOr<std::vector<RedisReply>> RedisConnection::ExchangeOverTls(
    const std::vector<RedisArgs>& commands) {
  // Every command formatted into one request, as redisAppendCommandArgv would buffer them.
  std::string request;
  for (const RedisArgs& command : commands) {
    CommandArgv argv(command);  // not const: hiredis takes a const char**
    char* formatted = nullptr;
    const int length =
        redisFormatCommandArgv(&formatted, argv.count(), argv.words.data(), argv.lengths.data());
    if (length < 0) {
      broken_ = true;
      return absl::InternalError(
          absl::StrCat("redis: ", Describe(commands, redacted_url_), ": out of memory"));
    }
    request.append(formatted, static_cast<size_t>(length));
    redisFreeCommand(formatted);
  }
  const std::string what = Describe(commands, redacted_url_);
  if (absl::Status status = tls_->WriteAll(request, what); !status.ok()) {
    broken_ = true;
    return status;
  }
  // hiredis's own reader (the context's, unused otherwise) parses what TLS decrypts.
  redisReader* reader = context_->reader;
  std::vector<RedisReply> replies;
  replies.reserve(commands.size());
  char buffer[16 * 1024];
  while (replies.size() < commands.size()) {
    void* raw = nullptr;
    if (redisReaderGetReply(reader, &raw) != REDIS_OK) {
      broken_ = true;
      return absl::UnavailableError(
          absl::StrCat("redis: ", what, " failed: protocol error: ", reader->errstr));
    }
    if (raw == nullptr) {
      absl::StatusOr<size_t> received = tls_->Read(buffer, sizeof(buffer), what);
      if (!received.ok()) {
        broken_ = true;
        return received.status();
      }
      if (redisReaderFeed(reader, buffer, *received) != REDIS_OK) {
        broken_ = true;
        return absl::UnavailableError(
            absl::StrCat("redis: ", what, " failed: protocol error: ", reader->errstr));
      }
      continue;
    }
    std::unique_ptr<void, ReplyDeleter> owned(raw);
    replies.push_back(CopyReply(*static_cast<const redisReply*>(raw)));
  }
  return replies;
}

}  // namespace getme::redis
