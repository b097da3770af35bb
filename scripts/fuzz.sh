#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, clang-14, ASan+UBSan) in build-asan/ and runs each for
# SECONDS_PER_TARGET (default 60) from the seed corpus (the shared meshes and tests/data written in
# every format, fuzz/make_seeds.cc) plus the corpus earlier runs kept. Prints per target the
# executions, exec/s, coverage (libFuzzer's final cov: and ft:) and new corpus units; exits 1 if a
# target crashed, leaked, timed out or hit an invariant (its reproducer is then in
# build-asan/fuzz/artifacts/TARGET/, see docs/fuzzing.md).
#   scripts/fuzz.sh [SECONDS_PER_TARGET]
#   scripts/fuzz.sh --build-only          configure and build only
#   scripts/fuzz.sh --no-build [SECONDS]  run what was built (scripts/test.sh times the two apart)
# Environment:
#   GETME_FUZZ_TARGETS    targets to run (default: all), e.g. "vtk gmsh"
#   GETME_FUZZ_MAX_SEED_KB  largest shared mesh used as a seed (default 100; big inputs fuzz slowly)
#   GETME_SHARED_MESHES   the shared meshes (default: ../shared/meshes beside the repository)
#   GETME_JOBS            parallel compile jobs (default: every core)
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

build=1
run=1
case "${1:-}" in
  --build-only)
    run=0
    shift
    ;;
  --no-build)
    build=0
    shift
    ;;
esac
seconds="${1:-60}"
if ! [[ "$seconds" =~ ^[0-9]+$ ]] || [ "$seconds" -eq 0 ]; then
  die "SECONDS_PER_TARGET must be a positive integer"
fi
read -ra targets <<< "${GETME_FUZZ_TARGETS:-vtk vtu gmsh medit su2 cgns exodus openfoam mesh_file engine_mesh wire_mesh http_job}"
max_seed_kb="${GETME_FUZZ_MAX_SEED_KB:-100}"
shared_meshes="${GETME_SHARED_MESHES:-$GETME_ROOT/../shared/meshes}"
build_dir="$(build_dir_for address)"
fuzz_dir="$build_dir/fuzz"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

start=$SECONDS
if [ "$build" = 1 ]; then
  # The ASan+UBSan build of scripts/build.sh holds the targets: one instrumented copy of the code.
  bash "$GETME_ROOT/scripts/build.sh" --sanitize address --target getme_fuzz
fi
build_seconds=$((SECONDS - start))
[ "$run" = 1 ] || exit 0

log "Writing the seed corpus"
seed_meshes=()
while IFS= read -r -d '' mesh; do seed_meshes+=("$mesh"); done < <(
  find "$shared_meshes" "$GETME_ROOT/tests/data" -maxdepth 2 -type f -name '*.vtk' \
    -not -path '*/fuzz-regressions/*' -size -"$max_seed_kb"k -print0 2> /dev/null | sort -z)
[ "${#seed_meshes[@]}" -gt 0 ] || die "no seed meshes in $shared_meshes or tests/data"
rm -rf "$fuzz_dir/seeds"
run_instrumented address "$fuzz_dir/getme-fuzz-seeds" "$fuzz_dir/seeds" "${seed_meshes[@]}"
# The inputs that once found a bug, as they are, for their format's target and the generic ones.
for input in "$GETME_ROOT"/tests/data/fuzz-regressions/*; do
  [ -f "$input" ] || continue
  case "$input" in
    *.vtk) format_target=vtk ;;
    *.vtu) format_target=vtu ;;
    *.msh) format_target=gmsh ;;
    *.mesh) format_target=medit ;;
    *.su2) format_target=su2 ;;
    *.cgns) format_target=cgns ;;
    *.exo) format_target=exodus ;;
    *) format_target=wire_mesh ;;
  esac
  for target in "$format_target" mesh_file engine_mesh; do
    mkdir -p "$fuzz_dir/seeds/$target"
    cp "$input" "$fuzz_dir/seeds/$target/"
  done
done
# HTTP POST /v1/jobs bodies that once broke the gateway.
mkdir -p "$fuzz_dir/seeds/http_job"
cp "$GETME_ROOT"/tests/data/fuzz-regressions/http/* "$fuzz_dir/seeds/http_job/" 2> /dev/null || true

# dictionary_for TARGET: the -dict= option of a target (the generic ones get every format's words).
dictionary_for() {
  local dictionaries="$GETME_ROOT/fuzz/dictionaries"
  case "$1" in
    vtk | vtu | gmsh | medit | su2 | openfoam) echo "-dict=$dictionaries/$1.dict" ;;
    http_job) echo "-dict=$dictionaries/json.dict" ;;
    mesh_file | engine_mesh)
      cat "$dictionaries"/*.dict > "$fuzz_dir/all.dict"
      echo "-dict=$fuzz_dir/all.dict"
      ;;
  esac
}

# stat LOG NAME: a value of libFuzzer's -print_final_stats block.
stat() { sed -n "s/^stat::$2: *//p" "$1" | tail -1; }

