#!/usr/bin/python3
"""getme smooth on OpenFOAM cases (write_fixtures.py's), judged by OpenFOAM's checkMesh, and
compared with the VTK run of the same mesh.

usage: check_smoothing.py GETME FIXTURES

- mixed_ascii smoothed (boundary fixed, and sliding along the patches): checkMesh says
  "Mesh OK." with no failed check ("***"), interior points moved, boundary points not (fixed run);
  the other files are byte for byte the input's.
- The same mesh converted to .vtk by getme and smoothed from there gives bit-identical points.
- --fix-physical xmin with --boundary free keeps exactly the points of patch xmin.
- poly_ascii (6 polyhedra): smoothed, checkMesh OK, every point of a polyhedron unchanged;
  converted to .vtk, the summary counts the polyhedra and a warning says they are left out.
- box_binary_gz: smoothed back to a gzip-compressed binary polyMesh that checkMesh reads.
- mixed.msh converted to a polyMesh (ASCII and binary): checkMesh OK, its physical surfaces
  become patches of the names and sizes gmshToFoam gives them.
Exits 1 with a message on the first failure.
"""
import gzip
import os
import re
import shutil
import struct
import subprocess
import sys

import meshio

GETME, FIXTURES = sys.argv[1], sys.argv[2]
OUT = os.path.join(FIXTURES, "smoothed")
ENV = dict(os.environ, WM_PROJECT_DIR="/usr/share/openfoam")


def fail(message):
    sys.exit(f"check_smoothing.py: {message}")


def run(*command):
    result = subprocess.run(list(command), capture_output=True, text=True, env=ENV)
    if result.returncode != 0:
        fail(f"{' '.join(command)} exited {result.returncode}:\n{result.stdout}\n{result.stderr}")
    return result.stdout + result.stderr


def read_file(directory, name):
    for candidate in (name, name + ".gz"):
        path = os.path.join(directory, candidate)
        if os.path.exists(path):
            with open(path, "rb") as f:
                data = f.read()
            return gzip.decompress(data) if candidate.endswith(".gz") else data
    fail(f"no {name} in {directory}")


def points(case):
    """The points of a case's polyMesh, parsed here (ASCII or binary, scalar=64)."""
    data = read_file(os.path.join(case, "constant", "polyMesh"), "points")
    header = data.find(b"FoamFile")
    header_end = data.index(b"}", header) + 1 if header >= 0 else 0
    binary = re.search(rb"format\s+binary", data[:header_end]) is not None
    match = re.compile(rb"(?:\s|//[^\n]*\n|/\*.*?\*/)*(\d+)\s*\(", re.S).match(data, header_end)
    count, start = int(match.group(1)), match.end()
    if binary:
        values = struct.unpack_from(f"<{3 * count}d", data, start)
        return [tuple(values[3 * i:3 * i + 3]) for i in range(count)]
    rows = re.findall(rb"\(([^()]*)\)", data[start:])[:count]
    return [tuple(float(v) for v in row.split()) for row in rows]


def ascii_faces(case):
    mesh = os.path.join(case, "constant", "polyMesh")
    return [tuple(int(v) for v in f.split()) for f in
            re.findall(rb"\d+\(([\d ]+)\)", read_file(mesh, "faces").split(b"\n(", 1)[1])]


def ascii_labels(case, name):
    data = read_file(os.path.join(case, "constant", "polyMesh"), name)
    return [int(v) for v in data[data.index(b"}", data.index(b"FoamFile")):].split(b"(", 1)[1]
            .split(b")", 1)[0].split()]


def polyhedron_points(case):
    """Points of the cells that are not hexahedra (6 quads), in a hexahedra-only mesh."""
    faces = ascii_faces(case)
    cells = {}
    for face, cell in enumerate(ascii_labels(case, "owner")):
        cells.setdefault(cell, []).append(faces[face])
    for face, cell in enumerate(ascii_labels(case, "neighbour")):
        cells.setdefault(cell, []).append(faces[face])
    return {p for cell_faces in cells.values()
            if len(cell_faces) != 6 or any(len(f) != 4 for f in cell_faces)
            for f in cell_faces for p in f}


def faces_and_patches(case):
    """Boundary patches → their point labels (ASCII faceList polyMeshes)."""
    mesh = os.path.join(case, "constant", "polyMesh")
    faces = ascii_faces(case)
    boundary = read_file(mesh, "boundary").decode()
    patches = {}
    for name, body in re.findall(r"\n\s*(\w+)\s*\{([^}]*)\}", boundary):
        if name == "FoamFile":
            continue
        n = int(re.search(r"nFaces\s+(\d+)", body).group(1))
        s = int(re.search(r"startFace\s+(\d+)", body).group(1))
        patches[name] = {p for f in faces[s:s + n] for p in f}
    return patches


def check_mesh(case):
    shutil.copytree(os.path.join(FIXTURES, "box_ascii", "system"), os.path.join(case, "system"),
                    dirs_exist_ok=True)
    log = run("checkMesh", "-case", case)
    if "Mesh OK." not in log or "***" in log:
        fail(f"checkMesh does not accept {case}:\n{log}")


