#!/usr/bin/python3
"""The smoothed result of a CGNS mesh equals the VTK run of the same mesh: each shared Mesquite
mesh is converted to .cgns by `getme convert`, both are smoothed by `getme smooth`, and the
points of both results (as ASCII VTK, shortest round-trip decimals) must agree bit for bit, and
differ from the input's. Also: `--ascii` with a .cgns output is refused with its message.

Usage: smooth_matches_vtk.py GETME SHARED_MESQUITE_DIR WORK_DIR NAME...
"""

import os
import subprocess
import sys


def run(*args):
    result = subprocess.run(args, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"{' '.join(args)}: exit {result.returncode}\n{result.stderr}")


def points_section(path):
    lines = open(path).read().split("\n")
    start = next(i for i, line in enumerate(lines) if line.startswith("POINTS"))
    end = next(i for i, line in enumerate(lines) if line.startswith("CELLS"))
    return lines[start:end]


def main():
    getme, shared, work, names = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
    os.makedirs(work, exist_ok=True)
    failed = False
    for name in names:
        source = os.path.join(shared, name + ".vtk")
        cgns = os.path.join(work, name + ".cgns")
        run(getme, "convert", source, cgns)
        run(getme, "smooth", source, os.path.join(work, name + ".smoothed.vtk"), "--ascii")
        run(getme, "smooth", cgns, os.path.join(work, name + ".smoothed.cgns"))
        run(getme, "convert", os.path.join(work, name + ".smoothed.cgns"),
            os.path.join(work, name + ".smoothed_cgns.vtk"), "--ascii")
        from_vtk = points_section(os.path.join(work, name + ".smoothed.vtk"))
        from_cgns = points_section(os.path.join(work, name + ".smoothed_cgns.vtk"))
        # The input as ASCII too: smoothing must have moved something, or the check proves
        # nothing.
        run(getme, "convert", source, os.path.join(work, name + ".input.vtk"), "--ascii")
        moved = points_section(os.path.join(work, name + ".input.vtk")) != from_vtk
        same = from_vtk == from_cgns and len(from_vtk) > 1
        print(f"{name}: {'same points' if same else 'points differ'} ({len(from_vtk) - 1} lines)"
              f"{'' if moved else ', but smoothing moved no point'}")
        failed = failed or not same or not moved
    # CGNS output is binary (HDF5) only: --ascii is refused, by name.
    result = subprocess.run([getme, "convert", os.path.join(shared, names[0] + ".vtk"),
                             os.path.join(work, "ascii.cgns"), "--ascii"],
                            capture_output=True, text=True)
    expected = "CGNS output is binary only (HDF5, written by the CGNS library)"
    if result.returncode == 0 or expected not in result.stderr:
        print(f"--ascii with .cgns output: exit {result.returncode}, stderr {result.stderr!r}")
        failed = True
    sys.exit(1 if failed or not names else 0)


if __name__ == "__main__":
    main()
