#!/usr/bin/python3
"""The process-start comparison of docs/benchmarks.md ("Process start"): the whole default run of
`getme smooth IN OUT --threads 2 --quiet` on the shared meshes with a Mesquite figure, as built and
with the libraries `getme` used to link preloaded (LD_PRELOAD), alternately, so both columns come
from one binary on one machine state.

Usage: bench/process_start.py BUILD_DIR [--shared DIR] [--repeats N] [--preload "LIB ..."]
"""
import argparse
import os
import statistics
import subprocess
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
MESHES = ["mesquite/tire.vtk", "mesquite/flat-tet-sphere.vtk", "mesquite/cub_fru.vtk",
          "mesquite/mixed-hex-pyr-tet.vtk", "mesquite/cub_wedge_like.vtk",
          "su2/knowles-mixed-beam.vtk"]
# What getme linked before 2026-11-26 evening: the format libraries, Highway and gRPC.
OLD_LIBRARIES = "libexoIIv2c.so.5 libcgns.so.3.4 libhwy.so.1 libgrpc++.so.1.51 libprotobuf.so.32"


def timed_run(getme, mesh, output, preload):
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
    args = parser.parse_args()
    getme = os.path.join(args.build, "bin", "getme")
    with tempfile.TemporaryDirectory() as work:
        output = os.path.join(work, "out.vtk")
        print("| mesh | now, s (min–max) | libraries preloaded, s (min–max) |")
        print("|---|---|---|")
        for relative in MESHES:
            mesh = os.path.join(args.shared, relative)
            now, before = [], []
            for _ in range(args.repeats):
                now.append(timed_run(getme, mesh, output, ""))
                before.append(timed_run(getme, mesh, output, args.preload))
            print(f"| {os.path.basename(relative)} | {statistics.median(now):.4f} "
                  f"({min(now):.4f}–{max(now):.4f}) | {statistics.median(before):.4f} "
                  f"({min(before):.4f}–{max(before):.4f}) |", flush=True)


if __name__ == "__main__":
    main()
