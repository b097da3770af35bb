#!/usr/bin/env bash
# The main job: installs the dependencies, builds only the two programs it runs (getme and
# getme-server, not the tests: scripts/test.sh builds those later in the same build/), starts
# getme-server on loopback, and smooths the bundled mixed example mesh
# (tests/data/hybrid-example.vtk) through it with the getme client, showing live progress, then
# prints the mesh quality before and after and draws them (histograms before/after, q_min and
# q_mean against time). The result is written to out/example-smoothed.vtk, the picture to
# out/example-report.svg, the server's log to out/getme-server.log.
# Extra arguments go to `getme smooth`, e.g. scripts/demo.sh --method sequential --threads 1
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

input="$GETME_ROOT/tests/data/hybrid-example.vtk"
output="$GETME_ROOT/out/example-smoothed.vtk"
trace="$GETME_ROOT/out/example-trace.jsonl"
picture="$GETME_ROOT/out/example-report.svg"
getme="$GETME_ROOT/build/bin/getme"
server_binary="$GETME_ROOT/build/bin/getme-server"
server_log="$GETME_ROOT/out/getme-server.log"
server_pid=""
server_address=""

# Starts getme-server on a free loopback port and waits until it says which one it bound.
start_engine() {
  # Emptied here, not by the job's own redirection: that runs only after the fork, and a read
  # before it would find the last run's log and its port.
  : > "$server_log"
  "$server_binary" --listen 127.0.0.1:0 > "$server_log" 2>&1 &
  server_pid=$!
  local port="" tries=0
  while [ -z "$port" ] && [ "$tries" -lt 100 ]; do
    kill -0 "$server_pid" 2> /dev/null || die "getme-server exited; see $server_log"
    port="$(sed -n 's/.*getme-server listening on port \([0-9]*\).*/\1/p' "$server_log" | head -n 1)"
    [ -n "$port" ] || sleep 0.1
    tries=$((tries + 1))
  done
  [ -n "$port" ] || die "getme-server did not start listening; see $server_log"
  server_address="127.0.0.1:$port"
  log "getme-server listening on $server_address (log: ${server_log#"$GETME_ROOT"/})"
}
# SIGTERM: the server drains and exits 0.
stop_engine() {
  [ -n "$server_pid" ] || return 0
  kill -TERM "$server_pid" 2> /dev/null || true
  wait "$server_pid" 2> /dev/null || true
  server_pid=""
}
run_getme() { "$getme" "$@" --server "$server_address"; }

# Every package first: the report needs gnuplot, which the build does not.
bash "$GETME_ROOT/scripts/setup.sh"
# Only what the demo runs: the CLI (quality, smooth, report) and the server, with the libraries
# they link: about 40 % of the full build's steps (docs/development.md, "First minutes").
# scripts/test.sh builds the rest in the same build/.
bash "$GETME_ROOT/scripts/build.sh" --target getme --target getme-server
[ -x "$getme" ] || die "the build produced no $getme"
[ -x "$server_binary" ] || die "the build produced no $server_binary"
[ -f "$input" ] || die "example mesh $input is missing"
mkdir -p "$(dirname "$output")"

start_engine
trap stop_engine EXIT

log "Quality of the example mesh ${input#"$GETME_ROOT"/}"
run_getme quality "$input"

log "Smoothing with GETMe"
run_getme smooth "$input" "$output" --trace "$trace" "$@"

log "Quality of the smoothed mesh ${output#"$GETME_ROOT"/}"
run_getme quality "$output"

log "Drawing the report"
"$getme" report "$input" "$output" --trace "$trace" -o "$picture" --title "hybrid example"

echo
echo "demo: smoothed mesh written to ${output#"$GETME_ROOT"/}, report to ${picture#"$GETME_ROOT"/}"
