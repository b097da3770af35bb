#!/usr/bin/env bash
# Reproduces docs/benchmarks.md: builds Release (scripts/build.sh), runs every benchmark
# (bench/run_benchmarks.py: getme-bench on the shared and generated meshes, scaling, service
# overhead, the micro-benchmarks if built, `getme report` plots), stores the data in
# docs/benchmarks/ and regenerates the tables of docs/benchmarks.md (bench/benchmarks_doc.py).
#   bench/run.sh             the full run: paper-size meshes, 5 repeats, scaling to ~10M elements
#   bench/run.sh --quick     minutes: small meshes, 1 repeat, scaling to ~100k elements
# Further options go to bench/run_benchmarks.py (--repeats N, --max-elements N, --skip-service,
# --skip-micro, --shared DIR, --only GROUPS to re-run some tables and keep the rest, recorded as an
# addendum in the header); --no-build uses build/ as it is.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

build=1
forwarded=()
for arg in "$@"; do
  case "$arg" in
    --no-build) build=0 ;;
    -h | --help)
      sed -n '2,10s/^# \{0,1\}//p' "${BASH_SOURCE[0]}"
      exit 0
      ;;
    *) forwarded+=("$arg") ;;
  esac
done

if [ "$build" = 1 ]; then
  bash "$root/scripts/build.sh"
fi
GETME_BENCH_COMMAND="bench/run.sh $*" /usr/bin/python3 "$root/bench/run_benchmarks.py" "$root/build" "${forwarded[@]}"
/usr/bin/python3 "$root/bench/benchmarks_doc.py" "$root/docs/benchmarks" "$root/docs/benchmarks.md"
echo "bench/run.sh: docs/benchmarks.md regenerated from docs/benchmarks/"
