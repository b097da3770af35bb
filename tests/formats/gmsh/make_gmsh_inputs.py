#!/usr/bin/python3
"""Writes the Gmsh reader's test inputs with other tools' own writers (ctest fixture).

usage: make_gmsh_inputs.py OUTPUT_DIR

- hybrid_{22,41}_{ascii,binary}.msh: written by Gmsh (Python API) from one model with all four
  volume types in two volumes, triangles and quads in two surfaces, lines, a point, named physical
  groups (one spanning two surfaces), a curve in no group, sparse shuffled node and element tags
  and coordinates that need all 17 digits.
- multi_41_{ascii,binary}.msh: Gmsh 4.1 with one surface in two physical groups.
- regular_{22,41}_{ascii,binary}.msh: one regular tet, hex, pyramid and prism (unit edges, each
  oriented as docs/node-orders.md orders the paper's nodes, which Gmsh's order is claimed to be).
- views_{22,41}_{ascii,binary}.msh: the hybrid mesh and Gmsh views: "fixed" on some nodes at two
  time steps, a 3-component "velocity" on all elements.
- meshio_{22,41}_{ascii,binary}.msh: the hybrid mesh written by meshio.
Each X.msh gets X.expected: what Gmsh (or meshio) itself reads back from X.msh, in a plain text
form the C++ test compares with (floats as float.hex()):
  node TAG X Y Z                      | point X Y Z            (meshio: file order)
  element TAG TYPE DIM ENTITY NODES…  | cell TYPE PHYS GEOM INDICES…
  physical DIM TAG NAME / member DIM PHYSICAL_TAG ENTITY_TAG
  data NODE|ELEMENT NAME STEP TIME COMPONENTS TAG VALUES…
  fixed X Y Z VALUE                   (meshio: the "fixed" value given to meshio at X Y Z)
"""

import math
import os
import random
import sys

import gmsh
import meshio
import numpy as np

OUT = sys.argv[1]
VARIANTS = [(2.2, 0, "22_ascii"), (2.2, 1, "22_binary"), (4.1, 0, "41_ascii"), (4.1, 1, "41_binary")]


def orient(points, cell, volume):
    """Swaps two nodes if the first node tetrahedron is negatively oriented."""
    a, b, c, d = (np.array(points[i]) for i in cell[:3] + [cell[volume]])
    return np.dot(np.cross(b - a, c - a), d - a) > 0


def hybrid_model():
    """Points and cells (gmsh order, 0-based point indices) of a small hybrid mesh."""
    rng = random.Random(7)
    index = {}
    points = []

    def node(x, y, z):
        key = (x, y, z)
        if key not in index:
            index[key] = len(points)
            # Perturbations that make every coordinate a full 17-digit double.
            points.append([x * 0.1 + rng.uniform(-1e-3, 1e-3) if 0 < x < 3 else x * 0.1,
                           y * 0.1 + rng.uniform(-1e-3, 1e-3) if 0 < y < 2 else y * 0.1,
                           z / 3.0])
        return index[key]

    cells = {"hex": [], "prism": [], "pyramid": [], "tet": [], "quad": [], "tri": [],
             "line": [], "line_free": [], "point": []}
    for i in range(2):
        for j in range(2):
            b = [node(i, j, 0), node(i + 1, j, 0), node(i + 1, j + 1, 0), node(i, j + 1, 0)]
            t = [node(i, j, 1), node(i + 1, j, 1), node(i + 1, j + 1, 1), node(i, j + 1, 1)]
            cells["hex"].append(b + t)
            cells["quad"].append(b)
            apex = len(points)
            points.append([(i + 0.5) * 0.1, (j + 0.5) * 0.1, 1.5 / 3.0])
            cells["pyramid"].append(t + [apex])
    for j in range(2):
        for tri in ([(2, j), (3, j), (3, j + 1)], [(2, j), (3, j + 1), (2, j + 1)]):
            bottom = [node(x, y, 0) for x, y in tri]
            top = [node(x, y, 1) for x, y in tri]
            cells["prism"].append(bottom + top)
            cells["tri"].append(bottom)
    apexes = [p[4] for p in cells["pyramid"]]
    # Tets between neighbouring pyramids (0,0)-(1,0) and (0,1)-(1,1), over their shared edge.
    for a, b, e0, e1 in ((0, 2, node(1, 0, 1), node(1, 1, 1)), (1, 3, node(1, 1, 1), node(1, 2, 1))):
        tet = [e0, e1, apexes[a], apexes[b]]
        if not orient(points, tet, 3):
            tet[0], tet[1] = tet[1], tet[0]
        cells["tet"].append(tet)
    cells["line"] = [[node(0, 0, 0), node(1, 0, 0)], [node(1, 0, 0), node(2, 0, 0)],
                     [node(2, 0, 0), node(3, 0, 0)]]
    cells["line_free"] = [[node(0, 2, 1), node(1, 2, 1)]]
    cells["point"] = [[node(0, 0, 0)]]
    return points, cells


