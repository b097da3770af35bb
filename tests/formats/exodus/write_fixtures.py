#!/usr/bin/python3
"""Writes the Exodus II test inputs with tools other than getme and the Exodus library:

- meshio's Exodus writer (meshio.write(..., file_format="exodus"), netCDF-4/HDF5 files) for one
  regular element of each type and a hybrid mesh with node sets;
- the netCDF4 Python module directly, laying out the variables as the Exodus II manual's
  Appendix A ("Implementation of EXODUS II with netCDF") names them, for what meshio cannot
  write: side sets, block and set names, number maps, classic and 64-bit-offset netCDF files, and
  the malformed files the reader must refuse.

Beside each readable file NAME.exo goes NAME.json: what it must read as in getme's terms (points,
cells as VTK codes in VTK node order, block ids, side set faces as the Exodus manual's side table
gives them, node sets).

Usage: write_fixtures.py OUTPUT_DIR HYBRID_EXAMPLE_VTK
"""

import json
import math
import os
import sys

import meshio
import netCDF4
import numpy as np

S3 = math.sqrt(3.0)

# Regular elements with unit edges in the paper's node order (docs/node-orders.md), which is
# meshio's and, per the Exodus II manual's element figures, Exodus's.
REGULAR = {
    "tetra": [(0, 0, 0), (1, 0, 0), (0.5, S3 / 2, 0), (0.5, S3 / 6, math.sqrt(2.0 / 3.0))],
    "hexahedron": [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
                   (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)],
    "pyramid": [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 0.5, math.sqrt(2.0) / 2)],
    "wedge": [(0, 0, 0), (1, 0, 0), (0.5, S3 / 2, 0), (0, 0, 1), (1, 0, 1), (0.5, S3 / 2, 1)],
}
EXODUS_NAME = {"tetra": "TETRA", "hexahedron": "HEX8", "pyramid": "PYRAMID", "wedge": "WEDGE"}
VTK_CODE = {"vertex": 1, "line": 3, "triangle": 5, "quad": 9, "tetra": 10, "hexahedron": 12,
            "wedge": 13, "pyramid": 14}

# The Exodus II manual's side numbering ("Side Set Node Ordering", 1-based local nodes, each
# side counter-clockwise seen from outside the element).
SIDES = {
    "tetra": [(1, 2, 4), (2, 3, 4), (1, 4, 3), (1, 3, 2)],
    "hexahedron": [(1, 2, 6, 5), (2, 3, 7, 6), (3, 4, 8, 7), (1, 5, 8, 4), (1, 4, 3, 2),
                   (5, 6, 7, 8)],
    "wedge": [(1, 2, 5, 4), (2, 3, 6, 5), (1, 4, 6, 3), (1, 3, 2), (4, 5, 6)],
    "pyramid": [(1, 2, 5), (2, 3, 5), (3, 4, 5), (1, 5, 4), (1, 4, 3, 2)],
}


def vtk_nodes(cell_type, nodes):
    """Exodus/meshio node order → VTK's: only the wedge differs (mirrored triangles)."""
    nodes = list(nodes)
    if cell_type == "wedge":
        return [nodes[i] for i in (0, 2, 1, 3, 5, 4)]
    return nodes


def put_names(nc, variable, dimension, names):
    data = nc.createVariable(variable, "S1", (dimension, "len_name"))
    data[:] = netCDF4.stringtochar(np.array(names, dtype="S33"))


