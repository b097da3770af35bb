#!/usr/bin/python3
"""Writes the CGNS test inputs with other tools: meshio writes UGRID (AFLR3) files, which the CGNS
project's own converter aflr3_to_cgns (Debian cgns-convert) turns into CGNS; meshio also writes
its own h5py-made "CGNS" file, which the CGNS library refuses. Beside each CGNS file a NAME.json
says what it must read as in getme's terms (VTK cell codes and node order, boundary conditions).

Usage: write_fixtures.py OUTPUT_DIR
"""

import json
import math
import os
import subprocess
import sys

import meshio
import numpy as np

S3 = math.sqrt(3.0)

# Regular elements with unit edges in meshio's (= Gmsh's, the paper's) node order: tet with
# det[p1-p0, p2-p0, p3-p0] > 0, hex and prism bottom counter-clockwise seen from the top,
# pyramid base counter-clockwise seen from the apex.
REGULAR = {
    "tetra": [(0, 0, 0), (1, 0, 0), (0.5, S3 / 2, 0), (0.5, S3 / 6, math.sqrt(2.0 / 3.0))],
    "hexahedron": [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
                   (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)],
    "pyramid": [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 0.5, math.sqrt(2.0) / 2)],
    "wedge": [(0, 0, 0), (1, 0, 0), (0.5, S3 / 2, 0), (0, 0, 1), (1, 0, 1), (0.5, S3 / 2, 1)],
}
VTK_CODE = {"triangle": 5, "quad": 9, "tetra": 10, "hexahedron": 12, "wedge": 13, "pyramid": 14}

# meshio's UGRID writer stores its pyramid (p0..p4) as (p1, p0, p4, p2, p3) (meshio/ugrid/
# _ugrid.py); aflr3_to_cgns stores a UGRID pyramid (a0..a4) as PYRA_5 (a0, a3, a4, a1, a2)
# (aflr3_to_cgns.c): together PYRA_5 = (p1, p2, p3, p0, p4), the same pyramid with its base
# rotated. The other types pass both tools unpermuted.
PYRAMID_THROUGH_UGRID = [1, 2, 3, 0, 4]
# UGRID stores what meshio calls (p0..p4) as (p1, p0, p4, p2, p3).
MESHIO_TO_UGRID_PYRAMID = [1, 0, 4, 2, 3]


def vtk_nodes(cell_type, nodes):
    """meshio (Gmsh) order → VTK's: only the wedge differs (mirrored triangles)."""
    nodes = list(nodes)
    if cell_type == "wedge":
        return [nodes[i] for i in (0, 2, 1, 3, 5, 4)]
    return nodes


def convert(directory, ugrid_name, cgns_name, options=()):
    result = subprocess.run(["aflr3_to_cgns", *options, os.path.join(directory, ugrid_name),
                             os.path.join(directory, cgns_name)],
                            capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"aflr3_to_cgns failed: {result.stdout}{result.stderr}")


def write_json(path, content):
    with open(path, "w") as out:
        json.dump(content, out, indent=1)


def regular_elements(directory):
    for cell_type, points in REGULAR.items():
        name = f"regular_{cell_type}"
        mesh = meshio.Mesh(np.array(points, dtype=np.float64),
                           [(cell_type, np.array([list(range(len(points)))]))])
        # big-endian C stream, 8-byte reals: aflr3_to_cgns's default input
        meshio.write(os.path.join(directory, name + ".b8.ugrid"), mesh)
        convert(directory, name + ".b8.ugrid", name + ".cgns")
        nodes = list(range(len(points)))
        if cell_type == "pyramid":
            nodes = [nodes[i] for i in PYRAMID_THROUGH_UGRID]
        write_json(os.path.join(directory, name + ".json"), {
            "points": [list(map(float, p)) for p in points],
            "cells": [[VTK_CODE[cell_type], vtk_nodes(cell_type, nodes)]],
            "bcs": []})


def shifted(points, dx, dy=0.0, dz=0.0):
    return [(x + dx, y + dy, z + dz) for x, y, z in points]


