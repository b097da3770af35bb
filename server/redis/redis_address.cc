#include "redis/redis_address.h"

#include <optional>

#include "absl/status/status.h"
#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/numbers.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"

namespace getme::redis {
namespace {

constexpr absl::string_view kForm = "redis[s]://[[user]:password@]host[:port][/db]";
constexpr absl::string_view kTlsParameters = "cacert, cert, key, sni";

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

// cacert=PATH&cert=PATH&key=PATH&sni=NAME, each at most once, values percent-decoded.
absl::Status ParseTlsParameters(absl::string_view query, RedisAddress& address) {
  for (absl::string_view parameter : absl::StrSplit(query, '&')) {
    const size_t equals = parameter.find('=');
    const absl::string_view name = parameter.substr(0, equals);
    std::string* field = name == "cacert" ? &address.tls_ca_file
                         : name == "cert" ? &address.tls_cert_file
                         : name == "key"  ? &address.tls_key_file
                         : name == "sni"  ? &address.tls_server_name
                                          : nullptr;
    if (field == nullptr) {
      return absl::InvalidArgumentError(absl::StrCat("redis URL: unknown parameter '", name,
                                                     "' (rediss:// takes ", kTlsParameters, ")"));
    }
    std::optional<std::string> value = equals == absl::string_view::npos
                                           ? std::nullopt
                                           : PercentDecode(parameter.substr(equals + 1));
    if (!value || value->empty()) {
      return absl::InvalidArgumentError(
          name == "sni" ? std::string("redis URL: parameter 'sni' needs a host name: sni=NAME")
                        : absl::StrCat("redis URL: parameter '", name,
                                       "' needs a file path: ", name, "=PATH"));
    }
    if (!field->empty()) {
      return absl::InvalidArgumentError(
          absl::StrCat("redis URL: parameter '", name, "' is given twice"));
    }
    *field = *std::move(value);
  }
  if (address.tls_cert_file.empty() != address.tls_key_file.empty()) {
    return absl::InvalidArgumentError(
        "redis URL: 'cert' and 'key' go together: a client certificate needs its private key");
  }
  return absl::OkStatus();
}

}  // namespace

absl::StatusOr<RedisAddress> ParseRedisUrl(absl::string_view url) {
  const size_t scheme_end = url.find("://");
  if (scheme_end == absl::string_view::npos) {
    return absl::InvalidArgumentError(absl::StrCat("redis URL: no scheme, expected ", kForm));
  }
  const std::string scheme = absl::AsciiStrToLower(url.substr(0, scheme_end));
  if (scheme != "redis" && scheme != "rediss") {
    return absl::InvalidArgumentError(absl::StrCat(
        "redis URL: scheme '", scheme, "://' is neither redis:// nor rediss://, expected ", kForm));
  }
  RedisAddress address;
  address.tls = scheme == "rediss";
  absl::string_view rest = url.substr(scheme_end + 3);
  if (rest.find('#') != absl::string_view::npos) {
    return absl::InvalidArgumentError("redis URL: fragments ('#') are not supported");
  }
  if (const size_t query_start = rest.find('?'); query_start != absl::string_view::npos) {
    if (!address.tls) {
      return absl::InvalidArgumentError(absl::StrCat(
          "redis URL: query parameters are for rediss:// (TLS) only: ", kTlsParameters));
    }
    if (absl::Status status = ParseTlsParameters(rest.substr(query_start + 1), address);
        !status.ok()) {
      return status;
    }
    rest = rest.substr(0, query_start);
  }
  const size_t path_start = rest.find('/');
  absl::string_view authority = rest.substr(0, path_start);
  const absl::string_view path =
      path_start == absl::string_view::npos ? absl::string_view() : rest.substr(path_start + 1);

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
  return absl::StrCat(address.tls ? "rediss://" : "redis://", user_info, HostForUrl(address.host),
                      ":", address.port, "/", address.db);
}

}  // namespace getme::redis