def write_exodus(path, points, blocks, side_sets=(), node_sets=(), num_dim=3,
                 file_format="NETCDF3_64BIT_OFFSET", node_map=None, elem_map=None, title="test"):
    """blocks: [dict(id, name, type (Exodus name), cells (0-based, Exodus order),
    nodes_per_elem (default: len of the first cell))]; side_sets: [dict(id, name, elements
    (1-based), sides)]; node_sets: [dict(id, name, nodes (0-based))]. Nothing is checked, so
    malformed files can be written too."""
    with netCDF4.Dataset(path, "w", format=file_format) as nc:
        nc.title = title
        nc.version = np.float32(5.1)
        nc.api_version = np.float32(5.1)
        nc.floating_point_word_size = np.int32(8)
        nc.file_size = np.int32(1)
        nc.createDimension("len_string", 33)
        nc.createDimension("len_line", 81)
        nc.createDimension("len_name", 33)
        nc.createDimension("four", 4)
        nc.createDimension("time_step", None)
        nc.createDimension("num_dim", num_dim)
        nc.createDimension("num_nodes", len(points))
        element_count = sum(len(b["cells"]) for b in blocks)
        if element_count > 0:  # a zero-length netCDF-3 dimension would be the unlimited one
            nc.createDimension("num_elem", element_count)
        nc.createVariable("time_whole", "f8", ("time_step",))
        names = nc.createVariable("coor_names", "S1", ("num_dim", "len_name"))
        names[:] = netCDF4.stringtochar(np.array(["X", "Y", "Z"][:num_dim], dtype="S33"))
        pts = np.array(points, dtype=np.float64).reshape(-1, 3)
        for axis, name in enumerate("xyz"[:num_dim]):
            nc.createVariable("coord" + name, "f8", ("num_nodes",))[:] = pts[:, axis]
        if node_map is not None:
            nc.createVariable("node_num_map", "i4", ("num_nodes",))[:] = node_map
        if elem_map is not None:
            nc.createVariable("elem_num_map", "i4", ("num_elem",))[:] = elem_map
        if blocks:
            nc.createDimension("num_el_blk", len(blocks))
            nc.createVariable("eb_status", "i4", ("num_el_blk",))[:] = [1] * len(blocks)
            ids = nc.createVariable("eb_prop1", "i4", ("num_el_blk",))
            ids.setncattr("name", "ID")
            ids[:] = [b["id"] for b in blocks]
            put_names(nc, "eb_names", "num_el_blk", [b.get("name", "") for b in blocks])
            for k, b in enumerate(blocks, start=1):
                per = b.get("nodes_per_elem", len(b["cells"][0]))
                nc.createDimension(f"num_el_in_blk{k}", len(b["cells"]))
                nc.createDimension(f"num_nod_per_el{k}", per)
                dims = b.get("connect_dims", (f"num_el_in_blk{k}", f"num_nod_per_el{k}"))
                conn = nc.createVariable(f"connect{k}", "i4", dims)
                conn.elem_type = b["type"]
                if "connect_dims" in b:  # malformed on purpose: node 1 wherever it reaches
                    conn[:] = np.ones(conn.shape, dtype=np.int32)
                else:
                    conn[:] = np.array(b["cells"], dtype=np.int64).reshape(-1, per) + 1
        if side_sets:
            nc.createDimension("num_side_sets", len(side_sets))
            nc.createVariable("ss_status", "i4", ("num_side_sets",))[:] = [1] * len(side_sets)
            ids = nc.createVariable("ss_prop1", "i4", ("num_side_sets",))
            ids.setncattr("name", "ID")
            ids[:] = [s["id"] for s in side_sets]
            put_names(nc, "ss_names", "num_side_sets", [s.get("name", "") for s in side_sets])
            for k, s in enumerate(side_sets, start=1):
                nc.createDimension(f"num_side_ss{k}", len(s["elements"]))
                nc.createVariable(f"elem_ss{k}", "i4", (f"num_side_ss{k}",))[:] = s["elements"]
                nc.createVariable(f"side_ss{k}", "i4", (f"num_side_ss{k}",))[:] = s["sides"]
        if node_sets:
            nc.createDimension("num_node_sets", len(node_sets))
            nc.createVariable("ns_status", "i4", ("num_node_sets",))[:] = [1] * len(node_sets)
            ids = nc.createVariable("ns_prop1", "i4", ("num_node_sets",))
            ids.setncattr("name", "ID")
            ids[:] = [s["id"] for s in node_sets]
            put_names(nc, "ns_names", "num_node_sets", [s.get("name", "") for s in node_sets])
            for k, s in enumerate(node_sets, start=1):
                nc.createDimension(f"num_nod_ns{k}", len(s["nodes"]))
                nc.createVariable(f"node_ns{k}", "i4", (f"num_nod_ns{k}",))[:] = (
                    np.array(s["nodes"], dtype=np.int64) + 1)


def expected(path, points, cells, block_ids, side_faces=(), node_sets=()):
    """cells: [(meshio type, 0-based nodes in Exodus order)] in file order; side_faces:
    [(side set id, [0-based global nodes of the face in the manual's side order])]."""
    with open(path, "w") as out:
        json.dump({
            "points": [float(c) for p in points for c in p],
            "cells": [[VTK_CODE[t]] + [int(i) for i in vtk_nodes(t, n)] for t, n in cells],
            "block_ids": block_ids,
            "side_faces": [[s, [int(i) for i in f]] for s, f in side_faces],
            "node_sets": [[s["id"], s["name"], [int(i) for i in s["nodes"]]] for s in node_sets],
        }, out)