POINTS, CELLS = hybrid_model()
TYPE = {"point": 15, "line": 1, "line_free": 1, "tri": 2, "quad": 3, "tet": 4, "hex": 5,
        "prism": 6, "pyramid": 7}


def build_gmsh_model(multi=False):
    """Adds the hybrid mesh to a fresh Gmsh model with sparse, shuffled node/element tags."""
    gmsh.model.add("hybrid")
    solid = gmsh.model.addDiscreteEntity(3, 1)
    wedges = gmsh.model.addDiscreteEntity(3, 7)
    quads = gmsh.model.addDiscreteEntity(2, 3)
    tris = gmsh.model.addDiscreteEntity(2, 4)
    edge = gmsh.model.addDiscreteEntity(1, 5)
    free = gmsh.model.addDiscreteEntity(1, 6)
    corner = gmsh.model.addDiscreteEntity(0, 9)
    rng = random.Random(11)
    order = list(range(len(POINTS)))
    rng.shuffle(order)
    tags = [0] * len(POINTS)
    for rank, i in enumerate(order):
        tags[i] = 1000 + 7 * rank
    shuffled = sorted(range(len(POINTS)), key=lambda i: order.index(i))
    gmsh.model.mesh.addNodes(3, solid, [tags[i] for i in shuffled],
                             [c for i in shuffled for c in POINTS[i]])
    next_tag = [500]

    def add(entity, name):
        element_tags = []
        for _ in CELLS[name]:
            next_tag[0] += 3
            element_tags.append(next_tag[0])
        nodes = [tags[i] for cell in CELLS[name] for i in cell]
        gmsh.model.mesh.addElementsByType(entity, TYPE[name], element_tags, nodes)

    add(solid, "hex")
    add(solid, "pyramid")
    add(solid, "tet")
    add(wedges, "prism")
    add(quads, "quad")
    add(tris, "tri")
    add(edge, "line")
    add(free, "line_free")
    add(corner, "point")
    gmsh.model.setPhysicalName(3, gmsh.model.addPhysicalGroup(3, [solid], 31), "solid")
    gmsh.model.setPhysicalName(3, gmsh.model.addPhysicalGroup(3, [wedges], 32), "wedges")
    gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, [quads, tris], 21), "bottom")
    if multi:
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, [tris], 22), "bottom tris")
    gmsh.model.setPhysicalName(1, gmsh.model.addPhysicalGroup(1, [edge], 11), "edge")
    gmsh.model.setPhysicalName(0, gmsh.model.addPhysicalGroup(0, [corner], 1), "corner")
    return tags


def write_variants(stem, variants):
    for version, binary, suffix in variants:
        gmsh.option.setNumber("Mesh.MshFileVersion", version)
        gmsh.option.setNumber("Mesh.Binary", binary)
        # 4.1: also the curve in no physical group. 2.2: Gmsh's SaveAll writes every physical
        # tag as 0, so only the elements of physical groups are written.
        gmsh.option.setNumber("Mesh.SaveAll", 1 if version == 4.1 else 0)
        gmsh.write(os.path.join(OUT, f"{stem}_{suffix}.msh"))


