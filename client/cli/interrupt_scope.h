#pragma once

#include <atomic>

#include "getme/smoothing/progress.h"

namespace getme::cli {

// While in scope, SIGINT (Ctrl-C) does not kill the process: it sets `flag()` and cancels the
// token given, if any, so an in-process run stops at the engine's next check and a remote call
// cancels its job on the server (it polls `flag()`), and either reports cleanly. Both are
// lock-free atomic stores, which are safe in a signal handler. The previous handler is restored
// when the scope ends. One scope at a time.
class InterruptScope {
 public:
  explicit InterruptScope(CancellationToken* token = nullptr);
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

  const std::atomic<bool>& flag() const;
  bool interrupted() const { return flag().load(); }

 private:
  void (*previous_)(int);
};

}  // namespace getme::cli
