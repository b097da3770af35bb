#!/usr/bin/python3
"""Alternating whole default runs, `getme smooth IN OUT --threads 2 --quiet`, on the shared meshes
with a Mesquite figure, in two columns measured turn about, so both see one machine state:
- by default (docs/benchmarks.md, "Process start") the build's getme as built, and the same binary
  with the libraries getme used to link preloaded (LD_PRELOAD);
- with --against OTHER_GETME, the build's getme and another getme binary (an older commit's
  build: docs/benchmarks.md, "Element lists ...").
Prints a markdown table and the geometric mean of Mesquite's time over each column's.

Usage: bench/process_start.py BUILD_DIR [--shared DIR] [--repeats N] [--only NAME,...]
                              [--preload "LIB ..." | --against OTHER_GETME]
"""
import argparse
import math
import os
import statistics
import subprocess
import tempfile
import time

from end_to_end import mesquite_reference

HERE = os.path.dirname(os.path.abspath(__file__))
MESHES = ["mesquite/tire.vtk", "mesquite/flat-tet-sphere.vtk", "mesquite/cub_fru.vtk",
          "mesquite/mixed-hex-pyr-tet.vtk", "mesquite/cub_wedge_like.vtk",
          "su2/knowles-mixed-beam.vtk"]
# What getme linked before 2026-11-26 evening: the format libraries, Highway and gRPC.
OLD_LIBRARIES = "libexoIIv2c.so.5 libcgns.so.3.4 libhwy.so.1 libgrpc++.so.1.51 libprotobuf.so.32"


def timed_run(getme, mesh, output, preload=""):
    env = dict(os.environ)
    if preload:
        env["LD_PRELOAD"] = preload
    start = time.perf_counter()
    subprocess.run([getme, "smooth", mesh, output, "--threads", "2", "--quiet"], env=env,
                   check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build")
    parser.add_argument("--shared", default=os.path.join(HERE, "..", "..", "shared", "meshes"))
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--preload", default=OLD_LIBRARIES)
    parser.add_argument("--against", default=None, help="another getme binary: the second column")
    parser.add_argument("--only", default="",
                        help="comma-separated file names of MESHES to run (default: all six)")
    args = parser.parse_args()
    meshes = MESHES
    if args.only:
        wanted = args.only.split(",")
        unknown = [name for name in wanted if name not in {os.path.basename(m) for m in MESHES}]
        if unknown:
            parser.error(f"--only: unknown mesh {', '.join(unknown)}; choose from "
                         f"{', '.join(os.path.basename(m) for m in MESHES)}")
        meshes = [m for m in MESHES if os.path.basename(m) in wanted]
    getme = os.path.join(args.build, "bin", "getme")
    reference = mesquite_reference(args.shared)
    second = "other getme" if args.against else "libraries preloaded"
    ratios = ([], [])
    with tempfile.TemporaryDirectory() as work:
        output = os.path.join(work, "out.vtk")
        print(f"| mesh | now, s (min–max) | {second}, s (min–max) | now / {second} |")
        print("|---|---|---|---|")
        for relative in meshes:
            mesh = os.path.join(args.shared, relative)
            now, before = [], []
            for _ in range(args.repeats):
                now.append(timed_run(getme, mesh, output))
                if args.against:
                    before.append(timed_run(args.against, mesh, output))
                else:
                    before.append(timed_run(getme, mesh, output, args.preload))
            median_now, median_before = statistics.median(now), statistics.median(before)
            mesquite_seconds = reference[os.path.basename(relative)][2]
            ratios[0].append(mesquite_seconds / median_now)
            ratios[1].append(mesquite_seconds / median_before)
            print(f"| {os.path.basename(relative)} | {median_now:.4f} "
                  f"({min(now):.4f}–{max(now):.4f}) | {median_before:.4f} "
                  f"({min(before):.4f}–{max(before):.4f}) | {median_now / median_before:.3f} |",
                  flush=True)
    means = [math.exp(sum(math.log(r) for r in column) / len(column)) for column in ratios]
    over = "" if len(meshes) == len(MESHES) else f" (over {len(meshes)} of the {len(MESHES)} meshes)"
    print(f"\nGeometric mean of Mesquite's time over getme's{over}: now {means[0]:.2f}, "
          f"{second} {means[1]:.2f}.")


if __name__ == "__main__":
    main()
