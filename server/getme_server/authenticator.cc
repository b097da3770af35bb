#include "getme_server/authenticator.h"

namespace getme::server {

absl::StatusOr<std::string> Authenticator::Authenticate(
    std::optional<absl::string_view> authorization) const {
  if (!enabled()) return std::string(kAnonymous);
  if (!authorization.has_value()) {
    return absl::UnauthenticatedError(
        "this server requires a bearer token: send 'authorization: Bearer <token>'");
  }
  std::optional<absl::string_view> token = BearerToken(*authorization);
  if (!token.has_value()) {
    return absl::UnauthenticatedError(
        "the authorization is not a bearer token: expected 'Bearer <token>'");
  }
  return AuthenticateToken(*token);
}

absl::StatusOr<std::string> Authenticator::AuthenticateToken(absl::string_view token) const {
  if (!enabled()) return std::string(kAnonymous);
  std::optional<std::string> owner = tokens_->OwnerOf(token);
  if (!owner.has_value()) {
    return absl::UnauthenticatedError("the bearer token is not valid for this server");
  }
  return *std::move(owner);
}

}  // namespace getme::server
