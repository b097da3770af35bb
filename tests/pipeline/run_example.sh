#!/usr/bin/env bash
# Runs the README's pipeline example (docs/examples/pipeline.sh) as a user would, against a real
# getme-server on a free loopback port, and checks what it leaves: the smoothed .msh with every
# group and element of gmsh's file, better quality, the report picture and the .vtu.
# Usage: run_example.sh GETME_SERVER_BINARY GETME_BINARY EXAMPLES_DIR WORK_DIR
set -euo pipefail
server_binary="$1" getme="$2" examples="$3" work="$4"
rm -rf "$work" && mkdir -p "$work" && cd "$work"

# shellcheck source=tests/pipeline/start_server.sh
source "$(dirname "${BASH_SOURCE[0]}")/start_server.sh"
start_getme_server "$server_binary"

GETME="$getme" GETME_SERVER="$server_address" GETME_EXAMPLES="$examples" \
  bash "$examples/pipeline.sh"

fail() { echo "FAIL: $*"; exit 1; }
for file in vessel.msh vessel-smooth.msh vessel-trace.jsonl vessel-report.svg vessel-smooth.vtu; do
  [ -s "$file" ] || fail "$file was not written"
done
grep -q "<svg" vessel-report.svg || fail "vessel-report.svg is not an SVG"

# Independent of our reader: gmsh itself reads the smoothed file, with the same groups and
# element counts as its own.
/usr/bin/python3 - << 'PY'
import gmsh

def summary(path):
    gmsh.open(path)
    groups = sorted((dim, tag, gmsh.model.getPhysicalName(dim, tag))
                    for dim, tag in gmsh.model.getPhysicalGroups())
    types, tags, _ = gmsh.model.mesh.getElements()
    counts = {int(t): len(e) for t, e in zip(types, tags)}
    nodes = len(gmsh.model.mesh.getNodes()[0])
    return groups, counts, nodes

gmsh.initialize(["-noenv"], readConfigFiles=False)
gmsh.option.setNumber("General.Terminal", 0)
before, after = summary("vessel.msh"), summary("vessel-smooth.msh")
gmsh.finalize()
assert before == after, f"gmsh sees a different mesh after smoothing:\n{before}\n{after}"
assert all(after[1].get(t, 0) > 0 for t in (4, 5, 6, 7)), f"expected all four types: {after[1]}"
print(f"gmsh reads the smoothed file: {after[2]} nodes, elements by type {after[1]}, "
      f"groups {[g[2] for g in after[0]]}")
PY

q() { "$getme" quality "$1" --json | /usr/bin/python3 -c "import json,sys; d=json.load(sys.stdin); print(d['$2'])"; }
before_min="$(q vessel.msh q_min)" after_min="$(q vessel-smooth.msh q_min)"
before_mean="$(q vessel.msh q_mean)" after_mean="$(q vessel-smooth.msh q_mean)"
echo "q_min $before_min -> $after_min, q_mean $before_mean -> $after_mean"
/usr/bin/python3 -c "import sys; b,a,bm,am=map(float,sys.argv[1:]); sys.exit(0 if a>b and am>bm else 1)" \
  "$before_min" "$after_min" "$before_mean" "$after_mean" || fail "quality did not improve"
echo "pipeline example: ok"
