#!/usr/bin/env bash
# Runs the README's Python pipeline example (docs/examples/pipeline.py) with the getme package
# from the build tree, against a real getme-server on a free loopback port, and checks what it
# leaves: the smoothed .vtu, read back by meshio with every cell and physical tag of gmsh's
# mesh, and better quality (getme quality, independent of the Python client).
# Usage: run_python_example.sh GETME_SERVER_BINARY GETME_BINARY PYTHON_PATH EXAMPLES_DIR WORK_DIR
set -euo pipefail
server_binary="$1" getme="$2" python_path="$3" examples="$4" work="$5"
rm -rf "$work" && mkdir -p "$work" && cd "$work"

# shellcheck source=tests/pipeline/start_server.sh
source "$(dirname "${BASH_SOURCE[0]}")/start_server.sh"
start_getme_server "$server_binary"

PYTHONPATH="$python_path" GETME_SERVER="$server_address" /usr/bin/python3 "$examples/pipeline.py"

/usr/bin/python3 - << 'PY'
import collections
import meshio

def cells_by_type(mesh):  # formats split cell blocks differently; the cells are what counts
    counts = collections.Counter()
    for block in mesh.cells:
        counts[block.type] += len(block.data)
    return counts

before = meshio.read("vessel.msh")
after = meshio.read("vessel-smooth.vtu")
assert cells_by_type(after) == cells_by_type(before), cells_by_type(after)
assert {"tetra", "hexahedron", "wedge", "pyramid"} <= {b.type for b in after.cells}
assert (after.points != before.points).any(), "nothing moved"
tags = lambda mesh: collections.Counter(int(t) for block in mesh.cell_data["gmsh:physical"]
                                        for t in block)
assert tags(after) == tags(before), (tags(before), tags(after))
print("python pipeline: the .vtu keeps every cell and physical tag")
PY

q() { "$getme" quality "$1" --json | /usr/bin/python3 -c "import json,sys; print(json.load(sys.stdin)['$2'])"; }
/usr/bin/python3 -c "import sys; b,a=map(float,sys.argv[1:]); sys.exit(0 if a>b else 1)" \
  "$(q vessel.msh q_min)" "$(q vessel-smooth.vtu q_min)" || { echo "FAIL: q_min did not improve"; exit 1; }
echo "python pipeline example: ok"
