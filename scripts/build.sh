#!/usr/bin/env bash
# Installs what building needs (scripts/setup.sh --build-only), then configures and builds the
# project with Ninja.
#   scripts/build.sh                      Release build in build/ (executables in build/bin/)
#   scripts/build.sh --sanitize address   ASan+UBSan build in build-asan/ (clang, with fuzz targets)
#   scripts/build.sh --sanitize thread    TSan build in build-tsan/ (clang)
#   scripts/build.sh ... --target NAME    build only NAME (and what it needs), e.g. getme_fuzz
# GETME_JOBS overrides the number of parallel compile jobs (default: every core).
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

usage() { sed -n '2,8s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"; }

sanitizer=""
targets=()
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
    --target)
      [ $# -ge 2 ] || die "--target needs a value: a CMake target name"
      targets+=(--target "$2")
      shift 2
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

# Only the [build] packages: scripts/test.sh installs the others meanwhile, in the background.
bash "$GETME_ROOT/scripts/setup.sh" --build-only

configure=(cmake -S "$GETME_ROOT" -B "$build_dir" -DGETME_SANITIZE="$sanitizer")
if [ -z "$sanitizer" ]; then
  build_type=Release
  configure+=(-DCMAKE_BUILD_TYPE=Release)
else
  # Compiling is most of a sanitizer stage's time. With the sanitizers, -O1 compiles about 40 %
  # faster than -O2 (client/formats/vtk_reader.cc), and -g1 (line tables only: reports still name
  # file and line) about 35 % faster than -g (core/getme/smoothing/sequential_smoother.cc).
  # clang-14 compiles the instrumented code about 40 % faster than GCC 12 (smoother_service.cc,
  # regular_element_test.cc, gmsh_reader.cc), and it brings libFuzzer: the ASan build also holds
  # the fuzz targets (fuzz/, scripts/fuzz.sh), so CI compiles the readers once for both.
  build_type="RelWithDebInfo, -O1 -g1, clang-14"
  configure+=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
    -DCMAKE_CXX_COMPILER=clang++-14)
  # A directory configured with another compiler cannot switch: CMake would drop its cache halfway.
  if [ -f "$build_dir/CMakeCache.txt" ] &&
    ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++-14$' "$build_dir/CMakeCache.txt"; then
    log "Reconfiguring $build_dir from scratch for clang-14"
    rm -rf "$build_dir/CMakeCache.txt" "$build_dir/CMakeFiles"
  fi
fi
[ "$sanitizer" != address ] || configure+=(-DGETME_FUZZ=ON)
if [ "$sanitizer" = thread ]; then
  # Debian's libgrpc is not built with ThreadSanitizer: TSan cannot see its lock-free hand-offs and
  # would report them as races in our handlers. The TSan stage checks the engine's threading (thread
  # pool, parallel smoothing, determinism); the service is checked under ASan+UBSan.
  configure+=(-DGETME_BUILD_SERVICE=OFF)
fi
# A build directory configured earlier by hand keeps its generator; CMake refuses to switch.
[ -f "$build_dir/CMakeCache.txt" ] || configure+=(-G Ninja)

log "Configuring $build_dir ($build_type${sanitizer:+, sanitizer: $sanitizer})"
"${configure[@]}"
log "Building $build_dir with $(build_jobs) jobs"
run_instrumented "$sanitizer" cmake --build "$build_dir" --parallel "$(build_jobs)" "${targets[@]}"
echo "build: done, executables in ${build_dir#"$GETME_ROOT"/}/bin/"
