#!/usr/bin/env bash
# The main job: installs the dependencies, builds, and smooths the bundled mixed example mesh
# (tests/data/hybrid-example.vtk) with GETMe, showing live progress, then prints the mesh quality
# before and after. The result is written to out/example-smoothed.vtk.
# Extra arguments go to `getme smooth`, e.g. scripts/demo.sh --method sequential --threads 1
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

input="$GETME_ROOT/tests/data/hybrid-example.vtk"
output="$GETME_ROOT/out/example-smoothed.vtk"
getme="$GETME_ROOT/build/bin/getme"

# The engine runs inside the CLI process for now. To go through getme-server instead, start the
# server on loopback in start_engine, stop it in stop_engine, and let run_getme pass its address.
start_engine() { :; }
stop_engine() { :; }
run_getme() { "$getme" "$@"; }

bash "$GETME_ROOT/scripts/build.sh"
[ -x "$getme" ] || die "the build produced no $getme"
[ -f "$input" ] || die "example mesh $input is missing"
mkdir -p "$(dirname "$output")"

start_engine
trap stop_engine EXIT

log "Quality of the example mesh ${input#"$GETME_ROOT"/}"
run_getme quality "$input"

log "Smoothing with GETMe"
run_getme smooth "$input" "$output" "$@"

log "Quality of the smoothed mesh ${output#"$GETME_ROOT"/}"
run_getme quality "$output"

echo
echo "demo: smoothed mesh written to ${output#"$GETME_ROOT"/}"
