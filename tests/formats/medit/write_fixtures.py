#!/usr/bin/python3
"""Writes the MEDIT test inputs with other tools' own MEDIT writers: gmsh (gmsh.write) and meshio
(meshio.write(..., file_format="medit")), each beside a sidecar NAME.expected holding what the
file must read as, in getme's terms (VTK cell codes and node order, refs, 1e-13 tolerance only
where gmsh rounds coordinates to 14 digits).

Usage: write_fixtures.py OUTPUT_DIR
"""

import math
import os
import sys

import gmsh
import meshio
import numpy as np

S3 = math.sqrt(3.0)

# Regular elements with unit edges in Gmsh's node order (= the paper's, docs/node-orders.md): tet
# with det[p1-p0, p2-p0, p3-p0] > 0, hex and prism bottom counter-clockwise seen from the top,
# pyramid base counter-clockwise seen from the apex.
REGULAR = {
    "tetra": [(0, 0, 0), (1, 0, 0), (0.5, S3 / 2, 0), (0.5, S3 / 6, math.sqrt(2.0 / 3.0))],
    "hexahedron": [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
                   (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)],
    "pyramid": [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 0.5, math.sqrt(2.0) / 2)],
    "wedge": [(0, 0, 0), (1, 0, 0), (0.5, S3 / 2, 0), (0, 0, 1), (1, 0, 1), (0.5, S3 / 2, 1)],
}

VTK_CODE = {"vertex": 1, "line": 3, "triangle": 5, "quad": 9, "tetra": 10, "hexahedron": 12,
            "wedge": 13, "pyramid": 14}
GMSH_TYPE = {"line": 1, "triangle": 2, "quad": 3, "tetra": 4, "hexahedron": 5}


def vtk_nodes(cell_type, nodes):
    """Gmsh/meshio node order → VTK's: only the wedge differs (mirrored triangles)."""
    nodes = list(nodes)
    if cell_type == "wedge":
        return [nodes[i] for i in (0, 2, 1, 3, 5, 4)]
    return nodes


def write_expected(path, points, cells, point_refs, cell_refs, tolerance=0.0):
    """cells: (meshio type, 0-based nodes in Gmsh order) in file order."""
    with open(path, "w") as out:
        out.write(f"tolerance {tolerance!r}\n")
        out.write(f"points {len(points)}\n")
        for p in points:
            out.write(" ".join(repr(float(c)) for c in p) + "\n")
        out.write(f"point_refs {len(point_refs)}\n")
        out.write(" ".join(str(int(r)) for r in point_refs) + "\n")
        out.write(f"cells {len(cells)}\n")
        for cell_type, nodes in cells:
            ids = vtk_nodes(cell_type, nodes)
            out.write(f"{VTK_CODE[cell_type]} {len(ids)} " + " ".join(str(int(i)) for i in ids) + "\n")
        out.write(f"cell_refs {len(cell_refs)}\n")
        out.write(" ".join(str(int(r)) for r in cell_refs) + "\n")


def meshio_file(directory, name, points, blocks, point_refs, block_refs, dtype=np.float64):
    """blocks: [(meshio type, [[nodes]...])]; one block per type (MEDIT has one section each)."""
    mesh = meshio.Mesh(
        np.array(points, dtype=dtype),
        [(t, np.array(c, dtype=np.int64)) for t, c in blocks],
        point_data={"medit:ref": np.array(point_refs, dtype=np.int64)},
        cell_data={"medit:ref": [np.array(r, dtype=np.int64) for r in block_refs]},
    )
    meshio.write(os.path.join(directory, name + ".mesh"), mesh, file_format="medit")
    cells = [(t, nodes) for t, c in blocks for nodes in c]
    refs = [r for rs in block_refs for r in rs]
    written_points = np.array(points, dtype=dtype).astype(np.float64)
    write_expected(os.path.join(directory, name + ".expected"), written_points, cells, point_refs,
                   refs)


