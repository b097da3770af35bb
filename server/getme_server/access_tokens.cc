#include "getme_server/access_tokens.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "absl/container/flat_hash_set.h"
#include "absl/strings/ascii.h"
#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"
#include "absl/strings/str_split.h"
#include "absl/strings/strip.h"

namespace getme::server {
namespace {

bool IsNameCharacter(char c) {
  return absl::ascii_isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '@' ||
         c == '-';
}

bool IsTokenCharacter(char c) { return c > ' ' && c < 0x7f; }

// Equal contents, in time that depends only on the lengths (which an attacker knows anyway for
// the presented token and learns nothing from for ours: every stored token is compared).
bool ConstantTimeEquals(absl::string_view presented, absl::string_view token) {
  unsigned char difference = presented.size() == token.size() ? 0 : 1;
  for (std::size_t i = 0; i < token.size(); ++i) {
    const char p = presented.empty() ? '\0' : presented[i % presented.size()];
    difference |= static_cast<unsigned char>(p ^ token[i]);
  }
  return difference == 0;
}

}  // namespace

absl::StatusOr<AccessTokens> AccessTokens::Parse(absl::string_view contents,
                                                 absl::string_view source) {
  AccessTokens tokens;
  absl::flat_hash_set<std::string> seen;
  int line_number = 0;
  for (absl::string_view line : absl::StrSplit(contents, '\n')) {
    ++line_number;
    line = absl::StripAsciiWhitespace(line);
    if (line.empty() || absl::StartsWith(line, "#")) continue;
    auto error = [&](absl::string_view what) {
      return absl::InvalidArgumentError(absl::StrCat(source, " line ", line_number, ": ", what));
    };
    std::string owner = absl::StrCat("line", line_number);
    absl::string_view token = line;
    if (const std::size_t colon = line.find(':'); colon != absl::string_view::npos) {
      const absl::string_view name = line.substr(0, colon);
      if (name.empty()) return error("empty NAME before ':' (expected NAME:TOKEN)");
      for (char c : name) {
        if (!IsNameCharacter(c)) {
          return error("NAME may only contain letters, digits and _ . @ - (expected NAME:TOKEN)");
        }
      }
      owner = std::string(name);
      token = line.substr(colon + 1);
    }
    for (char c : token) {
      if (!IsTokenCharacter(c)) {
        return error("the token contains a blank or non-printable character");
      }
    }
    if (token.size() < kMinTokenLength) {
      return error(absl::StrCat("the token is shorter than ", kMinTokenLength,
                                " characters (make one with: openssl rand -hex 32)"));
    }
    if (!seen.insert(std::string(token)).second) {
      return error("the token repeats one of an earlier line");
    }
    tokens.tokens_.push_back({std::move(owner), std::string(token)});
  }
  if (tokens.tokens_.empty()) {
    return absl::InvalidArgumentError(
        absl::StrCat(source, " has no token (one per line: TOKEN or NAME:TOKEN)"));
  }
  return tokens;
}

absl::StatusOr<AccessTokens> AccessTokens::ReadFile(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    const int error = errno;
    const std::string message =
        absl::StrCat("cannot read --auth_tokens_file '", path, "': ", std::strerror(error));
    return error == EACCES ? absl::PermissionDeniedError(message) : absl::NotFoundError(message);
  }
  std::ostringstream contents;
  contents << file.rdbuf();
  if (file.bad()) {
    return absl::DataLossError(absl::StrCat("cannot read --auth_tokens_file '", path, "'"));
  }
  return Parse(contents.str(), absl::StrCat("--auth_tokens_file '", path, "'"));
}

std::optional<std::string> AccessTokens::OwnerOf(absl::string_view presented) const {
  const Entry* match = nullptr;
  for (const Entry& entry : tokens_) {
    // No early exit: every token is compared, whichever matches.
    if (ConstantTimeEquals(presented, entry.token)) match = &entry;
  }
  if (match == nullptr) return std::nullopt;
  return match->owner;
}

std::optional<absl::string_view> BearerToken(absl::string_view authorization) {
  authorization = absl::StripAsciiWhitespace(authorization);
  constexpr absl::string_view kScheme = "bearer ";
  if (authorization.size() <= kScheme.size() ||
      !absl::EqualsIgnoreCase(authorization.substr(0, kScheme.size()), kScheme)) {
    return std::nullopt;
  }
  absl::string_view token = absl::StripLeadingAsciiWhitespace(authorization.substr(kScheme.size()));
  if (token.empty()) return std::nullopt;
  return token;
}

}  // namespace getme::server
