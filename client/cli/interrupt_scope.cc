#include "cli/interrupt_scope.h"

#include <csignal>

namespace getme::cli {
namespace {

std::atomic<bool> interrupt_flag{false};
std::atomic<CancellationToken*> interrupt_token{nullptr};
static_assert(std::atomic<bool>::is_always_lock_free);
static_assert(std::atomic<CancellationToken*>::is_always_lock_free);

extern "C" void OnInterrupt(int /*signal*/) {
  interrupt_flag.store(true);
  if (CancellationToken* token = interrupt_token.load(); token != nullptr) token->Cancel();
}

}  // namespace

InterruptScope::InterruptScope(CancellationToken* token) {
  interrupt_flag.store(false);
  interrupt_token.store(token);
  previous_ = std::signal(SIGINT, OnInterrupt);
}

InterruptScope::~InterruptScope() {
  std::signal(SIGINT, previous_);
  interrupt_token.store(nullptr);
}

const std::atomic<bool>& InterruptScope::flag() const { return interrupt_flag; }

}  // namespace getme::cli
