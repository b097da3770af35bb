#!/usr/bin/python3
"""Writes tests/data/hybrid-example.vtk as Gmsh files with boundary surfaces and named physical
groups, with gmsh's own writer (python3-gmsh), for the CLI format tests:

  OUT_DIR/hybrid-groups.msh      MSH 4.1 binary
  OUT_DIR/hybrid-groups-22.msh   MSH 2.2 ASCII

Volume elements (all four types) go to one discrete volume entity, physical "domain" (tag 1).
Boundary faces (faces of exactly one volume element) become triangles and quads: those in the
plane x = x_min form physical "inlet" (tag 11), the rest "walls" (tag 12). The vtk file is read
with meshio (whose wedge order is Gmsh's prism order)."""

import sys

import gmsh
import meshio
import numpy as np

# Faces per element type in Gmsh node order (the orientation does not matter here).
FACES = {
    "tetra": [(0, 1, 2), (0, 1, 3), (1, 2, 3), (0, 2, 3)],
    "hexahedron": [(0, 1, 2, 3), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6),
                   (3, 0, 4, 7)],
    "wedge": [(0, 1, 2), (3, 4, 5), (0, 1, 4, 3), (1, 2, 5, 4), (2, 0, 3, 5)],
    "pyramid": [(0, 1, 2, 3), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)],
}
GMSH_TYPE = {"tetra": 4, "hexahedron": 5, "wedge": 6, "pyramid": 7}


def main(source, out_dir):
    mesh = meshio.read(source)
    points = mesh.points
    faces = {}
    for block in mesh.cells:
        for element in block.data:
            for face in FACES[block.type]:
                nodes = tuple(int(element[k]) for k in face)
                key = tuple(sorted(nodes))
                faces[key] = None if key in faces else nodes
    boundary = [nodes for nodes in faces.values() if nodes is not None]
    x_min = points[:, 0].min()
    inlet = [f for f in boundary if all(points[n, 0] == x_min for n in f)]
    walls = [f for f in boundary if not all(points[n, 0] == x_min for n in f)]
    assert inlet and walls, "expected faces on x = x_min and elsewhere"

    gmsh.initialize(["-noenv"], readConfigFiles=False)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add("hybrid-groups")
    volume = gmsh.model.addDiscreteEntity(3)
    surface_inlet = gmsh.model.addDiscreteEntity(2)
    surface_walls = gmsh.model.addDiscreteEntity(2)
    gmsh.model.mesh.addNodes(3, volume, list(range(1, len(points) + 1)),
                             points.reshape(-1).tolist())
    next_tag = 1
    for block in mesh.cells:
        data = block.data + 1
        tags = list(range(next_tag, next_tag + len(data)))
        next_tag += len(data)
        gmsh.model.mesh.addElementsByType(volume, GMSH_TYPE[block.type], tags,
                                          data.reshape(-1).tolist())
    for entity, faces_of in ((surface_inlet, inlet), (surface_walls, walls)):
        for size, gmsh_type in ((3, 2), (4, 3)):
            chosen = [f for f in faces_of if len(f) == size]
            if not chosen:
                continue
            tags = list(range(next_tag, next_tag + len(chosen)))
            next_tag += len(chosen)
            gmsh.model.mesh.addElementsByType(entity, gmsh_type, tags,
                                              (np.array(chosen) + 1).reshape(-1).tolist())
    for dim, entity, tag, name in ((3, volume, 1, "domain"), (2, surface_inlet, 11, "inlet"),
                                   (2, surface_walls, 12, "walls")):
        gmsh.model.addPhysicalGroup(dim, [entity], tag)
        gmsh.model.setPhysicalName(dim, tag, name)

    for name, version, binary in (("hybrid-groups.msh", 4.1, 1),
                                  ("hybrid-groups-22.msh", 2.2, 0)):
        gmsh.option.setNumber("Mesh.MshFileVersion", version)
        gmsh.option.setNumber("Mesh.Binary", binary)
        gmsh.write(f"{out_dir}/{name}")
    gmsh.finalize()
    print(f"{len(points)} nodes, {sum(len(b.data) for b in mesh.cells)} volume elements, "
          f"{len(inlet)} inlet and {len(walls)} wall faces")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
