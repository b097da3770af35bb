#pragma once

#include <atomic>

namespace getme::cli {

// While in scope, SIGINT (Ctrl-C) sets `flag()` instead of killing the process, so a remote call
// can cancel its job on the server and report cleanly. A lock-free atomic store is safe in a
// signal handler.
class InterruptFlagScope {
 public:
  InterruptFlagScope();
  ~InterruptFlagScope();
  InterruptFlagScope(const InterruptFlagScope&) = delete;
  InterruptFlagScope& operator=(const InterruptFlagScope&) = delete;

  const std::atomic<bool>& flag() const;
  bool interrupted() const { return flag().load(); }

 private:
  void (*previous_)(int);
};

}  // namespace getme::cli