def gmsh_file(directory, name, volumes, others, tolerance):
    """volumes: [(tag, points, [(meshio type, [[0-based nodes into points]])])], nodes owned by
    volume entities; others: [(dim, tag, meshio type, [[global 0-based nodes]])].
    gmsh's writer numbers vertices entity by entity and writes each vertex's entity tag as its
    ref and each element's elementary entity tag as its ref, sections in the order Edges,
    Triangles, Quadrilaterals, Tetrahedra, Hexahedra."""
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add(name)
    points, point_refs, by_type = [], [], {}
    next_element = 1
    for tag, volume_points, blocks in volumes:
        gmsh.model.addDiscreteEntity(3, tag)
        first = len(points)
        gmsh.model.mesh.addNodes(3, tag, [first + i + 1 for i in range(len(volume_points))],
                                 [c for p in volume_points for c in p])
        points += volume_points
        point_refs += [tag] * len(volume_points)
        for cell_type, cells in blocks:
            global_cells = [[first + i for i in c] for c in cells]
            gmsh.model.mesh.addElementsByType(
                tag, GMSH_TYPE[cell_type], list(range(next_element, next_element + len(cells))),
                [i + 1 for c in global_cells for i in c])
            next_element += len(cells)
            by_type.setdefault(cell_type, []).extend((c, tag) for c in global_cells)
    for dim, tag, cell_type, cells in others:
        gmsh.model.addDiscreteEntity(dim, tag)
        gmsh.model.mesh.addElementsByType(
            tag, GMSH_TYPE[cell_type], list(range(next_element, next_element + len(cells))),
            [i + 1 for c in cells for i in c])
        next_element += len(cells)
        by_type.setdefault(cell_type, []).extend((c, tag) for c in cells)
    gmsh.write(os.path.join(directory, name + ".mesh"))
    gmsh.finalize()
    cells, refs = [], []
    for cell_type in ("line", "triangle", "quad", "tetra", "hexahedron"):
        for nodes, tag in by_type.get(cell_type, []):
            cells.append((cell_type, nodes))
            refs.append(tag)
    write_expected(os.path.join(directory, name + ".expected"), points, cells, point_refs, refs,
                   tolerance)


def shifted(points, dx, dy=0.0, dz=0.0):
    return [(x + dx, y + dy, z + dz) for x, y, z in points]


def main():
    directory = sys.argv[1]
    os.makedirs(directory, exist_ok=True)

    # One regular element per file, by each tool that writes the type.
    for cell_type, points in REGULAR.items():
        n = len(points)
        meshio_file(directory, f"regular_meshio_{cell_type}", points,
                    [(cell_type, [list(range(n))])], [0] * n, [[7]])
    # gmsh prints coordinates with 14 significant digits: compare them to 1e-13.
    for cell_type in ("tetra", "hexahedron"):
        points = REGULAR[cell_type]
        gmsh_file(directory, f"regular_gmsh_{cell_type}",
                  [(1, points, [(cell_type, [list(range(len(points)))])])], [], 1e-13)

    # A hybrid mesh: every volume type twice (valid, apart from each other), surface elements
    # on their faces, edges, refs on everything.
    points, blocks = [], []
    volume_blocks = []
    for k, cell_type in enumerate(("tetra", "wedge", "pyramid", "hexahedron")):
        cells = []
        for copy in range(2):
            first = len(points)
            points += shifted(REGULAR[cell_type], 2.0 * k + 0.25, 2.0 * copy, 0.5 * copy)
            cells.append(list(range(first, first + len(REGULAR[cell_type]))))
        volume_blocks.append((cell_type, cells))
    tet, wedge, pyramid, hexahedron = (b[1][0] for b in volume_blocks)
    blocks.append(("line", [[tet[0], tet[1]], [hexahedron[6], hexahedron[7]]]))
    blocks.append(("triangle", [[tet[0], tet[2], tet[1]], [wedge[3], wedge[4], wedge[5]]]))
    blocks.append(("quad", [[hexahedron[0], hexahedron[3], hexahedron[2], hexahedron[1]],
                            [pyramid[0], pyramid[3], pyramid[2], pyramid[1]]]))
    blocks += volume_blocks
    point_refs = [i % 4 + 1 for i in range(len(points))]
    block_refs = [[100 * (b + 1) + i for i in range(len(cells))]
                  for b, (_, cells) in enumerate(blocks)]
    meshio_file(directory, "hybrid_meshio", points, blocks, point_refs, block_refs)
    # The same as single precision: meshio writes MeshVersionFormatted 1.
    meshio_file(directory, "hybrid_meshio_float", points, blocks, point_refs, block_refs,
                dtype=np.float32)

    # gmsh writes no prisms or pyramids (GModelIO_MESH.cpp): tets, hexes, triangles, quads,
    # edges. Coordinates in eighths, which its 14 digits print exactly.
    tets = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 1)]
    hexes = shifted(REGULAR["hexahedron"], 2.0) + shifted(REGULAR["hexahedron"], 2.0, 0.0, 1.0)[4:]
    gmsh_file(directory, "hybrid_gmsh",
              [(1, tets, [("tetra", [[0, 1, 2, 3], [1, 2, 3, 4]])]),
               (2, [(x + 0.125, y, z) for x, y, z in hexes],
                [("hexahedron", [[0, 1, 2, 3, 4, 5, 6, 7], [4, 5, 6, 7, 8, 9, 10, 11]])])],
              [(2, 3, "triangle", [[0, 2, 1], [1, 2, 4]]),
               (2, 4, "quad", [[5, 8, 7, 6]]),
               (1, 5, "line", [[0, 1], [5, 6], [9, 10]])],
              0.0)


if __name__ == "__main__":
    main()
