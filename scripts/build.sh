#!/usr/bin/env bash
# Installs the dependencies, then configures and builds the project with Ninja.
#   scripts/build.sh                      Release build in build/ (executables in build/bin/)
#   scripts/build.sh --sanitize address   ASan+UBSan build in build-asan/
#   scripts/build.sh --sanitize thread    TSan build in build-tsan/
# GETME_JOBS overrides the number of parallel compile jobs (default: every core).
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

usage() { sed -n '2,6s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; }

sanitizer=""
while [ $# -gt 0 ]; do
  case "$1" in
    --sanitize)
      [ $# -ge 2 ] || die "--sanitize needs a value: address or thread"
      sanitizer="$2"
      shift 2
      ;;
    --sanitize=*)
      sanitizer="${1#--sanitize=}"
      shift
      ;;
    -h | --help)
      usage
      exit 0
      ;;
    *)
      usage >&2
      die "unknown argument '$1'"
      ;;
  esac
done
build_dir="$(build_dir_for "$sanitizer")"

bash "$GETME_ROOT/scripts/setup.sh"

# Sanitizer builds keep -O2 but add debug info so reports name files and lines.
build_type=Release
[ -z "$sanitizer" ] || build_type=RelWithDebInfo

configure=(cmake -S "$GETME_ROOT" -B "$build_dir" -DCMAKE_BUILD_TYPE="$build_type"
  -DGETME_SANITIZE="$sanitizer")
# A build directory configured earlier by hand keeps its generator; CMake refuses to switch.
[ -f "$build_dir/CMakeCache.txt" ] || configure+=(-G Ninja)

log "Configuring $build_dir ($build_type${sanitizer:+, sanitizer: $sanitizer})"
"${configure[@]}"
log "Building $build_dir with $(build_jobs) jobs"
run_instrumented "$sanitizer" cmake --build "$build_dir" --parallel "$(build_jobs)"
echo "build: done, executables in ${build_dir#"$GETME_ROOT"/}/bin/"
