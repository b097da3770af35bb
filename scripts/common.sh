# shellcheck shell=bash
# Shared helpers for the scripts in this folder; sourced, not run.

GETME_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

log() { printf '\n==> %s\n' "$*" >&2; }
die() {
  printf 'error: %s\n' "$*" >&2
  exit 1
}

# Parallel jobs for builds and ctest: GETME_JOBS if set, else every core.
build_jobs() { echo "${GETME_JOBS:-$(nproc)}"; }
# Parallel ctest jobs: GETME_TEST_JOBS if set, else one more than build_jobs. Many tests wait on
# the processes, sockets and timers of servers and clients they start: with one test per core the
# Release suite kept 1.5 of 2 cores busy (docs/development.md, CI).
test_jobs() { echo "${GETME_TEST_JOBS:-$(($(build_jobs) + 1))}"; }

# Build directory for a sanitizer name ('' = the plain Release build).
build_dir_for() {
  case "$1" in
    "") echo "$GETME_ROOT/build" ;;
    address) echo "$GETME_ROOT/build-asan" ;;
    thread) echo "$GETME_ROOT/build-tsan" ;;
    *) die "unknown sanitizer '$1': expected 'address' or 'thread'" ;;
  esac
}

# Runs a command that executes sanitizer-instrumented binaries (the build runs the tests once to
# list them). GCC 12's sanitizer runtimes cannot place their shadow memory when the kernel
# randomizes mmap addresses with more than 28 bits (Ubuntu 23.10+ kernels: "ThreadSanitizer:
# unexpected memory mapping", endless "AddressSanitizer:DEADLYSIGNAL"), so there the command runs
# with address randomization off.
run_instrumented() {
  local sanitizer="$1"
  shift
  local rnd_bits
  rnd_bits="$(cat /proc/sys/vm/mmap_rnd_bits 2> /dev/null || echo 28)"
  if [ -n "$sanitizer" ] && [ "$rnd_bits" -gt 28 ] && setarch "$(uname -m)" -R true 2> /dev/null; then
    echo "note: vm.mmap_rnd_bits=$rnd_bits, running without address randomization for $sanitizer" >&2
    setarch "$(uname -m)" -R "$@"
  else
    "$@"
  fi
}
