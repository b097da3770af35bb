#include "cli/interrupt_flag.h"

#include <csignal>

namespace getme::cli {
namespace {

std::atomic<bool> interrupt_flag{false};
static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void SetInterruptFlag(int /*signal*/) { interrupt_flag.store(true); }

}  // namespace

InterruptFlagScope::InterruptFlagScope() {
  interrupt_flag.store(false);
  previous_ = std::signal(SIGINT, SetInterruptFlag);
}

InterruptFlagScope::~InterruptFlagScope() { std::signal(SIGINT, previous_); }

const std::atomic<bool>& InterruptFlagScope::flag() const { return interrupt_flag; }

}  // namespace getme::cli
