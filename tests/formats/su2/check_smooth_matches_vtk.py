#!/usr/bin/python3
"""`getme smooth` of knowles-mixed-beam.su2 gives bit for bit the points of `getme smooth` of its
VTK twin (the same mesh; the SU2 file numbers 6,304 elements mirror-wise, which the reader
renumbers), says so in its read summary, and writes the SU2 file back with the input's element
rows and markers unchanged (meshio reads both).

usage: check_smooth_matches_vtk.py GETME SHARED_SU2_DIR WORK_DIR
"""

import os
import subprocess
import sys
import warnings

import meshio
import numpy as np


def rows(path, keyword):
    """The token lists of the rows after the line starting with `keyword` (count on that line)."""
    with open(path) as f:
        lines = f.read().splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith(keyword))
    count = int(lines[start].split("=")[1])
    return [line.split() for line in lines[start + 1:start + 1 + count]]


def main():
    getme, shared, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    su2_in = os.path.join(shared, "knowles-mixed-beam.su2")
    su2_out = os.path.join(work, "knowles-smoothed.su2")
    vtk_out = os.path.join(work, "knowles-smoothed.vtk")
    run = subprocess.run([getme, "smooth", su2_in, su2_out], check=True, capture_output=True,
                         text=True)
    subprocess.run([getme, "smooth", os.path.join(shared, "knowles-mixed-beam.vtk"), vtk_out],
                   check=True, capture_output=True)
    problems = []
    if "6304 mirrored elements renumbered" not in run.stderr + run.stdout:
        problems.append("the read summary does not report the 6304 mirrored elements")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        smoothed_su2 = meshio.read(su2_out)
    smoothed_vtk = meshio.read(vtk_out)
    if not np.array_equal(smoothed_su2.points, smoothed_vtk.points):
        difference = np.abs(smoothed_su2.points - smoothed_vtk.points).max()
        problems.append(f"smoothed points differ from the VTK run's (max {difference})")
    if np.array_equal(smoothed_su2.points, meshio.read(os.path.join(shared,
                                                                    "knowles-mixed-beam.vtk")).points):
        problems.append("nothing moved")
    for keyword in ("NELEM=", "MARKER_ELEMS= 80"):
        if rows(su2_out, keyword) != rows(su2_in, keyword):
            problems.append(f"the rows after {keyword} changed")
    for problem in problems:
        print("FAIL " + problem)
    if not problems:
        print("ok smoothed SU2 equals the VTK run, rows kept")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
