#!/usr/bin/env bash
# gmsh → getme → solver, in shell. Meshes the vessel of vessel.geo with gmsh (all four element
# types, named physical groups), smooths it on a getme-server, draws the quality report, and
# leaves vessel-smooth.msh for the solver: the same nodes, elements, tags and groups as gmsh
# wrote, with the smoothed coordinates and $ElementData views mean_ratio, warpage, valid.
#
# Environment: GETME (the client, default getme), GETME_SERVER (default 127.0.0.1:50051),
# GETME_EXAMPLES (the folder of vessel.geo, default this script's).
set -euo pipefail
getme="${GETME:-getme}"
server="${GETME_SERVER:-127.0.0.1:50051}"
examples="${GETME_EXAMPLES:-$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)}"

# 1. Mesh: gmsh writes MSH 4.1 with the physical groups inlet, outlet, wall and fluid.
gmsh -3 "$examples/vessel.geo" -format msh41 -o vessel.msh > gmsh.log

# 2. Smooth on the server with live progress. Boundary nodes stay where gmsh put them; with
#    --free-boundary, `--fix-physical NAME` holds chosen groups only. The trace records every
#    progress event for the report.
"$getme" smooth vessel.msh vessel-smooth.msh --server "$server" --trace vessel-trace.jsonl

# 3. Look: histogram before/after and q_min / q_mean against time (gnuplot, SVG).
"$getme" report vessel.msh vessel-smooth.msh --trace vessel-trace.jsonl -o vessel-report.svg

# 4. Hand on: any MSH reader takes vessel-smooth.msh as it took vessel.msh; for ParaView, or a
#    solver that reads VTK XML, convert it (groups stay as the cell array gmsh:physical).
"$getme" convert vessel-smooth.msh vessel-smooth.vtu
"$getme" quality vessel-smooth.msh
