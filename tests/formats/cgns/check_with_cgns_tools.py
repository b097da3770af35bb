#!/usr/bin/python3
"""Checks getme's own CGNS files (written by formats_cgns_test into the fixture directory) with
tools that are not getme:
- cgnscheck (the CGNS project's validator) must accept each file: exit 0, no error lines;
- h5py reads the HDF5 nodes directly (SIDS-to-HDF5 layout: Base/Zone/GridCoordinates/
  CoordinateX/" data", <section>/ElementConnectivity/" data", …);
- cgns_to_vtk (the CGNS project's converter, through the CGNS library) converts each file to
  VTK, which meshio then reads: the points must match h5py's within cgns_to_vtk's float
  precision, and the cells must be h5py's element connectivity (cgns_to_vtk copies CGNS node
  order into VTK cells unpermuted), element by element. It prints coordinates with 6
  significant digits: points agree to 1e-5 relative.

Usage: check_with_cgns_tools.py FIXTURE_DIR NAME...
"""

import os
import subprocess
import sys
import tempfile

import h5py
import meshio
import numpy as np

# ElementType_t values (cgnslib.h) and their node counts.
NODES = {2: 1, 3: 2, 5: 3, 7: 4, 10: 4, 12: 5, 14: 6, 17: 8}
MIXED = 20
VOLUME = {10, 12, 14, 17}


def h5py_content(path):
    """Points and the volume elements (CGNS node order, 0-based, element-number order)."""
    f = h5py.File(path, "r")
    base = next(k for k in f.keys() if isinstance(f[k], h5py.Group) and k.strip() != "")
    zone_group = f[base]
    zone = next(k for k in zone_group.keys()
                if isinstance(zone_group[k], h5py.Group) and zone_group[k].attrs.get("label", b"")
                .tobytes().rstrip(b"\0") == b"Zone_t")
    z = zone_group[zone]
    points = np.column_stack([z["GridCoordinates"][axis][" data"][()]
                              for axis in ("CoordinateX", "CoordinateY", "CoordinateZ")])
    elements = []
    for name in z.keys():
        node = z[name]
        if not isinstance(node, h5py.Group):
            continue
        if node.attrs["label"].tobytes().rstrip(b"\0") != b"Elements_t":
            continue
        element_type = int(node[" data"][()][0])
        start = int(node["ElementRange"][" data"][()][0])
        connectivity = [int(v) for v in node["ElementConnectivity"][" data"][()]]
        position, number = 0, start
        while position < len(connectivity):
            cell_type = element_type
            if element_type == MIXED:
                cell_type = connectivity[position]
                position += 1
            count = NODES[cell_type]
            if cell_type in VOLUME:
                elements.append((number, [v - 1 for v in connectivity[position:position + count]]))
            position += count
            number += 1
    elements.sort()
    return points, [nodes for _, nodes in elements]


def check(directory, name):
    path = os.path.join(directory, name + ".cgns")
    problems = []
    result = subprocess.run(["cgnscheck", path], capture_output=True, text=True)
    if result.returncode != 0 or "ERROR" in result.stdout.upper().replace("0 ERRORS", ""):
        problems.append(f"cgnscheck: exit {result.returncode}: {result.stdout[-400:]}")
    points, elements = h5py_content(path)
    with tempfile.TemporaryDirectory() as out:
        result = subprocess.run(["cgns_to_vtk", "-a", path, out], capture_output=True, text=True)
        written = [f for f in os.listdir(out) if f.endswith(".vtk")]
        if result.returncode != 0 or len(written) != 1:
            return problems + [f"cgns_to_vtk: exit {result.returncode}, files {written}"]
        mesh = meshio.read(os.path.join(out, written[0]))
    if mesh.points.shape != points.shape or not np.allclose(mesh.points, points, rtol=1e-5,
                                                              atol=1e-6):
        problems.append("points differ between h5py and cgns_to_vtk + meshio")
    # meshio keeps VTK's cell order; cgns_to_vtk writes the volume elements in section order.
    # meshio's VTK reader mirrors a VTK wedge into its own (Gmsh) prism order: undone here, so
    # that the cells are what cgns_to_vtk wrote.
    seen = [[int(nodes[i]) for i in ((0, 2, 1, 3, 5, 4) if block.type == "wedge"
                                     else range(len(nodes)))]
            for block in mesh.cells for nodes in block.data]
    if seen != elements:
        problems.append(f"volume cells differ ({len(seen)} via cgns_to_vtk, {len(elements)} in "
                        "the file)")
    if not elements:
        problems.append("no volume cells: the check would prove nothing")
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
