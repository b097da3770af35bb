#!/usr/bin/python3
"""What a sliding boundary and kept layers cost (issue 15): the whole `getme smooth` process.

    /usr/bin/python3 bench/boundary_cost.py BUILD_DIR MESH... [--runs 5] [--threads 2]

For every mesh, runs `getme smooth MESH OUT --json` with the boundary held (the default), with
`--boundary slide`, and with `--boundary slide --keep-layers`, each --runs times, and prints a
Markdown table: the median wall time of the whole process (start, read, smoothing, write), the
median engine time (the result's "seconds"), the ratio of each to the held run's, and q_min /
q_mean. Runs alternate between the modes, so a slow spell of the machine spreads over all of them.
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
    args = parser.parse_args()
    getme = os.path.join(args.build, "bin", "getme")
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


if __name__ == "__main__":
    sys.exit(main())
