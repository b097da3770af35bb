#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace getme::redis {

// An owned copy of one Redis (RESP2) reply, so that no hiredis type leaves the library. An error
// reply at the top level becomes an absl::Status instead (redis_status.h); kError appears only
// inside an array, where a command's reply holds another's failure (EXEC, a script's table).
class RedisReply {
 public:
  enum class Type { kNil, kInteger, kString, kStatus, kError, kArray };

  static RedisReply Nil();
  static RedisReply Integer(std::int64_t value);
  static RedisReply String(std::string value);  // a bulk string: binary-safe
  static RedisReply Status(std::string value);  // a simple string such as OK or PONG
  static RedisReply Error(std::string text);
  static RedisReply Array(std::vector<RedisReply> elements);

  Type type() const { return type_; }
  bool is_nil() const { return type_ == Type::kNil; }
  // 0 unless type() is kInteger.
  std::int64_t integer() const { return integer_; }
  // The bytes of a kString, kStatus or kError; empty otherwise.
  const std::string& str() const { return str_; }
  // The elements of a kArray; empty otherwise.
  const std::vector<RedisReply>& elements() const { return elements_; }

  // For test failures and logs: e.g. ["a", 3, nil]; long strings are cut.
  std::string DebugString() const;

  friend bool operator==(const RedisReply&, const RedisReply&) = default;

 private:
  RedisReply() = default;

  Type type_ = Type::kNil;
  std::int64_t integer_ = 0;
  std::string str_;
  std::vector<RedisReply> elements_;
};

}  // namespace getme::redis
