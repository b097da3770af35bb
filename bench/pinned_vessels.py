#!/usr/bin/python3
"""Two getme builds on the pinned thin-layer vessels (issue 14, item 3), turn about: the eight
artery variants of end_to_end.py and twelve more arteries of other sizes, seeds and layer
arrangements that no setting was chosen on. Each run is the whole default
`getme smooth IN OUT --threads N --json --quiet` (every boundary node fixed, the default);
prints per mesh the final q_min / q_mean and the median wall seconds of each build, then the
geometric means of the q_min ratio and the time ratio, second build over first.

The worst-cluster stage decides these meshes' q_min and lands on different plateaus of a
non-convex max-min problem when its path changes in the last bits (docs/thin-layers.md), so a
change to it is judged on the spread over many meshes, not on one.

Usage: bench/pinned_vessels.py FIRST_GETME SECOND_GETME [--work DIR] [--repeats N]
                               [--threads N] [--only NAME,...] [--meshgen GETME_MESHGEN]
"""
import argparse
import math
import os
import statistics
import subprocess
import tempfile

from end_to_end import GENERATED, smooth

HERE = os.path.dirname(os.path.abspath(__file__))

# name -> getme-meshgen arguments: the eight variants the targets are stated on, then twelve more.
VESSELS = {name: args for name, args in GENERATED.items() if name.startswith("artery")}
VESSELS.update({
    "artery-0.4-seed2": ["artery", "--mesh-size", "0.4", "--seed", "2"],
    "artery-0.4-seed3": ["artery", "--mesh-size", "0.4", "--seed", "3"],
    "artery-0.3-seed4": ["artery", "--mesh-size", "0.3", "--seed", "4"],
    "artery-0.3-seed5-in": ["artery", "--mesh-size", "0.3", "--seed", "5", "--outer-layers", "0"],
    "artery-0.35-seed6": ["artery", "--mesh-size", "0.35", "--seed", "6"],
    "artery-0.45-seed7-sharp": ["artery", "--mesh-size", "0.45", "--seed", "7",
                                "--junction-fillet", "0"],
    "artery-0.3-seed8-in": ["artery", "--mesh-size", "0.3", "--seed", "8", "--outer-layers", "0"],
    "artery-seed9": ["artery", "--seed", "9"],
    "artery-0.25-seed10": ["artery", "--mesh-size", "0.25", "--seed", "10"],
    "artery-0.5-seed11-in": ["artery", "--mesh-size", "0.5", "--seed", "11", "--outer-layers", "0"],
    "artery-0.4-seed12-sharp": ["artery", "--mesh-size", "0.4", "--seed", "12",
                                "--junction-fillet", "0"],
    "artery-seed13-in": ["artery", "--seed", "13", "--outer-layers", "0"],
})


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("first")
    parser.add_argument("second")
    parser.add_argument("--work", default=None)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--only", default="", help="comma-separated names of VESSELS")
    parser.add_argument("--meshgen", default=None,
                        help="getme-meshgen to make the meshes (default: beside SECOND_GETME)")
    args = parser.parse_args()
    names = list(VESSELS)
    if args.only:
        names = args.only.split(",")
        unknown = [name for name in names if name not in VESSELS]
        if unknown:
            parser.error(f"--only: unknown vessel {', '.join(unknown)}; choose from "
                         f"{', '.join(VESSELS)}")
    work = args.work or tempfile.mkdtemp(prefix="getme-vessels-")
    meshgen = args.meshgen or os.path.join(os.path.dirname(os.path.abspath(args.second)),
                                           "getme-meshgen")
    builds = [args.first, args.second]
    print("| mesh | elements | first: q_min / q_mean | first s | second: q_min / q_mean | "
          "second s | q_min ratio |")
    print("|---|---|---|---|---|---|---|")
    log_quality, log_time = [], []
    for name in names:
        mesh = os.path.join(work, name + ".vtk")
        if not os.path.exists(mesh):
            subprocess.run([meshgen, VESSELS[name][0], mesh] + VESSELS[name][1:], check=True,
                           stdout=subprocess.DEVNULL)
        walls = [[], []]
        results = [None, None]
        for _ in range(args.repeats):
            for which, getme in enumerate(builds):
                wall, result, error = smooth(getme, mesh, os.path.join(work, "out.vtk"),
                                             args.threads)
                if result is None:
                    raise SystemExit(f"{getme} failed on {name}: {error}")
                walls[which].append(wall)
                results[which] = result
        medians = [statistics.median(w) for w in walls]
        ratio = results[1]["q_min"] / results[0]["q_min"]
        log_quality.append(math.log(ratio))
        log_time.append(math.log(medians[1] / medians[0]))
        print(f"| {name} | {results[0]['elements']:,} | "
              f"{results[0]['q_min']:.4f} / {results[0]['q_mean']:.4f} | {medians[0]:.3f} | "
              f"{results[1]['q_min']:.4f} / {results[1]['q_mean']:.4f} | {medians[1]:.3f} | "
              f"{ratio:.3f} |", flush=True)
    count = len(names)
    print(f"\nGeometric means, second over first, over {count} vessels: q_min "
          f"{math.exp(sum(log_quality) / count):.3f} (lowest {math.exp(min(log_quality)):.3f}, "
          f"highest {math.exp(max(log_quality)):.3f}); wall seconds "
          f"{math.exp(sum(log_time) / count):.3f}")


if __name__ == "__main__":
    main()
