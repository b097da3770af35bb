#!/usr/bin/python3
"""Writes OpenFOAM polyMesh cases with OpenFOAM's own utilities (Debian's openfoam package) for
the OpenFOAM reader/writer tests, and what OpenFOAM says about them:

- box_ascii, box_binary, box_binary_gz: blockMesh, a graded 4x3x3 hex box with six patches;
  ASCII, binary (faceCompactList faces), binary with writeCompression on (NAME.gz files).
- mixed_ascii, mixed_binary: gmshToFoam of a hybrid MSH 2.2 mesh this script builds (hexahedra,
  prisms, pyramids, tetrahedra, interior nodes perturbed), ASCII, and foamFormatConvert'ed to
  binary; mixed.vtk is foamToVTK's legacy VTK of the same mesh.
- poly_ascii: blockMesh 2x2x2 and refineHexMesh of one cell, which turns its neighbours into
  polyhedra (their faces split in four).

For each case NAME, NAME.checkMesh holds checkMesh's cell-shape counts ("hexahedra 24" lines)
and the patch sizes ("patch xmin 9"), parsed from its output. Fails (exit 1) when an OpenFOAM
utility is missing or fails: the tests need them and must not pass without them.
"""
import gzip
import os
import random
import re
import shutil
import subprocess
import sys

OUT = sys.argv[1]
ENV = dict(os.environ, WM_PROJECT_DIR="/usr/share/openfoam")

CONTROL = """FoamFile {{ version 2.0; format ascii; class dictionary; object controlDict; }}
application blockMesh; startFrom startTime; startTime 0; stopAt endTime; endTime 1; deltaT 1;
writeControl timeStep; writeInterval 1; writeFormat {fmt}; writePrecision 17;
writeCompression {comp}; timeFormat general; timePrecision 6; runTimeModifiable false;
"""
SCHEMES = """FoamFile { version 2.0; format ascii; class dictionary; object fvSchemes; }
ddtSchemes { default steadyState; } gradSchemes { default Gauss linear; }
divSchemes { default none; } laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; } snGradSchemes { default corrected; }
"""
SOLUTION = "FoamFile { version 2.0; format ascii; class dictionary; object fvSolution; }\n"


def run(case, *command):
    if shutil.which(command[0]) is None:
        sys.exit(f"{command[0]} not found: install Debian's openfoam package (scripts/packages.txt)")
    result = subprocess.run(list(command) + ["-case", case], env=ENV, capture_output=True,
                            text=True)
    if result.returncode != 0:
        sys.exit(f"{' '.join(command)} failed in {case}:\n{result.stdout[-3000:]}\n{result.stderr}")
    return result.stdout


def make_case(name, fmt="ascii", comp="off"):
    case = os.path.join(OUT, name)
    shutil.rmtree(case, ignore_errors=True)
    os.makedirs(os.path.join(case, "system"))
    write_system(case, fmt, comp)
    return case


def write_system(case, fmt="ascii", comp="off"):
    os.makedirs(os.path.join(case, "system"), exist_ok=True)
    for file, text in (("controlDict", CONTROL.format(fmt=fmt, comp=comp)),
                       ("fvSchemes", SCHEMES), ("fvSolution", SOLUTION)):
        with open(os.path.join(case, "system", file), "w") as f:
            f.write(text)


def block_mesh_dict(cells, grading):
    return f"""FoamFile {{ version 2.0; format ascii; class dictionary; object blockMeshDict; }}
scale 1;
vertices ( (0 0 0) (2 0 0) (2 1.5 0) (0 1.5 0) (0 0 1) (2 0 1) (2 1.5 1) (0 1.5 1) );
blocks ( hex (0 1 2 3 4 5 6 7) ({cells}) simpleGrading ({grading}) );
boundary (
  xmin {{ type patch; faces ((0 4 7 3)); }}
  xmax {{ type patch; faces ((1 2 6 5)); }}
  ymin {{ type wall; faces ((0 1 5 4)); }}
  ymax {{ type wall; faces ((3 7 6 2)); }}
  zmin {{ type patch; faces ((0 3 2 1)); }}
  zmax {{ type patch; faces ((4 5 6 7)); }}
);
"""