def shifted(points, dx, dy=0.0, dz=0.0):
    return [(x + dx, y + dy, z + dz) for x, y, z in points]


def regular_files(directory):
    for cell_type, points in REGULAR.items():
        n = len(points)
        name = f"regular_meshio_{cell_type}"
        meshio.write(os.path.join(directory, name + ".exo"),
                     meshio.Mesh(np.array(points, dtype=np.float64),
                                 [(cell_type, np.array([list(range(n))]))]),
                     file_format="exodus")
        # meshio numbers its blocks from 0 (eb_prop1).
        expected(os.path.join(directory, name + ".json"), points,
                 [(cell_type, list(range(n)))], [0])
        # The same element with a side set holding every side of it: the faces must come out
        # as the manual's side table says, and all of them facing outwards.
        name = f"regular_sides_{cell_type}"
        sides = list(range(1, len(SIDES[cell_type]) + 1))
        write_exodus(os.path.join(directory, name + ".exo"), points,
                     [dict(id=10, name="solid", type=EXODUS_NAME[cell_type],
                           cells=[list(range(n))])],
                     side_sets=[dict(id=3, name="all_sides", elements=[1] * len(sides),
                                     sides=sides)])
        faces = [(3, [i - 1 for i in SIDES[cell_type][s - 1]]) for s in sides]
        expected(os.path.join(directory, name + ".json"), points,
                 [(cell_type, list(range(n)))], [10], faces)


def hybrid(directory):
    """Every volume type twice in blocks of their own, a shell block on a hex face, side sets on
    several elements (one face in two sets), node sets, number maps."""
    points, blocks, cells, block_ids = [], [], [], []
    element = 0
    first_of = {}
    for k, cell_type in enumerate(("tetra", "wedge", "pyramid", "hexahedron")):
        block_cells = []
        for copy in range(2):
            first = len(points)
            points += shifted(REGULAR[cell_type], 2.0 * k + 0.25, 2.0 * copy, 0.5 * copy)
            block_cells.append(list(range(first, first + len(REGULAR[cell_type]))))
        first_of[cell_type] = element + 1
        element += len(block_cells)
        blocks.append(dict(id=100 + k, name=f"{cell_type}_block", type=EXODUS_NAME[cell_type],
                           cells=block_cells))
        cells += [(cell_type, c) for c in block_cells]
        block_ids += [100 + k] * len(block_cells)
    hexahedron = blocks[3]["cells"][0]
    shell = [hexahedron[4], hexahedron[5], hexahedron[6], hexahedron[7]]
    blocks.append(dict(id=7, name="lid", type="SHELL4", cells=[shell]))
    cells.append(("quad", shell))
    block_ids.append(7)
    side_sets = [
        dict(id=1, name="inlet", elements=[first_of["tetra"], first_of["wedge"] + 1,
                                           first_of["pyramid"]], sides=[4, 3, 5]),
        dict(id=2, name="wall", elements=[first_of["hexahedron"], first_of["tetra"]],
             sides=[6, 4]),
    ]
    side_faces = []
    for s in side_sets:
        for e, side in zip(s["elements"], s["sides"]):
            cell_type, nodes = cells[e - 1]
            side_faces.append((s["id"], [nodes[i - 1] for i in SIDES[cell_type][side - 1]]))
    node_sets = [dict(id=5, name="clamp", nodes=[0, 1, 2]),
                 dict(id=6, name="top", nodes=list(blocks[3]["cells"][1][4:]))]
    node_map = [1000 + 3 * i for i in range(len(points))]
    elem_map = [500 + i for i in range(element + 1)]
    for fmt, suffix in (("NETCDF3_64BIT_OFFSET", ""), ("NETCDF3_CLASSIC", "_classic"),
                        ("NETCDF4", "_netcdf4")):
        name = "hybrid" + suffix
        write_exodus(os.path.join(directory, name + ".exo"), points, blocks, side_sets,
                     node_sets, file_format=fmt, node_map=node_map, elem_map=elem_map,
                     title="hybrid test mesh")
        expected(os.path.join(directory, name + ".json"), points, cells, block_ids, side_faces,
                 node_sets)
    # The same volume cells through meshio (no side sets, no names; node sets as point sets).
    mesh = meshio.Mesh(np.array(points), [(t, np.array(b["cells"])) for t, b in
                                          zip(("tetra", "wedge", "pyramid", "hexahedron"),
                                              blocks)],
                       point_sets={s["name"]: np.array(s["nodes"]) for s in node_sets})
    meshio.write(os.path.join(directory, "hybrid_meshio.exo"), mesh, file_format="exodus")
    expected(os.path.join(directory, "hybrid_meshio.json"), points, cells[:-1],
             [0, 0, 1, 1, 2, 2, 3, 3],
             node_sets=[dict(id=k, name=s["name"], nodes=s["nodes"])
                        for k, s in enumerate(node_sets)])