def smooth(source, name, *flags):
    target = os.path.join(OUT, name)
    shutil.rmtree(target, ignore_errors=True)
    run(GETME, "smooth", source, target, "--format", "openfoam", "--quiet", *flags)
    return target


def same_files(a, b, names):
    for name in names:
        if read_file(os.path.join(a, "constant", "polyMesh"), name) != read_file(
                os.path.join(b, "constant", "polyMesh"), name):
            fail(f"{name} of {b} differs from {a}'s")


os.makedirs(OUT, exist_ok=True)
mixed = os.path.join(FIXTURES, "mixed_ascii")
before = points(mixed)
patches = faces_and_patches(mixed)
on_boundary = set().union(*patches.values())

# Boundary fixed (the default): interior points move, boundary points stay.
fixed_run = smooth(mixed, "mixed_fixed")
check_mesh(fixed_run)
after = points(fixed_run)
same_files(mixed, fixed_run, ["faces", "owner", "neighbour", "boundary"])
moved = [i for i in range(len(before)) if before[i] != after[i]]
if not moved or any(i in on_boundary for i in moved):
    fail(f"mixed_fixed: moved points {moved}; boundary points {sorted(on_boundary)}")

# The VTK run of the same mesh: bit-identical points.
vtk_input = os.path.join(OUT, "mixed.vtk")
run(GETME, "convert", mixed, vtk_input)
vtk_output = os.path.join(OUT, "mixed_smoothed.vtk")
run(GETME, "smooth", vtk_input, vtk_output, "--quiet")
vtk_points = [tuple(p) for p in meshio.read(vtk_output).points.tolist()]
if vtk_points != after:
    differing = [i for i in range(len(after)) if vtk_points[i] != after[i]]
    fail(f"the VTK run differs at points {differing[:10]}")

# Sliding along the patches (their surface groups) keeps checkMesh happy; an OpenFOAM input
# written to a path without extension needs no --format.
slide_run = os.path.join(OUT, "mixed_slide")
shutil.rmtree(slide_run, ignore_errors=True)
run(GETME, "smooth", mixed, slide_run, "--quiet", "--boundary", "slide")
check_mesh(slide_run)

# A patch fixed by name, the rest of the boundary free.
free_run = smooth(mixed, "mixed_fix_xmin", "--boundary", "free", "--fix-physical", "xmin")
check_mesh(free_run)
after = points(free_run)
moved = {i for i in range(len(before)) if before[i] != after[i]}
if moved & patches["xmin"] or not (moved & (on_boundary - patches["xmin"])):
    fail(f"--fix-physical xmin: moved {sorted(moved)}, xmin {sorted(patches['xmin'])}")

# Polyhedra keep every point.
poly = os.path.join(FIXTURES, "poly_ascii")
poly_run = smooth(poly, "poly", "--boundary", "free")
check_mesh(poly_run)
before, after = points(poly), points(poly_run)
held = polyhedron_points(poly)
moved = {i for i in range(len(before)) if before[i] != after[i]}
if not held or not moved or moved & held:
    fail(f"poly: moved {sorted(moved)}, polyhedron points {sorted(held)}")
same_files(poly, poly_run, ["faces", "owner", "neighbour", "boundary", "cellZones"])

# Converted to another format, the polyhedra cannot follow: the read summary counts them and a
# warning names what is left out.
log = run(GETME, "convert", poly, os.path.join(OUT, "poly.vtk"))
for expected in ("6 polyhedra kept fixed with their points",
                 "6 polyhedral cells of the OpenFOAM mesh are not written to VTK legacy"):
    if expected not in log:
        fail(f"getme convert poly_ascii poly.vtk does not say '{expected}':\n{log}")

# Binary, gzip compressed.
gz_run = smooth(os.path.join(FIXTURES, "box_binary_gz"), "box_gz")
if not os.path.exists(os.path.join(gz_run, "constant", "polyMesh", "points.gz")):
    fail("box_gz: no points.gz written")
check_mesh(gz_run)
if points(gz_run) == points(os.path.join(FIXTURES, "box_binary_gz")):
    fail("box_gz: smoothing the graded box moved nothing")
# Another format to a polyMesh: the hybrid .msh with its physical surfaces → patches of the same
# names and sizes as gmshToFoam's, accepted by checkMesh, in both encodings.
expected_patches = {}
with open(os.path.join(FIXTURES, "mixed_ascii.checkMesh")) as f:
    for line in f:
        words = line.split()
        if words[0] == "patch":
            expected_patches[words[1]] = int(words[2])
for encoding in ("--ascii", "--binary"):
    converted = os.path.join(OUT, "from_msh" + encoding.replace("-", "_"))
    shutil.rmtree(converted, ignore_errors=True)
    run(GETME, "convert", os.path.join(FIXTURES, "mixed.msh"), converted, "--format", "openfoam",
        encoding)
    check_mesh(converted)
    log = run("checkMesh", "-case", converted)
    found = {m.group(1): int(m.group(2))
             for m in re.finditer(r"^ +(\S+) +(\d+) +\d+ +ok", log, re.M)}
    if found != expected_patches:
        fail(f"from_msh {encoding}: patches {found}, gmshToFoam's {expected_patches}")
print("check_smoothing.py: all checks passed")
