#!/usr/bin/python3
"""Reads getme's own Exodus files (ours_NAME.exo, written by formats_exodus_test from NAME.exo)
with meshio's Exodus reader and compares what meshio sees with the sidecar NAME.json the input
was written from: points bit for bit, the block cells (meshio keeps Exodus's node order, so its
wedge is the sidecar's VTK wedge mirrored back), the node sets as meshio's point sets.

Usage: check_with_meshio.py FIXTURE_DIR NAME...
"""

import json
import os
import sys

import meshio
import numpy as np

VTK_CODE = {"vertex": 1, "line": 3, "triangle": 5, "quad": 9, "tetra": 10, "tetra4": 10,
            "hexahedron": 12, "wedge": 13, "pyramid": 14}


def check(directory, name):
    with open(os.path.join(directory, name + ".json")) as source:
        expected = json.load(source)
    mesh = meshio.read(os.path.join(directory, "ours_" + name + ".exo"), file_format="exodus")
    problems = []
    points = np.array(expected["points"]).reshape(-1, 3)
    if mesh.points.shape != points.shape or not np.array_equal(
            mesh.points.astype(np.float64).view(np.uint64), points.view(np.uint64)):
        problems.append("points differ")
    cells = []
    for block in mesh.cells:
        for nodes in block.data:
            nodes = [int(i) for i in nodes]
            if block.type == "wedge":
                nodes = [nodes[i] for i in (0, 2, 1, 3, 5, 4)]
            cells.append([VTK_CODE[block.type]] + nodes)
    if cells != expected["cells"]:
        problems.append(f"cells differ: {cells} != {expected['cells']}")
    point_sets = {k: [int(i) for i in v] for k, v in mesh.point_sets.items()}
    wanted = {s[1]: s[2] for s in expected["node_sets"]}
    if point_sets != wanted:
        problems.append(f"node sets differ: {point_sets} != {wanted}")
    return problems


def check_quality(directory):
    """ours_quality.exo: the interleaved grid of exodus_round_trip_test.cc with the cell array
    quality = 0.5 * cell index, grouped into blocks tet (cells 0, 3), hex (1), quad (2), wedge
    (4), pyramid (5)."""
    mesh = meshio.read(os.path.join(directory, "ours_quality.exo"), file_format="exodus")
    values = [float(v) for block in mesh.cell_data.get("quality", []) for v in block]
    wanted = [0.0, 1.5, 0.5, 1.0, 2.0, 2.5]
    return [] if values == wanted else [f"element variable quality {values} != {wanted}"]


def main():
    directory = sys.argv[1]
    problems = check_quality(directory)
    print(f"quality: {'ok' if not problems else '; '.join(problems)}")
    failed = bool(problems)
    for name in sys.argv[2:]:
        problems = check(directory, name)
        print(f"{name}: {'ok' if not problems else '; '.join(problems)}")
        failed |= bool(problems)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
