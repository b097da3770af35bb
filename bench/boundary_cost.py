#!/usr/bin/python3
"""What a sliding boundary and kept layers cost (issue 15): the whole `getme smooth` process.

    /usr/bin/python3 bench/boundary_cost.py BUILD_DIR MESH... [--runs 5] [--threads 2]
    /usr/bin/python3 bench/boundary_cost.py BUILD_DIR MESH... --against OTHER_BUILD_DIR

For every mesh, runs `getme smooth MESH OUT --json` with the boundary held (the default), with
`--boundary slide`, and with `--boundary slide --keep-layers`, each --runs times, and prints a
Markdown table: the median wall time of the whole process (start, read, smoothing, write), the
median engine time (the result's "seconds"), the ratio of each to the held run's, and q_min /
q_mean. Runs alternate between the modes, so a slow spell of the machine spreads over all of them.

With --against, it compares two builds' sliding runs instead: every round runs BUILD_DIR held,
OTHER_BUILD_DIR sliding and BUILD_DIR sliding, and the table gives each sliding median against the
held one and the change between the builds.

With --projections (needs Linux `perf`), it measures the projections alone, on one thread: the
share of a sliding run's samples (`perf record -F 10000`) in the nearest-point functions (the
grids and their building, the node lists and their gathering, CGAL's trees; the sorts the grids
call are not counted, since perf names them by the standard library's template), times the
median sliding run, against
the median held run: the issue's "projection costs at most 30 % on top of a fixed run". With
--against too, both builds are measured, alternating.
"""

import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

MODES = [("held", []), ("slide", ["--boundary", "slide"]),
         ("slide + keep", ["--boundary", "slide", "--keep-layers"])]


def print_header(*columns):
    """A Markdown table's header and separator rows."""
    print("| " + " | ".join(columns) + " |")
    print("|" + "---|" * len(columns))


def run_once(getme, mesh, out, threads, extra):
    start = time.perf_counter()
    done = subprocess.run([getme, "smooth", mesh, out, "--json", "--quiet", "--threads",
                           str(threads)] + extra, capture_output=True, text=True, check=True)
    wall = time.perf_counter() - start
    result = json.loads(done.stdout.strip().splitlines()[-1])
    return wall, result


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build")
    parser.add_argument("meshes", nargs="+")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--against", help="another build directory to compare sliding runs with")
    parser.add_argument("--projections", action="store_true",
                        help="the projections' share of one-thread sliding runs (perf)")
    args = parser.parse_args()
    getme = os.path.join(args.build, "bin", "getme")
    if args.projections:
        builds = [("this build", getme)]
        if args.against:
            builds.append(("other build", os.path.join(args.against, "bin", "getme")))
        return projection_shares(builds, args)
    if args.against:
        return compare_builds(getme, os.path.join(args.against, "bin", "getme"), args)
    print_header("mesh", "mode", "process s (× held)", "engine s (× held)", "q_min / q_mean")
    with tempfile.TemporaryDirectory() as scratch:
        out = os.path.join(scratch, "out.vtk")
        for mesh in args.meshes:
            walls = {name: [] for name, _ in MODES}
            engines = {name: [] for name, _ in MODES}
            quality = {}
            for _ in range(args.runs):
                for name, extra in MODES:
                    wall, result = run_once(getme, mesh, out, args.threads, extra)
                    walls[name].append(wall)
                    engines[name].append(result["seconds"])
                    quality[name] = (result["q_min"], result["q_mean"])
            held_wall = statistics.median(walls["held"])
            held_engine = statistics.median(engines["held"])
            for name, _ in MODES:
                wall = statistics.median(walls[name])
                engine = statistics.median(engines[name])
                print(f"| {os.path.basename(mesh)} | {name} | {wall:.3f} ({wall / held_wall:.2f} ×) "
                      f"| {engine:.3f} ({engine / max(held_engine, 1e-9):.2f} ×) "
                      f"| {quality[name][0]:.4f} / {quality[name][1]:.4f} |")
    return 0


def compare_builds(getme, other, args):
    slide = ["--boundary", "slide"]
    print_header("mesh", "held s", "sliding s, other build (× held)",
                 "sliding s, this build (× held)", "change")
    with tempfile.TemporaryDirectory() as scratch:
        out = os.path.join(scratch, "out.vtk")
        for mesh in args.meshes:
            walls = {"held": [], "other": [], "this": []}
            for _ in range(args.runs):
                for name, binary, extra in [("held", getme, []), ("other", other, slide),
                                            ("this", getme, slide)]:
                    wall, _ = run_once(binary, mesh, out, args.threads, extra)
                    walls[name].append(wall)
            held, before, after = (statistics.median(walls[k]) for k in ("held", "other", "this"))
            print(f"| {os.path.basename(mesh)} | {held:.3f} | {before:.3f} ({before / held:.2f} ×) "
                  f"| {after:.3f} ({after / held:.2f} ×) | {100.0 * (after / before - 1.0):+.0f} % |")
    return 0


# The nearest-point functions (surface/getme_surface): the grids (their building too), the node
# lists and their gathering, the projector, CGAL's trees.
PROJECTION_SYMBOLS = re.compile(
    r"TriangleGrid::|NodeTriangles::|"
    r"SurfaceProjector::|CGAL::")


def projection_share(getme, mesh, out, scratch):
    """Percent of a one-thread sliding run's samples in PROJECTION_SYMBOLS."""
    data = os.path.join(scratch, "perf.data")
    subprocess.run(["perf", "record", "-q", "-F", "10000", "-o", data, getme, "smooth", mesh, out,
                    "--quiet", "--threads", "1", "--boundary", "slide"],
                   capture_output=True, check=True)
    report = subprocess.run(["perf", "report", "-i", data, "--no-children", "--sort", "symbol",
                             "--stdio"], capture_output=True, text=True, check=True).stdout
    share = 0.0
    for line in report.splitlines():
        match = re.match(r"\s+([0-9.]+)%\s+\[\.\]\s+(.*)", line)
        if match and PROJECTION_SYMBOLS.search(match.group(2)):
            share += float(match.group(1))
    return share


def projection_shares(builds, args):
    print_header("mesh", "build", "share of samples", "sliding s (1 thread)", "projections s",
                 "held s", "projections / held")
    with tempfile.TemporaryDirectory() as scratch:
        out = os.path.join(scratch, "out.vtk")
        for mesh in args.meshes:
            shares = {name: [] for name, _ in builds}
            slides = {name: [] for name, _ in builds}
            helds = {name: [] for name, _ in builds}
            for _ in range(args.runs):
                for name, getme in builds:
                    slides[name].append(run_once(getme, mesh, out, 1, ["--boundary", "slide"])[0])
                    helds[name].append(run_once(getme, mesh, out, 1, [])[0])
            for _ in range(3):
                for name, getme in builds:
                    shares[name].append(projection_share(getme, mesh, out, scratch))
            for name, _ in builds:
                share = statistics.median(shares[name])
                slide = statistics.median(slides[name])
                held = statistics.median(helds[name])
                projections = share / 100.0 * slide
                print(f"| {os.path.basename(mesh)} | {name} | {share:.1f} % | {slide:.3f} "
                      f"| {projections:.3f} | {held:.3f} | {100.0 * projections / held:.0f} % |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
