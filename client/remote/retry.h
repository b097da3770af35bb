#pragma once

#include <algorithm>
#include <atomic>
#include <type_traits>
#include <utility>

#include "absl/status/status.h"
#include "absl/status/statusor.h"
#include "absl/strings/str_cat.h"
#include "absl/time/clock.h"
#include "absl/time/time.h"
#include "remote/call_options.h"

namespace getme::remote {

// What one attempt of a call reports besides its outcome.
struct Attempt {
  absl::Time deadline;  // of the whole call, for the attempt's ClientContext
  // The attempt sets this false once the server may have kept something from it (a queued job,
  // a delivered event): its failure is then final.
  bool retry_safe = true;
};

inline const absl::Status& StatusOf(const absl::Status& status) { return status; }
template <typename T>
const absl::Status& StatusOf(const absl::StatusOr<T>& result) {
  return result.status();
}

// Runs `attempt(Attempt&)` under CallOptions.retry (call_options.h says which failures are
// retried). A final UNAVAILABLE after several attempts says how many there were.
template <typename AttemptFn>
auto WithRetry(const CallOptions& call, const AttemptFn& attempt)
    -> std::invoke_result_t<const AttemptFn&, Attempt&> {
  const absl::Time deadline = call.timeout == absl::InfiniteDuration() ? absl::InfiniteFuture()
                                                                       : absl::Now() + call.timeout;
  absl::Duration backoff = call.retry.initial_backoff;
  for (int number = 1;; ++number) {
    Attempt state{deadline};
    auto result = attempt(state);
    const absl::Status& status = StatusOf(result);
    if (status.code() != absl::StatusCode::kUnavailable) return result;
    const bool cancelled = call.cancel != nullptr && call.cancel->load();
    if (!state.retry_safe || cancelled || number >= call.retry.max_attempts ||
        absl::Now() + backoff >= deadline) {
      if (number == 1) return result;
      return absl::UnavailableError(absl::StrCat(status.message(), " (", number, " attempts)"));
    }
    // In small steps, so that a cancel flag set meanwhile ends the wait.
    const absl::Time wake = absl::Now() + backoff;
    while (absl::Now() < wake && !(call.cancel != nullptr && call.cancel->load())) {
      absl::SleepFor(std::min(absl::Milliseconds(20), wake - absl::Now()));
    }
    backoff = std::min(2 * backoff, call.retry.max_backoff);
  }
}

}  // namespace getme::remote
