#!/usr/bin/python3
"""Draws a cut through volume meshes, side by side, as SVG or PNG (docs/boundary.md's pictures).

    /usr/bin/python3 scripts/render_cut.py OUT.svg --axis y --at 3 --width 0.3 \
        "before=IN.vtk" "after=OUT.vtk" [--view xz] [--xrange A:B] [--yrange A:B]

For each mesh (VTK legacy or MSH, read with meshio) every element edge whose two nodes lie in the
slab |axis - at| <= width is drawn, projected onto the two other axes (or --view), so a cut along
a grid plane of a structured block shows that plane's cells and a cut through an unstructured
mesh shows the elements it crosses. Plotted with gnuplot (Debian's gnuplot-nox), like getme
report.
"""

import argparse
import os
import subprocess
import sys
import tempfile

import meshio

# Element edges by node index, in VTK's (and meshio's) node order.
EDGES = {
    "tetra": [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)],
    "hexahedron": [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4),
                   (0, 4), (1, 5), (2, 6), (3, 7)],
    "wedge": [(0, 1), (1, 2), (2, 0), (3, 4), (4, 5), (5, 3), (0, 3), (1, 4), (2, 5)],
    "pyramid": [(0, 1), (1, 2), (2, 3), (3, 0), (0, 4), (1, 4), (2, 4), (3, 4)],
}
AXES = {"x": 0, "y": 1, "z": 2}


def cut_edges(path, axis, at, width, view):
    mesh = meshio.read(path)
    points = mesh.points
    inside = abs(points[:, AXES[axis]] - at) <= width
    seen = set()
    lines = []
    for block in mesh.cells:
        for a, b in EDGES.get(block.type, []):
            for cell in block.data:
                i, j = int(cell[a]), int(cell[b])
                key = (min(i, j), max(i, j))
                if key in seen or not (inside[i] and inside[j]):
                    continue
                seen.add(key)
                lines.append((points[i, view[0]], points[i, view[1]],
                              points[j, view[0]], points[j, view[1]]))
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output")
    parser.add_argument("meshes", nargs="+", help="LABEL=PATH")
    parser.add_argument("--axis", choices="xyz", default="y")
    parser.add_argument("--at", type=float, default=0.0)
    parser.add_argument("--width", type=float, default=0.1)
    parser.add_argument("--view", default=None, help="the two axes drawn, e.g. xz")
    parser.add_argument("--xrange", default=None)
    parser.add_argument("--yrange", default=None)
    parser.add_argument("--title", default="")
    parser.add_argument("--equal", action="store_true",
                        help="the same scale on both axes (default: each axis fills its panel)")
    parser.add_argument("--rows", action="store_true", help="panels one above the other")
    args = parser.parse_args()
    view_names = args.view or "".join(a for a in "xyz" if a != args.axis)
    view = [AXES[a] for a in view_names]
    panels = []
    with tempfile.TemporaryDirectory() as scratch:
        for k, spec in enumerate(args.meshes):
            label, path = spec.split("=", 1)
            data = os.path.join(scratch, f"{k}.dat")
            with open(data, "w") as out:
                for x0, y0, x1, y1 in cut_edges(path, args.axis, args.at, args.width, view):
                    out.write(f"{x0} {y0}\n{x1} {y1}\n\n")
            panels.append((label, data))
        terminal = "pngcairo" if args.output.endswith(".png") else "svg"
        rows, columns = (len(panels), 1) if args.rows else (1, len(panels))
        script = [
            f"set terminal {terminal} size {480 * columns},{360 * rows + 40} font 'sans,11'",
            f"set output '{args.output}'",
            f"set multiplot layout {rows},{columns} title '{args.title}'",
            "unset key", "set termoption noenhanced",
            f"set xlabel '{view_names[0]}'", f"set ylabel '{view_names[1]}'",
        ]
        if args.equal:
            script.append("set size ratio -1")
        if args.xrange:
            script.append(f"set xrange [{args.xrange}]")
        if args.yrange:
            script.append(f"set yrange [{args.yrange}]")
        for label, data in panels:
            script.append(f"set title '{label}'")
            script.append(f"plot '{data}' with lines lc rgb '#1f4e79' lw 0.6")
        script.append("unset multiplot")
        subprocess.run(["gnuplot"], input="\n".join(script), text=True, check=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