# fuzz_target TARGET: runs one target; writes its summary line to logs/TARGET.summary and its
# result (passed or FAILED) to logs/TARGET.result.
fuzz_target() {
  local target="$1" binary corpus artifacts run_log result lsan_options status_line cov ft
  local -a dictionary target_options
  binary="$fuzz_dir/${target}_fuzzer"
  corpus="$fuzz_dir/corpus/$target"
  artifacts="$fuzz_dir/artifacts/$target"
  run_log="$fuzz_dir/logs/$target.log"
  mkdir -p "$corpus" "$artifacts" "$(dirname "$run_log")" "$fuzz_dir/seeds/$target"
  log "Fuzzing $target for ${seconds}s"
  result=passed
  read -ra dictionary <<< "$(dictionary_for "$target")"
  # The CGNS library leaks on a cg_open that fails part-way (fuzz/cgns_lsan.supp says where):
  # checked after every such input, it slowed the target from ~1,600 to ~5 executions per second,
  # so the cgns target checks leaks only at exit, with the library's suppressed. It also callocs
  # a damaged ADF child count's worth of ids (up to 2^31 doubles, 16 GiB) before finding no
  # children: pages never touched, so the RSS limit still holds, but libFuzzer's malloc limit
  # (the RSS limit by default) would report each as out-of-memory.
  lsan_options="${LSAN_OPTIONS:-}"
  target_options=()
  if [ "$target" = cgns ]; then
    lsan_options="suppressions=$GETME_ROOT/fuzz/cgns_lsan.supp"
    target_options=(-malloc_limit_mb=17000 -detect_leaks=0)
  fi
  # The first folder collects new units (kept for the next run), the seeds are only read.
  LSAN_OPTIONS="$lsan_options" run_instrumented address "$binary" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 \
    -print_final_stats=1 -artifact_prefix="$artifacts/" "${dictionary[@]}" "${target_options[@]}" \
    "$corpus" "$fuzz_dir/seeds/$target" > "$run_log" 2>&1 || result=FAILED
  # The last status line ("#N DONE cov: 1234 ft: 5678 corp: …") holds the final coverage.
  status_line="$(grep -E '^#[0-9]+' "$run_log" | tail -1 || true)"
  cov="$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<< "$status_line")"
  ft="$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<< "$status_line")"
  printf '%-12s %-7s %10s runs %7s exec/s  cov %6s  ft %6s  new units %5s\n' \
    "$target" "$result" "$(stat "$run_log" number_of_executed_units)" \
    "$(stat "$run_log" average_exec_per_sec)" "${cov:-?}" "${ft:-?}" \
    "$(stat "$run_log" new_units_added)" > "$fuzz_dir/logs/$target.summary"
  echo "$result" > "$fuzz_dir/logs/$target.result"
}

# Each target is one process on one core: as many run at a time as there are compile jobs
# (GETME_JOBS), so CI's two cores fuzz every target for the full time in half the wall time.
for target in "${targets[@]}"; do
  [ -x "$fuzz_dir/${target}_fuzzer" ] || die "unknown fuzz target '$target' (not built)"
  rm -f "$fuzz_dir/logs/$target.summary" "$fuzz_dir/logs/$target.result"
done
for target in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$(build_jobs)" ]; do wait -n || true; done
  fuzz_target "$target" &
done
wait

summary=()
failed=0
for target in "${targets[@]}"; do
  if [ "$(cat "$fuzz_dir/logs/$target.result" 2> /dev/null)" != passed ]; then
    failed=1
    grep -E 'ERROR: |invariant violated|runtime error|Test unit written' \
      "$fuzz_dir/logs/$target.log" | head -5 >&2 || true
    echo "$target FAILED; full log: $fuzz_dir/logs/$target.log" >&2
  fi
  summary+=("$(cat "$fuzz_dir/logs/$target.summary" 2> /dev/null || echo "$target: no result")")
done

log "Fuzz summary (${seconds}s per target; build ${build_seconds}s, total $((SECONDS - start))s)"
printf '%s\n' "${summary[@]}"
exit "$failed"