def check_mesh(case, name):
    """checkMesh's cell-shape counts and patch sizes, to NAME.checkMesh."""
    log = run(case, "checkMesh")
    lines = []
    for shape in ("hexahedra", "prisms", "wedges", "pyramids", "tet wedges", "tetrahedra",
                  "polyhedra"):
        match = re.search(rf"^\s*{shape}:\s+(\d+)", log, re.M)
        if match is None:
            sys.exit(f"checkMesh of {case}: no '{shape}' count in\n{log}")
        lines.append(f"{shape.replace(' ', '_')} {match.group(1)}")
    for match in re.finditer(r"^ +(\S+) +(\d+) +(\d+) +ok", log, re.M):
        lines.append(f"patch {match.group(1)} {match.group(2)}")
    if "Mesh OK." not in log:
        sys.exit(f"checkMesh of {case} does not say 'Mesh OK.':\n{log}")
    with open(os.path.join(OUT, name + ".checkMesh"), "w") as f:
        f.write("\n".join(lines) + "\n")


def boxes():
    for name, fmt in (("box_ascii", "ascii"), ("box_binary", "binary")):
        case = make_case(name, fmt)
        with open(os.path.join(case, "system", "blockMeshDict"), "w") as f:
            f.write(block_mesh_dict("4 3 3", "2 1 0.5"))
        run(case, "blockMesh")
        check_mesh(case, name)
    # OpenFOAM v1912 writes the polyMesh uncompressed whatever writeCompression says (tried:
    # blockMesh and foamFormatConvert -constant with "on" and "compressed"), but reads NAME.gz
    # where NAME is missing: gzip the binary box's files here and let checkMesh read them.
    compressed = os.path.join(OUT, "box_binary_gz")
    shutil.rmtree(compressed, ignore_errors=True)
    shutil.copytree(os.path.join(OUT, "box_binary"), compressed)
    mesh = os.path.join(compressed, "constant", "polyMesh")
    for file in ("points", "faces", "owner", "neighbour", "boundary"):
        with open(os.path.join(mesh, file), "rb") as f:
            data = f.read()
        with gzip.open(os.path.join(mesh, file + ".gz"), "wb") as f:
            f.write(data)
        os.remove(os.path.join(mesh, file))
    check_mesh(compressed, "box_binary_gz")


# --- the hybrid mesh -------------------------------------------------------------------------

def det(a, b, c):
    return (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
            a[2] * (b[0] * c[1] - b[1] * c[0]))


def sub(p, q):
    return [p[i] - q[i] for i in range(3)]


def hybrid_mesh():
    """A 3x3x2 block of unit cubes: column i = 0 split into prism pairs, the others hexahedra,
    except two cubes split into 6 pyramids around a centre node, two of which (those on the
    outer boundary) are split further into 2 tetrahedra each. Gmsh node order throughout."""
    nx, ny, nz = 3, 3, 2
    index = {}
    points = []

    def point(i, j, k):
        return index[(i, j, k)]

    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                index[(i, j, k)] = len(points)
                points.append([float(i), float(j), float(k)])
    rng = random.Random(17)
    for key, p in index.items():
        if 0 < key[0] < nx and 0 < key[1] < ny and 0 < key[2] < nz:
            points[p] = [c + rng.uniform(-0.2, 0.2) for c in points[p]]
    elements = []  # (gmsh type, nodes)
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                c = [point(i, j, k), point(i + 1, j, k), point(i + 1, j + 1, k),
                     point(i, j + 1, k), point(i, j, k + 1), point(i + 1, j, k + 1),
                     point(i + 1, j + 1, k + 1), point(i, j + 1, k + 1)]
                if i == 0:
                    elements.append((6, [c[0], c[1], c[2], c[4], c[5], c[6]]))
                    elements.append((6, [c[0], c[2], c[3], c[4], c[6], c[7]]))
                elif (i, j, k) in ((1, 1, 0), (2, 1, 1)):
                    centre = len(points)
                    points.append([i + 0.5, j + 0.5, k + 0.5])
                    # The six faces of the cube; oriented below (a pyramid's base must be
                    # counter-clockwise seen from its apex).
                    faces = [(c[0], c[3], c[2], c[1]), (c[4], c[5], c[6], c[7]),
                             (c[0], c[1], c[5], c[4]), (c[2], c[3], c[7], c[6]),
                             (c[1], c[2], c[6], c[5]), (c[0], c[4], c[7], c[3])]
                    for f, face in enumerate(faces):
                        outer = (i, j, k) == (2, 1, 1) and f in (1, 4)  # z = 2 and x = 3
                        if outer:
                            elements.append((4, [face[0], face[1], face[2], centre]))
                            elements.append((4, [face[0], face[2], face[3], centre]))
                        else:
                            elements.append((7, list(face) + [centre]))
                else:
                    elements.append((5, c))
    # Every element positive in the paper's / Gmsh's convention (docs/node-orders.md): the
    # pyramids and tetrahedra built around a centre are turned round where they are not.
    spans = {4: (1, 2, 3), 5: (1, 3, 4), 6: (1, 2, 3), 7: (1, 3, 4)}
    for kind, nodes in elements:
        p = [points[n] for n in nodes]
        if kind in (4, 7) and det(*(sub(p[s], p[0]) for s in spans[kind])) < 0:
            other = 3 if kind == 7 else 2  # base (0, 1, 2, 3) → (0, 3, 2, 1); tet 1 ↔ 2
            nodes[1], nodes[other] = nodes[other], nodes[1]
            p = [points[n] for n in nodes]
        assert det(*(sub(p[s], p[0]) for s in spans[kind])) > 0, (kind, nodes)
    return points, elements


