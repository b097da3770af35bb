#!/usr/bin/env bash
# Installs the dependencies (those only the tests run while the Release build compiles), builds,
# and runs the whole test suite: the Release build (build/),
# then ASan+UBSan (build-asan/), then TSan (build-tsan/) on the tests of threaded code (label
# `threads`); then a short run of every libFuzzer target (scripts/fuzz.sh, build-asan/). Exits
# nonzero if any build, test or fuzz target fails; every stage still runs, and the failed tests
# and a summary with timings come last.
# Environment:
#   GETME_SKIP_SANITIZERS=1      run the Release suite only (no sanitizer or fuzz stage)
#   GETME_FUZZ_SECONDS           seconds per fuzz target in the fuzz stage (default 6; 0 skips it)
#   GETME_SANITIZER_CTEST_ARGS   ctest filter for the sanitizer runs (default: -LE slow, i.e. all
#                                tests but those labelled slow), e.g. "-R Smoother" or "" for all
#   GETME_JOBS                   parallel compile jobs (default: every core)
#   GETME_TEST_JOBS              parallel ctest jobs (default: GETME_JOBS + 1)
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

# Reports as errors what would otherwise scroll past; user-set options win.
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:detect_stack_use_after_return=1:strict_init_order=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$GETME_ROOT/tests/sanitizers/lsan.supp:print_suppressions=0}"
export TSAN_OPTIONS="${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1}"

read -ra sanitizer_filter <<< "${GETME_SANITIZER_CTEST_ARGS--LE slow}"

summary=()
failed=0
failed_reports=()

# run_stage NAME SANITIZER TARGET [ctest filter...]: builds one variant (TARGET and what it needs,
# or everything when TARGET is empty) and runs its tests.
run_stage() {
  local name="$1" sanitizer="$2" target="$3"
  shift 3
  local build_dir start build_seconds result junit
  build_dir="$(build_dir_for "$sanitizer")"
  junit="$build_dir/Testing/ctest-junit.xml"
  start=$SECONDS
  result=passed
  bash "$GETME_ROOT/scripts/build.sh" ${sanitizer:+--sanitize "$sanitizer"} \
    ${target:+--target "$target"} || result="FAILED (build)"
  build_seconds=$((SECONDS - start))
  if [ "$result" = passed ]; then
    wait_for_run_packages
    log "Testing $name ($build_dir${*:+, ctest $*})"
    rm -f "$junit"
    run_instrumented "$sanitizer" ctest --test-dir "$build_dir" --output-on-failure \
      --output-junit "$junit" --no-tests=error --parallel "$(test_jobs)" "$@" ||
      result="FAILED (tests)"
  fi
  [ "$result" != "FAILED (tests)" ] || failed_reports+=("$name=$junit")
  [ "$result" = passed ] || failed=1
  summary+=("$(printf '%-10s %-16s build %5ds  tests %5ds' "$name" "$result" "$build_seconds" \
    $((SECONDS - start - build_seconds)))")
}

# What the builds need first; the packages only the tests run (scripts/packages.txt, [run]:
# OpenFOAM, chromium, Python's, ...) install in the background while the Release build compiles,
# and the first stage to test waits for them. Beside the build, in a fresh root, they took 163 s
# (docs/development.md, CI).
bash "$GETME_ROOT/scripts/setup.sh" --build-only
run_packages_log="$(mktemp)"
bash "$GETME_ROOT/scripts/setup.sh" > "$run_packages_log" 2>&1 &
run_packages_pid=$!

# wait_for_run_packages: waits for the background setup.sh, prints its output, and stops the
# run if it failed (as setup.sh failing in the foreground would).
wait_for_run_packages() {
  [ -n "$run_packages_pid" ] || return 0
  local status=0
  wait "$run_packages_pid" || status=$?
  run_packages_pid=""
  log "Packages the tests run (scripts/setup.sh, in the background since the first build began)"
  cat "$run_packages_log"
  rm -f "$run_packages_log"
  [ "$status" = 0 ] || die "scripts/setup.sh failed (exit $status): the tests cannot run"
}

run_stage release "" ""
if [ "${GETME_SKIP_SANITIZERS:-0}" = 1 ]; then
  summary+=("sanitizers skipped (GETME_SKIP_SANITIZERS=1)")
else
  run_stage asan+ubsan address "" "${sanitizer_filter[@]}"
  # TSan looks for data races: only the executables that run threaded code (label `threads`,
  # tests/CMakeLists.txt) are built and run; the single-threaded readers and generators would
  # only cost build time.
  run_stage tsan thread getme_thread_tests -L threads "${sanitizer_filter[@]}"
fi

# The fuzz stage: every target for GETME_FUZZ_SECONDS from the seed corpus. The ASan+UBSan stage
# built the targets (scripts/build.sh). A crash fails the stage; its reproducer is in
# build-asan/fuzz/artifacts/ (docs/fuzzing.md).
run_fuzz_stage() {
  local seconds="$1" start result=passed
  start=$SECONDS
  bash "$GETME_ROOT/scripts/fuzz.sh" --no-build "$seconds" || result="FAILED (fuzz)"
  [ "$result" = passed ] || failed=1
  summary+=("$(printf '%-10s %-16s (built by asan+ubsan)  fuzz  %5ds' fuzz "$result" \
    $((SECONDS - start)))")
}

fuzz_seconds="${GETME_FUZZ_SECONDS:-6}"
if [ "${GETME_SKIP_SANITIZERS:-0}" = 1 ] || [ "$fuzz_seconds" = 0 ]; then
  summary+=("fuzzing skipped (GETME_SKIP_SANITIZERS=1 or GETME_FUZZ_SECONDS=0)")
else
  run_fuzz_stage "$fuzz_seconds"
fi

wait_for_run_packages  # every build failed: still report an install failure, and leave no apt behind

# The failed tests and why, last but for the summary: a CI log is often seen only by its tail.
for report in "${failed_reports[@]}"; do
  log "Failed tests of ${report%%=*}"
  /usr/bin/python3 "$GETME_ROOT/scripts/ctest_failures.py" "${report#*=}"
done

log "Summary (total ${SECONDS}s)"
printf '%s\n' "${summary[@]}"
exit "$failed"