def malformed(directory):
    tet = REGULAR["tetra"]
    hexa = REGULAR["hexahedron"]

    def bad(name, *args, **kwargs):
        write_exodus(os.path.join(directory, "bad_" + name + ".exo"), *args, **kwargs)

    bad("tet4_with_5_nodes", tet + [(1, 1, 1)],
        [dict(id=1, name="solid", type="TET4", cells=[[0, 1, 2, 3, 4]])])
    bad("side_of_shell", tet,
        [dict(id=1, name="solid", type="TETRA", cells=[[0, 1, 2, 3]]),
         dict(id=2, name="skin", type="TRI3", cells=[[0, 2, 1]])],
        side_sets=[dict(id=9, name="wall", elements=[2], sides=[1])])
    bad("hex20", hexa + [(2, 2, 2)] * 12,
        [dict(id=4, name="quadratic", type="HEX20", cells=[list(range(20))])])
    bad("node_out_of_range", tet,
        [dict(id=2, name="solid", type="TET4", cells=[[0, 1, 2, 6]])])
    bad("no_blocks", tet, [])
    bad("two_dimensional", [(0, 0, 0), (1, 0, 0), (0, 1, 0)],
        [dict(id=1, name="plate", type="TRI3", cells=[[0, 1, 2]])], num_dim=2)
    bad("side_out_of_range", tet,
        [dict(id=1, name="solid", type="TETRA", cells=[[0, 1, 2, 3]])],
        side_sets=[dict(id=9, name="wall", elements=[1, 1], sides=[2, 5])])
    bad("side_element_out_of_range", tet,
        [dict(id=1, name="solid", type="TETRA", cells=[[0, 1, 2, 3]])],
        side_sets=[dict(id=9, name="wall", elements=[2], sides=[1])])
    bad("node_set_out_of_range", tet,
        [dict(id=1, name="solid", type="TETRA", cells=[[0, 1, 2, 3]])],
        node_sets=[dict(id=4, name="clamp", nodes=[0, 4])])
    bad("polyhedron", tet,
        [dict(id=1, name="poly", type="NFACED", cells=[[0, 1, 2, 3]])])
    bad("duplicate_block_ids", tet + [(1, 1, 1)],
        [dict(id=3, name="a", type="TETRA", cells=[[0, 1, 2, 3]]),
         dict(id=3, name="b", type="TETRA", cells=[[1, 2, 3, 4]])])
    # The block says 4 nodes per element, its connectivity variable is 33 wide: the Exodus
    # library read all 33 into a buffer for 4 (found by fuzzing, 2026-11-27).
    bad("connect_over_other_dimensions", tet,
        [dict(id=1, name="solid", type="TETRA", cells=[[0, 1, 2, 3]],
              connect_dims=("num_el_in_blk1", "len_string"))])
    bad("file_size_array", tet, [dict(id=1, name="solid", type="TETRA", cells=[[0, 1, 2, 3]])])
    with netCDF4.Dataset(os.path.join(directory, "bad_file_size_array.exo"), "a") as nc:
        nc.file_size = np.arange(1000, dtype=np.int32)
    with open(os.path.join(directory, "bad_not_netcdf.exo"), "w") as out:
        out.write("this is not an Exodus file\n")


def main():
    directory = sys.argv[1]
    os.makedirs(directory, exist_ok=True)
    regular_files(directory)
    hybrid(directory)
    malformed(directory)
    # The repository's hybrid example through meshio's VTK reader and Exodus writer (one
    # Exodus block per run of one cell type, meshio's block order = the file's cell order).
    meshio.write(os.path.join(directory, "hybrid_example_meshio.exo"),
                 meshio.read(sys.argv[2]), file_format="exodus")


if __name__ == "__main__":
    main()
