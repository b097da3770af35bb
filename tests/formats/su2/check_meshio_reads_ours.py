#!/usr/bin/python3
"""meshio reads the .su2 files formats_su2_test wrote (ours_NAME.su2, SU2 → SU2 through getme)
as it reads the originals (NAME.su2): the same points, the same cell blocks with the same node
order, the same marker tags ("su2:tag"; meshio numbers named markers 1, 2, … in file order).

usage: check_meshio_reads_ours.py ORIGINALS_DIR OURS_DIR NAME...
"""

import os
import sys
import warnings

import meshio
import numpy as np


def read(path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # meshio warns about every named marker
        return meshio.read(path, file_format="su2")


def compare(original, ours):
    problems = []
    if not np.array_equal(original.points, ours.points):
        problems.append(f"points differ (max {np.abs(original.points - ours.points).max()})")
    blocks = [(block.type, len(block.data)) for block in original.cells]
    ours_blocks = [(block.type, len(block.data)) for block in ours.cells]
    if blocks != ours_blocks:
        problems.append(f"cell blocks {ours_blocks}, expected {blocks}")
    else:
        for block, ours_block in zip(original.cells, ours.cells):
            if not np.array_equal(block.data, ours_block.data):
                problems.append(f"{block.type} cells differ")
        for tags, ours_tags in zip(original.cell_data["su2:tag"], ours.cell_data["su2:tag"]):
            if not np.array_equal(tags, ours_tags):
                problems.append("su2:tag differs")
    return problems


def main():
    originals, ours, names = sys.argv[1], sys.argv[2], sys.argv[3:]
    failed = 0
    for name in names:
        path = os.path.join(ours, f"ours_{name}.su2")
        try:
            problems = compare(read(os.path.join(originals, f"{name}.su2")), read(path))
        except Exception as error:  # meshio raises ReadError, ValueError, …
            problems = [f"meshio cannot read it: {error}"]
        if problems:
            print(f"FAIL {os.path.basename(path)}: " + "; ".join(problems))
            failed += 1
        else:
            print(f"ok {os.path.basename(path)}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
