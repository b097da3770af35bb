#include "getme_server/stream_limiter.h"

#include "absl/strings/match.h"
#include "absl/strings/str_cat.h"

namespace getme::server {

std::string ClientHost(absl::string_view peer) {
  for (absl::string_view scheme : {"ipv4:", "ipv6:"}) {
    if (!absl::StartsWith(peer, scheme)) continue;
    absl::string_view address = peer.substr(scheme.size());
    const std::size_t port = address.rfind(':');
    const std::size_t bracket = address.rfind(']');
    if (port != absl::string_view::npos && (bracket == absl::string_view::npos || port > bracket)) {
      address = address.substr(0, port);
    }
    return std::string(address);
  }
  return std::string(peer);
}

ClientStreamLimiter::Slot::~Slot() {
  if (limiter_ != nullptr) limiter_->Release(host_);
}

absl::StatusOr<ClientStreamLimiter::Slot> ClientStreamLimiter::Acquire(absl::string_view peer) {
  std::string host = ClientHost(peer);
  std::lock_guard lock(mutex_);
  int& open = open_[host];
  if (open >= max_per_client_) {
    return absl::ResourceExhaustedError(
        absl::StrCat("client ", host, " already has ", open,
                     " open streaming calls (Smooth, SubmitJob, WatchJob, GetResult, "
                     "EvaluateQuality), the server's limit per client (--max_streams_per_client); "
                     "retry when one has ended"));
  }
  ++open;
  return Slot(this, std::move(host));
}

int ClientStreamLimiter::OpenStreams(absl::string_view peer) const {
  std::lock_guard lock(mutex_);
  auto it = open_.find(ClientHost(peer));
  return it == open_.end() ? 0 : it->second;
}

void ClientStreamLimiter::Release(const std::string& host) {
  std::lock_guard lock(mutex_);
  auto it = open_.find(host);
  if (it != open_.end() && --it->second == 0) open_.erase(it);
}

}  // namespace getme::server
