#!/usr/bin/python3
"""Reads getme's own MEDIT files (written by formats_medit_test into the fixture directory) with
meshio's MEDIT reader and compares what meshio sees with the sidecar NAME.expected written beside
each: points bit for bit, cells (meshio's wedge is in Gmsh order; the sidecar uses VTK's), point
and cell refs.

Usage: check_with_meshio.py FIXTURE_DIR NAME...
"""

import os
import sys

import meshio
import numpy as np

VTK_CODE = {"line": 3, "triangle": 5, "quad": 9, "tetra": 10, "hexahedron": 12, "wedge": 13,
            "pyramid": 14}


def read_expected(path):
    tokens = open(path).read().split()
    pos = 0

    def take(keyword):
        nonlocal pos
        assert tokens[pos] == keyword, f"{path}: expected {keyword}, found {tokens[pos]}"
        pos += 1

    take("tolerance")
    pos += 1
    take("points")
    n = int(tokens[pos]); pos += 1
    points = np.array([float(t) for t in tokens[pos:pos + 3 * n]]).reshape(n, 3)
    pos += 3 * n
    take("point_refs")
    n = int(tokens[pos]); pos += 1
    point_refs = [int(t) for t in tokens[pos:pos + n]]
    pos += n
    take("cells")
    n = int(tokens[pos]); pos += 1
    cells = []
    for _ in range(n):
        code, count = int(tokens[pos]), int(tokens[pos + 1])
        cells.append((code, [int(t) for t in tokens[pos + 2:pos + 2 + count]]))
        pos += 2 + count
    take("cell_refs")
    n = int(tokens[pos]); pos += 1
    cell_refs = [int(t) for t in tokens[pos:pos + n]]
    return points, point_refs, cells, cell_refs


def check(directory, name):
    points, point_refs, cells, cell_refs = read_expected(os.path.join(directory, name + ".expected"))
    mesh = meshio.read(os.path.join(directory, name + ".mesh"), file_format="medit")
    problems = []
    if mesh.points.shape != points.shape or not np.array_equal(
            mesh.points.astype(np.float64).view(np.uint64), points.view(np.uint64)):
        problems.append("points differ")
    if list(mesh.point_data["medit:ref"]) != point_refs:
        problems.append("point refs differ")
    seen_cells, seen_refs = [], []
    for block, refs in zip(mesh.cells, mesh.cell_data["medit:ref"]):
        for nodes, ref in zip(block.data, refs):
            nodes = [int(i) for i in nodes]
            if block.type == "wedge":
                nodes = [nodes[i] for i in (0, 2, 1, 3, 5, 4)]
            seen_cells.append((VTK_CODE[block.type], nodes))
            seen_refs.append(int(ref))
    if seen_cells != cells:
        problems.append(f"cells differ ({len(seen_cells)} read, {len(cells)} expected)")
    if seen_refs != cell_refs:
        problems.append("cell refs differ")
    if not cells:
        problems.append("no cells: the check would prove nothing")
    return problems


def main():
    directory, names = sys.argv[1], sys.argv[2:]
    failed = False
    for name in names:
        problems = check(directory, name)
        print(f"{name}: {'ok' if not problems else '; '.join(problems)}")
        failed = failed or bool(problems)
    sys.exit(1 if failed or not names else 0)


if __name__ == "__main__":
    main()
