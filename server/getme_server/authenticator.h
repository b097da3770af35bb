#pragma once

#include <optional>
#include <string>

#include "absl/status/statusor.h"
#include "absl/strings/string_view.h"
#include "getme_server/access_tokens.h"

namespace getme::server {

// Who a caller is, shared by the gRPC service and the HTTP gateway: the owner of the bearer
// token the call presents. Every job is owned by the identity that created it (JobRegistry).
class Authenticator {
 public:
  // Authentication off: every caller is the same anonymous owner (kAnonymous) and sees all jobs.
  Authenticator() = default;
  explicit Authenticator(AccessTokens tokens) : tokens_(std::move(tokens)) {}

  static constexpr absl::string_view kAnonymous = "";

  bool enabled() const { return tokens_.has_value(); }
  // `authorization`: the HTTP Authorization header or gRPC `authorization` metadata value, if the
  // call has one. UNAUTHENTICATED when it is missing, not a bearer token, or not a known token;
  // the message never repeats what was presented.
  absl::StatusOr<std::string> Authenticate(std::optional<absl::string_view> authorization) const;
  // The same for a bare token (e.g. the one query parameter the dashboard's EventSource can send).
  absl::StatusOr<std::string> AuthenticateToken(absl::string_view token) const;

 private:
  std::optional<AccessTokens> tokens_;
};

}  // namespace getme::server
