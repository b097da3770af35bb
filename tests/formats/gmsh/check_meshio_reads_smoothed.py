#!/usr/bin/python3
"""meshio reads what `getme smooth` writes as MSH 2.2 and 4.1, ASCII and binary (issue 17: meshio
could not read the 2.2 files, "Incompatible cell data … has length 2"), and so does `getme
convert` of such a file; Gmsh still shows the quality arrays as views; getme reads the 2.2 views
back with the values written.

The input is the hybrid mesh make_gmsh_inputs.py writes with Gmsh as MSH 2.2 (hexahedra, pyramids,
tetrahedra, prisms, and quads, triangles, lines and a vertex around them), so the $Elements hold
several runs of element types, the case meshio's 2.2 reader gets wrong for $ElementData.

usage: check_meshio_reads_smoothed.py GETME INPUTS_DIR WORK_DIR
"""

import os
import subprocess
import sys

import gmsh
import meshio
import numpy as np

QUALITY = ("mean_ratio", "warpage", "valid")


def run(*command):
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)


def element_node_data(path, name):
    """The values of the ASCII $ElementNodeData view `name`: element tag → its nodes' values."""
    values = {}
    with open(path) as f:
        lines = iter(f.read().splitlines())
    for line in lines:
        if line != "$ElementNodeData":
            continue
        string_tags = [next(lines).strip('"') for _ in range(int(next(lines)))]
        for _ in range(int(next(lines))):
            next(lines)
        integer_tags = [int(next(lines)) for _ in range(int(next(lines)))]
        entries = [next(lines).split() for _ in range(integer_tags[2])]
        if string_tags[0] == name:
            values = {int(e[0]): [float(v) for v in e[2:]] for e in entries}
    return values


def check_gmsh_views(path, elements):
    """Gmsh opens the file and has each quality array as a view with a value per element."""
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        gmsh.open(path)
        found = {}
        for view in gmsh.view.getTags():
            index = gmsh.view.getIndex(view)
            _, tags, _, _, _ = gmsh.view.getModelData(view, 0)
            found[gmsh.option.getString(f"View[{index}].Name")] = len(tags)
    finally:
        gmsh.finalize()
    return [f"Gmsh view {name}: {found.get(name)} entries, expected {elements}"
            for name in QUALITY if found.get(name) != elements]


def check(path, reference):
    problems = []
    try:
        mesh = meshio.read(path)
    except Exception as error:  # meshio raises ValueError, ReadError, …
        return [f"meshio cannot read it: {error}"]
    blocks = [(b.type, len(b.data)) for b in mesh.cells]
    expected = [(b.type, len(b.data)) for b in reference.cells]
    if blocks != expected:
        problems.append(f"cell blocks {blocks}, expected {expected}")
    if len(mesh.points) != len(reference.points):
        problems.append(f"{len(mesh.points)} points, expected {len(reference.points)}")
    if "msh4" in os.path.basename(path):
        # meshio reads 4.1 $ElementData: one value per cell of every block.
        for name in QUALITY:
            if name not in mesh.cell_data:
                problems.append(f"meshio has no cell data {name}")
    problems += check_gmsh_views(path, sum(n for _, n in expected))
    return problems


def main():
    getme, inputs, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    source = os.path.join(inputs, "hybrid_22_ascii.msh")
    reference = meshio.read(source)
    outputs = []
    for fmt in ("msh2", "msh4"):
        for encoding in ("--ascii", "--binary"):
            out = os.path.join(work, f"smoothed_{fmt}_{encoding[2:]}.msh")
            run(getme, "smooth", source, out, "--format", fmt, encoding)
            outputs.append(out)
    # getme convert of a smoothed 2.2 file (its views read back, written again).
    ascii22 = os.path.join(work, "smoothed_msh2_ascii.msh")
    for fmt in ("msh2", "msh4"):
        out = os.path.join(work, f"converted_{fmt}.msh")
        run(getme, "convert", ascii22, out, "--format", fmt, "--ascii")
        outputs.append(out)

    failed = 0
    for path in outputs:
        problems = check(path, reference)
        print(("FAIL " if problems else "ok ") + os.path.basename(path) +
              (": " + "; ".join(problems) if problems else ""))
        failed += bool(problems)

    # getme read the 2.2 views back with the values written: its 4.1 conversion, which meshio
    # reads, holds for every element the value the 2.2 file gives each of its nodes.
    written = element_node_data(ascii22, "mean_ratio")
    converted = meshio.read(os.path.join(work, "converted_msh4.msh"))
    with open(ascii22) as f:
        text = f.read()
    body = text[text.index("$Elements\n") + len("$Elements\n"):text.index("$EndElements")]
    element_tags = [int(line.split()[0]) for line in body.splitlines()[1:]]
    read_back = np.concatenate(converted.cell_data["mean_ratio"])
    if sorted(written) != sorted(element_tags):
        print("FAIL the 2.2 mean_ratio view does not cover every element")
        failed += 1
    elif any(len(set(written[tag])) != 1 for tag in element_tags):
        print("FAIL the 2.2 mean_ratio view gives an element different values at its nodes")
        failed += 1
    elif not np.array_equal(read_back, [written[tag][0] for tag in element_tags]):
        print("FAIL getme did not read the 2.2 mean_ratio view back as written")
        failed += 1
    else:
        print("ok mean_ratio read back from MSH 2.2")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
