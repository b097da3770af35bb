#include "redis/redis_address.h"

#include <optional>

#include "absl/status/status.h"
#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"

namespace getme::redis {
namespace {

constexpr absl::string_view kForm = "redis://[[user]:password@]host[:port][/db]";

std::optional<int> HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  c = absl::ascii_tolower(static_cast<unsigned char>(c));
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return std::nullopt;
}

std::optional<std::string> PercentDecode(absl::string_view text) {
  std::string decoded;
  decoded.reserve(text.size());
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '%') {
      decoded.push_back(text[i]);
      continue;
    }
    if (i + 2 >= text.size()) return std::nullopt;
    const std::optional<int> high = HexDigit(text[i + 1]);
    const std::optional<int> low = HexDigit(text[i + 2]);
    if (!high || !low) return std::nullopt;
    decoded.push_back(static_cast<char>(*high * 16 + *low));
    i += 2;
  }
  return decoded;
}

// A URL for the log only: user and host are not secret, the password is.
std::string HostForUrl(const std::string& host) {
  return absl::StrContains(host, ':') ? absl::StrCat("[", host, "]") : host;
}

}  // namespace

absl::StatusOr<RedisAddress> ParseRedisUrl(absl::string_view url) {
  const size_t scheme_end = url.find("://");
  if (scheme_end == absl::string_view::npos) {
    return absl::InvalidArgumentError(absl::StrCat("redis URL: no scheme, expected ", kForm));
  }
  const std::string scheme = absl::AsciiStrToLower(url.substr(0, scheme_end));
  if (scheme == "rediss") {
    return absl::UnimplementedError(
        "redis URL: rediss:// (TLS) is not supported: Debian bookworm's hiredis 0.14 has no TLS. "
        "Reach Redis over a private network, or put a TLS tunnel (stunnel, spiped) in front of "
        "it and give its local end as redis://");
  }
  if (scheme != "redis") {
    return absl::InvalidArgumentError(
        absl::StrCat("redis URL: scheme '", scheme, "://' is not redis://, expected ", kForm));
  }
  absl::string_view rest = url.substr(scheme_end + 3);
  if (rest.find_first_of("?#") != absl::string_view::npos) {
    return absl::InvalidArgumentError(
        "redis URL: query parameters and fragments ('?', '#') are not supported");
  }
  const size_t path_start = rest.find('/');
  absl::string_view authority = rest.substr(0, path_start);
  const absl::string_view path =
      path_start == absl::string_view::npos ? absl::string_view() : rest.substr(path_start + 1);

  RedisAddress address;
  // The last '@' ends the user information, so an unencoded '@' in a password still parses.
  const size_t at = authority.rfind('@');
  if (at != absl::string_view::npos) {
    const absl::string_view user_info = authority.substr(0, at);
    authority = authority.substr(at + 1);
    const size_t colon = user_info.find(':');
    if (colon == absl::string_view::npos) {
      return absl::InvalidArgumentError(
          "redis URL: a user without a password; write redis://:password@host for a password "
          "alone or redis://user:password@host for an ACL user");
    }
    std::optional<std::string> user = PercentDecode(user_info.substr(0, colon));
    std::optional<std::string> password = PercentDecode(user_info.substr(colon + 1));
    if (!user || !password) {
      return absl::InvalidArgumentError(
          "redis URL: bad percent-encoding in the user or password (a '%' must be followed by "
          "two hex digits; write '%25' for '%' itself)");
    }
    if (password->empty()) {
      return absl::InvalidArgumentError("redis URL: the password after ':' is empty");
    }
    address.user = *std::move(user);
    address.password = *std::move(password);
  }

  absl::string_view port_text;
  bool has_port = false;
  if (absl::StartsWith(authority, "[")) {  // an IPv6 literal, [::1]:6379
    const size_t close = authority.find(']');
    if (close == absl::string_view::npos) {
      return absl::InvalidArgumentError("redis URL: host '[' without its closing ']'");
    }
    address.host = std::string(authority.substr(1, close - 1));
    const absl::string_view after = authority.substr(close + 1);
    if (!after.empty()) {
      if (after[0] != ':') {
        return absl::InvalidArgumentError(
            absl::StrCat("redis URL: unexpected '", after, "' after the host"));
      }
      has_port = true;
      port_text = after.substr(1);
    }
  } else {
    const size_t colon = authority.find(':');
    address.host = std::string(authority.substr(0, colon));
    if (colon != absl::string_view::npos) {
      has_port = true;
      port_text = authority.substr(colon + 1);
    }
  }
  if (address.host.empty()) {
    return absl::InvalidArgumentError(absl::StrCat("redis URL: no host, expected ", kForm));
  }
  if (has_port) {
    int port = 0;
    if (!absl::SimpleAtoi(port_text, &port) || port < 1 || port > 65535 ||
        !absl::ascii_isdigit(static_cast<unsigned char>(port_text[0]))) {
      return absl::InvalidArgumentError(
          absl::StrCat("redis URL: port '", port_text, "' is not a number from 1 to 65535"));
    }
    address.port = port;
  }
  if (!path.empty()) {
    int db = 0;
    if (!absl::SimpleAtoi(path, &db) || db < 0 ||
        !absl::ascii_isdigit(static_cast<unsigned char>(path[0]))) {
      return absl::InvalidArgumentError(absl::StrCat(
          "redis URL: database '", path, "' is not a number from 0 (the path is /db, e.g. /2)"));
    }
    address.db = db;
  }
  return address;
}

std::string RedactedUrl(const RedisAddress& address) {
  std::string user_info;
  if (!address.password.empty()) user_info = absl::StrCat(address.user, ":***@");
  return absl::StrCat("redis://", user_info, HostForUrl(address.host), ":", address.port, "/",
                      address.db);
}

}  // namespace getme::redis
