#pragma once

#include <optional>
#include <string>
#include <vector>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"

namespace getme::server {

// The bearer tokens of --auth_tokens_file and the owner each one stands for.
//
// File format (docs/reliability.md): one token per line, either `NAME:TOKEN` (the owner
// is NAME) or a bare `TOKEN` (the owner is `line<N>`, its line number). Leading and trailing
// blanks are ignored, as are blank lines and lines starting with '#'. A token is at least
// kMinTokenLength printable, non-blank ASCII characters; a NAME is [A-Za-z0-9_.@-]+. Two lines
// may share a NAME (one owner with two tokens, e.g. while rotating) but not a TOKEN.
class AccessTokens {
 public:
  static constexpr std::size_t kMinTokenLength = 16;

  // INVALID_ARGUMENT naming `source` and the line (never the token) for a malformed file, and for
  // a file without any token.
  static absl::StatusOr<AccessTokens> Parse(absl::string_view contents, absl::string_view source);
  // Parse() of a file's contents; NOT_FOUND / PERMISSION_DENIED naming the file when unreadable.
  static absl::StatusOr<AccessTokens> ReadFile(const std::string& path);

  // The owner of `presented`, or nullopt. Compares against every token in time independent of
  // where (or whether) `presented` matches, so response times do not reveal a token's prefix.
  std::optional<std::string> OwnerOf(absl::string_view presented) const;
  std::size_t size() const { return tokens_.size(); }

 private:
  struct Entry {
    std::string owner;
    std::string token;
  };
  std::vector<Entry> tokens_;
};

// The token of an HTTP `Authorization` header or gRPC `authorization` metadata value
// ("Bearer <token>", scheme case-insensitive); nullopt when it is not a bearer credential.
std::optional<absl::string_view> BearerToken(absl::string_view authorization);

}  // namespace getme::server
