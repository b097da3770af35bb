#include "redis/redis_reply.h"

#include <utility>

#include "absl/strings/escaping.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_join.h"

namespace getme::redis {

RedisReply RedisReply::Nil() { return RedisReply(); }

RedisReply RedisReply::Integer(std::int64_t value) {
  RedisReply reply;
  reply.type_ = Type::kInteger;
  reply.integer_ = value;
  return reply;
}

RedisReply RedisReply::String(std::string value) {
  RedisReply reply;
  reply.type_ = Type::kString;
  reply.str_ = std::move(value);
  return reply;
}

RedisReply RedisReply::Status(std::string value) {
  RedisReply reply;
  reply.type_ = Type::kStatus;
  reply.str_ = std::move(value);
  return reply;
}

RedisReply RedisReply::Error(std::string text) {
  RedisReply reply;
  reply.type_ = Type::kError;
  reply.str_ = std::move(text);
  return reply;
}

RedisReply RedisReply::Array(std::vector<RedisReply> elements) {
  RedisReply reply;
  reply.type_ = Type::kArray;
  reply.elements_ = std::move(elements);
  return reply;
}

std::string RedisReply::DebugString() const {
  // Values may be megabytes of protobuf bytes: a log line shows their start and size.
  constexpr size_t kShown = 64;
  auto shown = [this] {
    std::string text = absl::CHexEscape(str_.substr(0, kShown));
    if (str_.size() > kShown) absl::StrAppend(&text, "... (", str_.size(), " bytes)");
    return text;
  };
  switch (type_) {
    case Type::kNil:
      return "nil";
    case Type::kInteger:
      return absl::StrCat(integer_);
    case Type::kString:
      return absl::StrCat("\"", shown(), "\"");
    case Type::kStatus:
      return absl::StrCat("+", shown());
    case Type::kError:
      return absl::StrCat("-", shown());
    case Type::kArray:
      return absl::StrCat("[",
                          absl::StrJoin(elements_, ", ",
                                        [](std::string* out, const RedisReply& element) {
                                          out->append(element.DebugString());
                                        }),
                          "]");
  }
  return "?";
}

}  // namespace getme::redis
