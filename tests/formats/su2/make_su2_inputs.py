#!/usr/bin/python3
"""SU2 files written by other tools, for formats_su2_test, each with NAME.expected.json saying
what the tool was given: "points", "cells" (VTK type code and 0-based nodes, in the order
written) and "markers" (name → boundary cells, in order).

- box_gmsh.su2: Gmsh's own SU2 writer on a box of tetrahedra it meshes here, the six sides as
  named physical surfaces (→ markers). Nodes are renumbered 1..N first, so point i is node i+1.
- hybrid_meshio.su2: meshio's SU2 writer on a hand-made mesh of each volume type (two
  hexahedra, a wedge, a pyramid on top, a tetrahedron). Without markers: meshio 7's writer fails
  on boundary cells ("cannot unpack non-iterable CellBlock object", _su2.py write()).

usage: make_su2_inputs.py OUTPUT_DIR
"""

import json
import os
import sys

import gmsh
import meshio
import numpy as np

VTK_TETRA, VTK_HEXAHEDRON, VTK_WEDGE, VTK_PYRAMID, VTK_TRIANGLE = 10, 12, 13, 14, 5


def write_gmsh_box(out):
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("box")
    gmsh.model.occ.addBox(0, 0, 0, 1, 0.5, 0.25)
    gmsh.model.occ.synchronize()
    for _, surface in gmsh.model.getEntities(2):
        group = gmsh.model.addPhysicalGroup(2, [surface], 10 + surface)
        gmsh.model.setPhysicalName(2, group, f"side{surface}")
    gmsh.model.addPhysicalGroup(3, [1], 1)
    gmsh.option.setNumber("Mesh.MeshSizeMax", 0.2)
    gmsh.model.mesh.generate(3)
    gmsh.model.mesh.renumberNodes()
    tags, coords, _ = gmsh.model.mesh.getNodes()
    order = np.argsort(tags)
    points = np.asarray(coords).reshape(-1, 3)[order]
    assert (np.asarray(tags)[order] == np.arange(1, len(tags) + 1)).all()
    _, tet_nodes = gmsh.model.mesh.getElementsByType(4)
    cells = [[VTK_TETRA] + [int(n) - 1 for n in tet]
             for tet in np.asarray(tet_nodes).reshape(-1, 4)]
    markers = {}
    for dim, tag in gmsh.model.getPhysicalGroups(2):
        name = gmsh.model.getPhysicalName(dim, tag)
        for entity in gmsh.model.getEntitiesForPhysicalGroup(dim, tag):
            _, _, nodes = gmsh.model.mesh.getElements(2, entity)
            for triangle in np.asarray(nodes[0]).reshape(-1, 3):
                markers.setdefault(name, []).append([VTK_TRIANGLE] + [int(n) - 1 for n in triangle])
    gmsh.write(os.path.join(out, "box_gmsh.su2"))
    gmsh.finalize()
    return {"points": points.tolist(), "cells": cells, "markers": markers}


def write_meshio_hybrid(out):
    # Two unit hexahedra side by side, a wedge and a pyramid on top of them, a tetrahedron on
    # the pyramid's apex side: every element valid in VTK's node order.
    points = np.array([
        [0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0],
        [0, 0, 1], [1, 0, 1], [2, 0, 1], [0, 1, 1], [1, 1, 1], [2, 1, 1],
        [0.5, 0.0, 1.8], [0.5, 1.0, 1.8], [1.5, 0.5, 1.7], [2.5, 0.5, 1.2]], dtype=float)
    hexahedra = np.array([[0, 1, 4, 3, 6, 7, 10, 9], [1, 2, 5, 4, 7, 8, 11, 10]])
    wedges = np.array([[6, 7, 12, 9, 10, 13]])
    pyramids = np.array([[7, 8, 11, 10, 14]])
    tetra = np.array([[8, 11, 14, 15]])
    blocks = [("hexahedron", hexahedra, VTK_HEXAHEDRON), ("wedge", wedges, VTK_WEDGE),
              ("pyramid", pyramids, VTK_PYRAMID), ("tetra", tetra, VTK_TETRA)]
    mesh = meshio.Mesh(points, [(name, data) for name, data, _ in blocks])
    meshio.write(os.path.join(out, "hybrid_meshio.su2"), mesh, file_format="su2")
    cells = [[code] + row.tolist() for _, data, code in blocks for row in data]
    return {"points": points.tolist(), "cells": cells, "markers": {}}


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for name, expected in (("box_gmsh", write_gmsh_box(out)),
                           ("hybrid_meshio", write_meshio_hybrid(out))):
        with open(os.path.join(out, f"{name}.expected.json"), "w") as f:
            json.dump(expected, f)
    return 0


if __name__ == "__main__":
    sys.exit(main())