def boundary_faces(elements, points):
    local = {4: [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)],
             5: [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (2, 3, 7, 6), (1, 2, 6, 5),
                 (0, 4, 7, 3)],
             6: [(0, 2, 1), (3, 4, 5), (0, 1, 4, 3), (1, 2, 5, 4), (0, 3, 5, 2)],
             7: [(0, 3, 2, 1), (0, 1, 4), (1, 2, 4), (2, 3, 4), (3, 0, 4)]}
    seen = {}
    for kind, nodes in elements:
        for face in local[kind]:
            key = frozenset(nodes[n] for n in face)
            seen.setdefault(key, []).append([nodes[n] for n in face])
    faces = []
    for key, found in seen.items():
        if len(found) == 1:
            face = found[0]
            coords = [points[n] for n in face]
            for axis, name in ((0, "x"), (1, "y"), (2, "z")):
                values = {round(p[axis], 9) for p in coords}
                if len(values) == 1:
                    side = f"{name}{'min' if values.pop() == 0 else 'max'}"
            faces.append((side, face))
    return faces


def write_msh(path, points, elements, faces):
    sides = ["xmin", "xmax", "ymin", "ymax", "zmin", "zmax"]
    lines = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$PhysicalNames", "7"]
    lines += [f'2 {t + 1} "{side}"' for t, side in enumerate(sides)] + ['3 100 "fluid"']
    lines += ["$EndPhysicalNames", "$Nodes", str(len(points))]
    lines += [f"{n + 1} {p[0]!r} {p[1]!r} {p[2]!r}" for n, p in enumerate(points)]
    lines += ["$EndNodes", "$Elements", str(len(faces) + len(elements))]
    number = 0
    for side, face in faces:
        number += 1
        tag = sides.index(side) + 1
        kind = 2 if len(face) == 3 else 3
        lines.append(f"{number} {kind} 2 {tag} {tag} " + " ".join(str(n + 1) for n in face))
    for kind, nodes in elements:
        number += 1
        lines.append(f"{number} {kind} 2 100 1 " + " ".join(str(n + 1) for n in nodes))
    lines.append("$EndElements")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def mixed():
    points, elements = hybrid_mesh()
    msh = os.path.join(OUT, "mixed.msh")
    write_msh(msh, points, elements, boundary_faces(elements, points))
    case = make_case("mixed_ascii")
    run(case, "gmshToFoam", msh)
    check_mesh(case, "mixed_ascii")
    binary = os.path.join(OUT, "mixed_binary")
    shutil.rmtree(binary, ignore_errors=True)
    shutil.copytree(case, binary)
    write_system(binary, "binary")
    run(binary, "foamFormatConvert", "-constant")
    check_mesh(binary, "mixed_binary")
    run(case, "foamToVTK", "-legacy", "-ascii", "-constant", "-no-boundary", "-no-point-data")
    vtk_dir = os.path.join(case, "VTK")
    written = [f for f in os.listdir(vtk_dir) if f.endswith(".vtk")]
    if len(written) != 1:
        sys.exit(f"foamToVTK wrote {written} in {vtk_dir}; expected one .vtk file")
    shutil.copyfile(os.path.join(vtk_dir, written[0]), os.path.join(OUT, "mixed.vtk"))
    shutil.rmtree(vtk_dir)


def polyhedra():
    case = make_case("poly_ascii")
    with open(os.path.join(case, "system", "blockMeshDict"), "w") as f:
        f.write(block_mesh_dict("2 2 2", "1 1 1"))
    run(case, "blockMesh")
    with open(os.path.join(case, "system", "topoSetDict"), "w") as f:
        f.write("""FoamFile { version 2.0; format ascii; class dictionary; object topoSetDict; }
actions ( { name c0; type cellSet; action new; source labelToCell; value (0); } );
""")
    run(case, "topoSet")
    run(case, "refineHexMesh", "c0", "-overwrite")
    check_mesh(case, "poly_ascii")


os.makedirs(OUT, exist_ok=True)
boxes()
mixed()
polyhedra()
