#include "redis/redis_status.h"

#include <hiredis/hiredis.h>

#include <cerrno>
#include <regex>
#include <string>

#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"

namespace getme::redis {
namespace {

// Redis 7 (measured with redis-server 7.0.15): `error("X msg")` reaches the client as
// "ERR user_script:1: X msg script: <sha1>, on @user_script:1.", `error({err="X msg"})` and a
// failed redis.call as "X msg script: <sha1>, on @user_script:1."; redis.error_reply("X msg")
// and `return {err="X msg"}` arrive untouched.
absl::string_view WithoutScriptDecoration(absl::string_view text) {
  static const std::regex kPrefix(R"(^ERR user_script:\d+: )");
  static const std::regex kSuffix(R"( script: [0-9a-f]{40}, on @user_script:\d+\.$)");
  std::cmatch match;
  if (std::regex_search(text.begin(), text.end(), match, kSuffix)) {
    text = text.substr(0, static_cast<size_t>(match.position(0)));
  }
  if (std::regex_search(text.begin(), text.end(), match, kPrefix)) {
    text.remove_prefix(static_cast<size_t>(match.length(0)));
  }
  return text;
}

struct NamedCode {
  absl::string_view name;
  absl::StatusCode code;
};

constexpr NamedCode kCodes[] = {
    {"CANCELLED", absl::StatusCode::kCancelled},
    {"UNKNOWN", absl::StatusCode::kUnknown},
    {"INVALID_ARGUMENT", absl::StatusCode::kInvalidArgument},
    {"DEADLINE_EXCEEDED", absl::StatusCode::kDeadlineExceeded},
    {"NOT_FOUND", absl::StatusCode::kNotFound},
    {"ALREADY_EXISTS", absl::StatusCode::kAlreadyExists},
    {"PERMISSION_DENIED", absl::StatusCode::kPermissionDenied},
    {"RESOURCE_EXHAUSTED", absl::StatusCode::kResourceExhausted},
    {"FAILED_PRECONDITION", absl::StatusCode::kFailedPrecondition},
    {"ABORTED", absl::StatusCode::kAborted},
    {"OUT_OF_RANGE", absl::StatusCode::kOutOfRange},
    {"UNIMPLEMENTED", absl::StatusCode::kUnimplemented},
    {"INTERNAL", absl::StatusCode::kInternal},
    {"UNAVAILABLE", absl::StatusCode::kUnavailable},
    {"DATA_LOSS", absl::StatusCode::kDataLoss},
    {"UNAUTHENTICATED", absl::StatusCode::kUnauthenticated},
};

}  // namespace

absl::Status StatusFromErrorReply(absl::string_view text) {
  const absl::string_view stripped = WithoutScriptDecoration(text);
  for (const NamedCode& named : kCodes) {
    if (!absl::StartsWith(stripped, named.name)) continue;
    absl::string_view message = stripped.substr(named.name.size());
    if (!message.empty() && message[0] != ' ' && message[0] != ':') continue;
    if (!message.empty()) message.remove_prefix(1);
    return absl::Status(named.code, absl::StripLeadingAsciiWhitespace(message));
  }
  // Redis over its maxmemory with noeviction refuses writes with "OOM ...": a full store, which
  // a caller may retry once results were fetched or expired.
  if (absl::StartsWith(stripped, "OOM ")) {
    return absl::ResourceExhaustedError(absl::StrCat("redis: ", stripped));
  }
  return absl::InternalError(absl::StrCat("redis: ", text));
}

absl::Status StatusFromConnectionError(int hiredis_error, int error_number,
                                       absl::string_view errstr, absl::string_view what) {
  // hiredis 0.14 reports an expired SO_RCVTIMEO/SO_SNDTIMEO as REDIS_ERR_IO with errno EAGAIN
  // ("Resource temporarily unavailable"). ETIMEDOUT is not ours: on an open connection it is TCP
  // keepalive giving up on a vanished server, which is UNAVAILABLE.
  const bool timed_out =
      hiredis_error == REDIS_ERR_IO && (error_number == EAGAIN || error_number == EWOULDBLOCK);
  if (timed_out) {
    return absl::DeadlineExceededError(absl::StrCat("redis: ", what, " timed out (", errstr, ")"));
  }
  return absl::UnavailableError(absl::StrCat("redis: ", what, " failed: ", errstr));
}

}  // namespace getme::redis