def hybrid(directory):
    """Two elements of each type and boundary faces with surface IDs and a .mapbc, as an ASCII
    UGRID file (format: simcenter.msstate.edu ug_io 3d_grid_file_type_ugrid), converted with
    aflr3_to_cgns -f. It writes one section per type (TETRA_4, PYRA_5, PENTA_6, HEXA_8), then
    TRI_3 and QUAD_4 sections per surface ID, each with a BC_t (PointRange, FaceCenter) named
    after its BCType and set number."""
    points, volumes = [], {}
    for k, cell_type in enumerate(("tetra", "pyramid", "wedge", "hexahedron")):
        for copy in range(2):
            first = len(points)
            points += shifted(REGULAR[cell_type], 2.0 * k + 0.25, 2.0 * copy, 0.5 * copy)
            volumes.setdefault(cell_type, []).append(list(range(first, first + len(REGULAR[cell_type]))))
    tet, pyramid, wedge, hexahedron = (volumes[t][0] for t in ("tetra", "pyramid", "wedge", "hexahedron"))
    # (nodes, surface id): ids 1 and 2 on triangles, 3 on quads; .mapbc: 1 → 4000 (viscous wall),
    # 2 → 5000 (farfield), 3 → 6662 (symmetry plane).
    triangles = [([tet[0], tet[2], tet[1]], 1), ([wedge[3], wedge[4], wedge[5]], 2),
                 ([tet[0], tet[1], tet[3]], 1)]
    quads = [([hexahedron[0], hexahedron[3], hexahedron[2], hexahedron[1]], 3),
             ([pyramid[0], pyramid[3], pyramid[2], pyramid[1]], 3)]
    lines = [" ".join(str(n) for n in (len(points), len(triangles), len(quads), 2, 2, 2, 2))]
    lines += [" ".join(repr(float(c)) for c in p) for p in points]
    lines += [" ".join(str(i + 1) for i in nodes) for nodes, _ in triangles]
    lines += [" ".join(str(i + 1) for i in nodes) for nodes, _ in quads]
    lines += [str(tag) for _, tag in triangles + quads]
    for cell_type in ("tetra", "pyramid", "wedge", "hexahedron"):
        for nodes in volumes[cell_type]:
            if cell_type == "pyramid":
                nodes = [nodes[i] for i in MESHIO_TO_UGRID_PYRAMID]
            lines.append(" ".join(str(i + 1) for i in nodes))
    with open(os.path.join(directory, "hybrid.ugrid"), "w") as out:
        out.write("\n".join(lines) + "\n")
    with open(os.path.join(directory, "hybrid.mapbc"), "w") as out:
        out.write("3\n1 4000\n2 5000\n3 6662\n")
    convert(directory, "hybrid.ugrid", "hybrid.cgns", ["-f"])

    cells = []
    for cell_type in ("tetra", "pyramid", "wedge", "hexahedron"):
        for nodes in volumes[cell_type]:
            if cell_type == "pyramid":
                nodes = [nodes[i] for i in PYRAMID_THROUGH_UGRID]
            cells.append([VTK_CODE[cell_type], vtk_nodes(cell_type, nodes)])
    bcs = []
    # aflr3_to_cgns sorts faces by surface ID, one section and BC per ID, triangles first.
    for kind, faces, bc_name, bc_type, tag in (
            ("triangle", triangles, "WallViscous 1", "BCWallViscous", 1),
            ("triangle", triangles, "Farfield 2", "BCFarfield", 2),
            ("quad", quads, "SymmetryPlane 3", "BCSymmetryPlane", 3)):
        members = []
        for nodes, face_tag in faces:
            if face_tag == tag:
                members.append(len(cells))
                cells.append([VTK_CODE[kind], list(nodes)])
        bcs.append({"name": bc_name, "type": bc_type, "cells": members})
    write_json(os.path.join(directory, "hybrid.json"),
               {"points": [list(map(float, p)) for p in points], "cells": cells, "bcs": bcs})


def meshio_h5py_file(directory):
    """meshio's own CGNS writer: an HDF5 file with CGNS-like group names but none of the node
    attributes (label, type) SIDS-to-HDF5 requires, so the CGNS library refuses it."""
    points = REGULAR["tetra"]
    mesh = meshio.Mesh(np.array(points), [("tetra", np.array([[0, 1, 2, 3]]))])
    meshio.write(os.path.join(directory, "meshio_written.cgns"), mesh, file_format="cgns")


def oversized_section(directory):
    """regular_tetra.cgns with its TETRA_4 section claiming 100,000,000 elements, their
    connectivity an HDF5 dataset of 400,000,000 values in unwritten chunks: a consistent file
    for the CGNS library that holds no data, so the file stays small (a damaged or hostile file
    of the kind the reader must not allocate gigabytes for)."""
    import shutil
    import h5py
    path = os.path.join(directory, "oversized_section.cgns")
    shutil.copy(os.path.join(directory, "regular_tetra.cgns"), path)
    with h5py.File(path, "r+") as f:
        section = f["Base/Zone/TetElements"]
        section["ElementRange/ data"][...] = np.array([1, 100_000_000], dtype=np.int32)
        connectivity = section["ElementConnectivity"]
        del connectivity[" data"]
        connectivity.create_dataset(" data", shape=(400_000_000,), dtype=np.int32,
                                    chunks=(1 << 16,))
        f["Base/Zone/ data"][...] = np.array([[4], [100_000_000], [0]], dtype=np.int32)


def main():
    directory = sys.argv[1]
    os.makedirs(directory, exist_ok=True)
    regular_elements(directory)
    hybrid(directory)
    meshio_h5py_file(directory)
    oversized_section(directory)


if __name__ == "__main__":
    main()