def dump_gmsh_reading(path):
    """What Gmsh reads back from `path`, as the .expected sidecar."""
    gmsh.clear()
    gmsh.open(path)
    lines = []
    node_tags, coords, _ = gmsh.model.mesh.getNodes()
    for k, tag in enumerate(node_tags):
        lines.append("node %d %s %s %s" % (tag, *(float(c).hex() for c in coords[3 * k:3 * k + 3])))
    for dim, entity in gmsh.model.getEntities():
        types, element_tags, nodes = gmsh.model.mesh.getElements(dim, entity)
        for t, etags, enodes in zip(types, element_tags, nodes):
            per = len(enodes) // len(etags)
            for k, tag in enumerate(etags):
                lines.append("element %d %d %d %d %s" % (tag, t, dim, entity,
                                                         " ".join(str(n) for n in enodes[per * k:per * (k + 1)])))
    for dim, tag in gmsh.model.getPhysicalGroups():
        lines.append("physical %d %d %s" % (dim, tag, gmsh.model.getPhysicalName(dim, tag)))
        for entity in gmsh.model.getEntitiesForPhysicalGroup(dim, tag):
            lines.append("member %d %d %d" % (dim, tag, entity))
    for view in gmsh.view.getTags():
        name = gmsh.option.getString(f"View[{gmsh.view.getIndex(view)}].Name")
        steps = int(gmsh.option.getNumber(f"View[{gmsh.view.getIndex(view)}].NbTimeStep"))
        for step in range(steps):
            kind, tags, data, time, components = gmsh.view.getModelData(view, step)
            for tag, values in zip(tags, data):
                lines.append("data %s %s %d %s %d %d %s" % (
                    "NODE" if kind == "NodeData" else "ELEMENT", name, step, float(time).hex(),
                    components, tag, " ".join(float(v).hex() for v in values)))
        gmsh.view.remove(view)
    with open(path[:-4] + ".expected", "w") as out:
        out.write("\n".join(lines) + "\n")


def regular_elements():
    s3 = math.sqrt(3.0)
    return {
        4: [(0, 0, 0), (1, 0, 0), (0.5, s3 / 2, 0), (0.5, s3 / 6, math.sqrt(2.0 / 3.0))],
        5: [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)],
        7: [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0.5, 0.5, math.sqrt(2.0) / 2)],
        # Paper order (docs/node-orders.md): bottom triangle counter-clockwise seen from the top,
        # 3 above 0.
        6: [(0, 0, 0), (1, 0, 0), (0.5, s3 / 2, 0), (0, 0, 1), (1, 0, 1), (0.5, s3 / 2, 1)],
    }


def main():
    os.makedirs(OUT, exist_ok=True)
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)

    build_gmsh_model()
    write_variants("hybrid", VARIANTS)
    # Views: "fixed" listed on three nodes at two time steps; "velocity" on every element.
    node_tags, _, _ = gmsh.model.mesh.getNodes()
    fixed = gmsh.view.add("fixed")
    picked = [int(t) for t in node_tags[:3]]
    gmsh.view.addModelData(fixed, 0, "hybrid", "NodeData", picked, [[1.0], [1.0], [0.0]], time=0.0)
    gmsh.view.addModelData(fixed, 1, "hybrid", "NodeData", picked, [[0.5], [2.0], [1.0]], time=0.25)
    velocity = gmsh.view.add("velocity")
    element_tags = [int(t) for dim, entity in gmsh.model.getEntities() if (dim, entity) != (1, 6)
                    for tags in gmsh.model.mesh.getElements(dim, entity)[1] for t in tags]
    gmsh.view.addModelData(velocity, 0, "hybrid", "ElementData", element_tags,
                           [[t * 0.1, -t / 3.0, 1e-300] for t in element_tags], numComponents=3)
    write_variants("views_mesh", VARIANTS)
    gmsh.option.setNumber("PostProcessing.SaveMesh", 0)
    for version, binary, suffix in VARIANTS:
        gmsh.option.setNumber("Mesh.MshFileVersion", version)
        gmsh.option.setNumber("Mesh.Binary", binary)
        path = os.path.join(OUT, f"views_{suffix}.msh")
        os.replace(os.path.join(OUT, f"views_mesh_{suffix}.msh"), path)
        for view in (fixed, velocity):
            gmsh.view.write(view, path, append=True)
    gmsh.model.remove()

    gmsh.clear()
    build_gmsh_model(multi=True)
    write_variants("multi", VARIANTS[2:])
    gmsh.model.remove()

    gmsh.clear()
    gmsh.model.add("regular")
    tag = 1
    for k, (gmsh_type, points) in enumerate(regular_elements().items()):
        entity = gmsh.model.addDiscreteEntity(3, k + 1)
        node_tags = list(range(tag, tag + len(points)))
        gmsh.model.mesh.addNodes(3, entity, node_tags,
                                 [c + (3.0 * k if axis == 0 else 0.0)
                                  for p in points for axis, c in enumerate(p)])
        gmsh.model.mesh.addElementsByType(entity, gmsh_type, [k + 1], node_tags)
        tag += len(points)
    write_variants("regular", VARIANTS)

    for stem, variants in (("hybrid", VARIANTS), ("views", VARIANTS), ("multi", VARIANTS[2:]),
                           ("regular", VARIANTS)):
        for _, _, suffix in variants:
            dump_gmsh_reading(os.path.join(OUT, f"{stem}_{suffix}.msh"))
    gmsh.finalize()

    write_meshio()


