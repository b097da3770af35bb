#!/usr/bin/python3
"""Writes the Python client tests' input meshes with meshio's own VTK writer (ctest fixture):

  surface.vtk   tests/data/hybrid-example.vtk (tetra, hexahedron, wedge, pyramid) plus surface
                cells found here from the volume cells' faces: a triangle block before the volume
                blocks (so cell indices differ from element numbers), then quad, line and vertex
                blocks; cell data extended to them, point data "temperature".
  fixed.vtk     surface.vtk plus point data "fixed" (1 on every 9th interior node).
  inverted.vtk  surface.vtk with one cell of each volume type inverted.
  regular.vtk   one regular element of each type (all edges 1), oriented as in docs/node-orders.md.
  meshes.json   what the tests check against: the fixed and the interior nodes, the inverted
                cells (cell indices over all blocks).
"""

import argparse
import json
import math
import os

import meshio
import numpy as np

# Faces of each meshio volume type in meshio's node order (VTK's; Gmsh's prism order for wedge,
# which is the paper's): the paper's tables F (Sec. 2.1), 0-based.
FACES = {
    "tetra": [(0, 1, 2), (0, 1, 3), (1, 2, 3), (2, 0, 3)],
    "hexahedron": [(0, 1, 2, 3), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7),
                   (4, 7, 6, 5)],
    "pyramid": [(0, 1, 2, 3), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)],
    "wedge": [(0, 1, 2), (0, 1, 4, 3), (1, 2, 5, 4), (2, 0, 3, 5), (3, 5, 4)],
}
# A node permutation that inverts a cell of each type.
INVERT = {
    "tetra": [1, 0, 2, 3],
    "hexahedron": [4, 5, 6, 7, 0, 1, 2, 3],
    "pyramid": [0, 3, 2, 1, 4],
    "wedge": [3, 4, 5, 0, 1, 2],
}


def boundary_faces(cells):
    """Faces that belong to exactly one volume cell, as (triangles, quads) arrays."""
    count = {}
    for block in cells:
        for cell in block.data:
            for face in FACES[block.type]:
                nodes = tuple(int(cell[i]) for i in face)
                key = tuple(sorted(nodes))
                count.setdefault(key, [0, nodes])[0] += 1
    triangles = [nodes for n, nodes in count.values() if n == 1 and len(nodes) == 3]
    quads = [nodes for n, nodes in count.values() if n == 1 and len(nodes) == 4]
    return np.array(triangles, dtype=np.int64), np.array(quads, dtype=np.int64)


def with_surface(volume):
    triangles, quads = boundary_faces(volume.cells)
    lines = triangles[:20, :2]
    vertices = triangles[:5, :1]
    blocks = ([meshio.CellBlock("triangle", triangles)] + list(volume.cells) +
              [meshio.CellBlock("quad", quads), meshio.CellBlock("line", lines),
               meshio.CellBlock("vertex", vertices)])
    cell_data = {}
    for name, arrays in volume.cell_data.items():
        def filler(n, like):
            return np.full((n,) + like.shape[1:], -1, dtype=like.dtype)

        cell_data[name] = ([filler(len(triangles), arrays[0])] + list(arrays) +
                           [filler(len(quads), arrays[0]), filler(len(lines), arrays[0]),
                            filler(len(vertices), arrays[0])])
    cell_data["surface"] = [np.full(len(b.data), int(b.type not in FACES), dtype=np.int32)
                            for b in blocks]
    points = volume.points
    point_data = {"temperature": points[:, 0] + 2 * points[:, 1] - points[:, 2]}
    boundary = np.unique(np.concatenate([triangles.reshape(-1), quads.reshape(-1)]))
    return meshio.Mesh(points, blocks, point_data=point_data, cell_data=cell_data), boundary


def regular_elements():
    """One regular element of each type, 2 apart along x."""
    s3, h = math.sqrt(3), math.sqrt(2.0 / 3.0)
    shapes = {
        "tetra": [(0, 0, 0), (1, 0, 0), (0.5, s3 / 2, 0), (0.5, s3 / 6, h)],
        "hexahedron": [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1),
                       (1, 1, 1), (0, 1, 1)],
        "pyramid": [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 0.5, math.sqrt(2) / 2)],
        # Gmsh prism order (meshio's "wedge"): bottom counter-clockwise seen from the top.
        "wedge": [(0, 0, 0), (1, 0, 0), (0.5, s3 / 2, 0), (0, 0, 1), (1, 0, 1), (0.5, s3 / 2, 1)],
    }
    points, blocks = [], []
    for offset, (cell_type, corners) in enumerate(shapes.items()):
        first = len(points)
        points += [(x + 2 * offset, y, z) for x, y, z in corners]
        blocks.append(meshio.CellBlock(cell_type, np.arange(first, len(points))[None, :]))
    return meshio.Mesh(np.array(points, dtype=np.float64), blocks)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--hybrid", required=True, help="tests/data/hybrid-example.vtk")
    parser.add_argument("--out", required=True)
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)

    def write(name, mesh, binary=True):
        meshio.write(os.path.join(args.out, name), mesh, file_format="vtk", binary=binary)

    surface, boundary = with_surface(meshio.read(args.hybrid))
    write("surface.vtk", surface)

    interior = np.setdiff1d(np.arange(len(surface.points)), boundary)
    fixed_nodes = interior[::9]
    fixed = meshio.Mesh(surface.points, surface.cells, cell_data=surface.cell_data,
                        point_data={**surface.point_data,
                                    "fixed": np.isin(np.arange(len(surface.points)),
                                                     fixed_nodes).astype(np.int32)})
    write("fixed.vtk", fixed, binary=False)

    inverted_cells = []
    blocks, first_cell = [], 0
    for block in surface.cells:
        data = block.data.copy()
        if block.type in INVERT and block.type not in [t for t, _ in inverted_cells]:
            row = len(data) // 2
            data[row] = data[row][INVERT[block.type]]
            inverted_cells.append((block.type, first_cell + row))
        blocks.append(meshio.CellBlock(block.type, data))
        first_cell += len(data)
    inverted = meshio.Mesh(surface.points, blocks, cell_data=surface.cell_data)
    write("inverted.vtk", inverted)

    write("regular.vtk", regular_elements(), binary=False)

    with open(os.path.join(args.out, "meshes.json"), "w") as manifest:
        json.dump({"fixed_nodes": fixed_nodes.tolist(), "interior_nodes": interior.tolist(),
                   "inverted_cells": sorted(cell for _, cell in inverted_cells)}, manifest)


if __name__ == "__main__":
    main()
