#!/usr/bin/env bash
# Checks that two builds smooth alike: runs `getme smooth` (default method, 2 threads) on every
# mesh of ../shared/meshes with each build's getme, in-process and through that build's own
# getme-server on loopback, and compares the written files byte for byte and the exit codes and
# error lines (timings and ports left out). Used to show that a refactoring changed no result.
#   scripts/compare_results.sh OLD_BIN_DIR NEW_BIN_DIR [WORK_DIR]
# e.g. after `git worktree add ../before <commit>` and a build there:
#   scripts/compare_results.sh ../before/build/bin build/bin
set -euo pipefail
# shellcheck source=scripts/common.sh
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -ge 2 ] || die "usage: scripts/compare_results.sh OLD_BIN_DIR NEW_BIN_DIR [WORK_DIR]"
old_bin="$(cd "$1" && pwd)"
new_bin="$(cd "$2" && pwd)"
work="${3:-$(mktemp -d)}"
meshes_dir="$GETME_ROOT/../shared/meshes"
mapfile -t meshes < <(find "$meshes_dir" -name '*.vtk' -o -name '*.su2' | sort)
[ "${#meshes[@]}" -gt 0 ] || die "no meshes in $meshes_dir"

# smooth_all BIN OUT: every mesh in-process and through a server of the same build.
smooth_all() {
  local bin="$1" out="$2" server_pid port="" tries=0
  mkdir -p "$out"
  : > "$out/server.log" # before the fork, so the first read never misses or sees an old log
  "$bin/getme-server" --listen 127.0.0.1:0 --http_listen= > "$out/server.log" 2>&1 &
  server_pid=$!
  while [ -z "$port" ] && [ "$tries" -lt 100 ]; do
    port="$(grep -o 'listening on port [0-9]*' "$out/server.log" | grep -o '[0-9]*$' || true)"
    tries=$((tries + 1))
    sleep 0.1
  done
  [ -n "$port" ] || die "getme-server of $bin did not start: $(cat "$out/server.log")"
  for mesh in "${meshes[@]}"; do
    local name
    name="$(basename "$mesh")"
    for mode in local remote; do
      local extra=()
      [ "$mode" = local ] || extra=(--server "127.0.0.1:$port")
      local rc=0
      "$bin/getme" smooth "$mesh" "$out/$mode-$name.vtk" --threads 2 "${extra[@]}" \
        > "$out/$mode-$name.log" 2>&1 || rc=$?
      echo "$rc" > "$out/$mode-$name.rc"
      # Error lines, without what differs from run to run (seconds, ports).
      grep -E '^getme: ' "$out/$mode-$name.log" | sed -E 's/127\.0\.0\.1:[0-9]+//g' \
        > "$out/$mode-$name.errors" || true
    done
  done
  kill "$server_pid"
}

smooth_all "$old_bin" "$work/old"
smooth_all "$new_bin" "$work/new"
same=0
different=0
for file in "$work"/old/*.rc "$work"/old/*.errors "$work"/old/*.vtk; do
  other="$work/new/$(basename "$file")"
  if [ -f "$other" ] && cmp -s "$file" "$other"; then
    same=$((same + 1))
  else
    different=$((different + 1))
    echo "differs: $(basename "$file")"
  fi
done
echo "compare_results: ${#meshes[@]} meshes, $same files identical, $different differ ($work)"
[ "$different" -eq 0 ]