def write_meshio():
    names = [("tetra", "tet", 3), ("hexahedron", "hex", 3), ("pyramid", "pyramid", 3),
             ("wedge", "prism", 3), ("triangle", "tri", 2), ("quad", "quad", 2),
             ("line", "line", 1), ("vertex", "point", 0)]
    cells = [(meshio_name, np.array(CELLS[ours])) for meshio_name, ours, _ in names]
    # meshio's 4.1 writer needs one geometrical tag per cell block and dimension.
    geometrical = [np.full(len(CELLS[ours]), k + 1) for k, (_, ours, _) in enumerate(names)]
    physical = [np.full(len(CELLS[ours]), 100 + dim) for _, ours, dim in names]
    # Its reader also wants every cell block's entity in $Entities, which it builds from the
    # nodes' entities: classify one node of each block on the block's entity.
    dim_tags = np.array([[3, 1]] * len(POINTS))
    taken = set()
    for k, (_, ours, dim) in sorted(enumerate(names), key=lambda item: item[1][2]):
        free = next(i for cell in CELLS[ours] for i in cell if i not in taken)
        taken.add(free)
        dim_tags[free] = [dim, k + 1]
    mesh = meshio.Mesh(
        np.array(POINTS), cells,
        point_data={"gmsh:dim_tags": dim_tags,
                    "fixed": np.arange(len(POINTS), dtype=float) % 2},
        cell_data={"gmsh:physical": physical, "gmsh:geometrical": geometrical})
    code = {"vertex": 15, "line": 1, "triangle": 2, "quad": 3, "tetra": 4, "hexahedron": 5,
            "wedge": 6, "pyramid": 7}
    for fmt, version in (("gmsh22", "22"), ("gmsh", "41")):
        for binary in (False, True):
            path = os.path.join(OUT, f"meshio_{version}_{'binary' if binary else 'ascii'}.msh")
            mesh.write(path, file_format=fmt, binary=binary)
            back = meshio.read(path)
            lines = ["point %s %s %s" % tuple(float(c).hex() for c in p) for p in back.points]
            for b, block in enumerate(back.cells):
                phys = back.cell_data.get("gmsh:physical", [None] * len(back.cells))[b]
                geo = back.cell_data.get("gmsh:geometrical", [None] * len(back.cells))[b]
                for k, cell in enumerate(block.data):
                    lines.append("cell %d %d %d %s" % (
                        code[block.type], -1 if phys is None else phys[k],
                        -1 if geo is None else geo[k], " ".join(str(i) for i in cell)))
            # "fixed" as given to meshio, by position: meshio's 4.1 reader assigns $NodeData
            # values in file order rather than by node tag, so its reading is no reference.
            for p, v in zip(mesh.points, mesh.point_data["fixed"]):
                lines.append("fixed %s %s %s %s" % (*(float(c).hex() for c in p), float(v).hex()))
            with open(path[:-4] + ".expected", "w") as out:
                out.write("\n".join(lines) + "\n")


main()
