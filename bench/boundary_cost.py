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
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

MODES = [("held", []), ("slide", ["--boundary", "slide"]),
         ("slide + keep", ["--boundary", "slide", "--keep-layers"])]


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
    args = parser.parse_args()
    getme = os.path.join(args.build, "bin", "getme")
    if args.against:
        return compare_builds(getme, os.path.join(args.against, "bin", "getme"), args)
    print("| mesh | mode | process s (× held) | engine s (× held) | q_min / q_mean |")
    print("|---|---|---|---|---|")
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
    print("| mesh | held s | sliding s, other build (× held) | sliding s, this build (× held) "
          "| change |")
    print("|---|---|---|---|---|")
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


if __name__ == "__main__":
    sys.exit(main())
