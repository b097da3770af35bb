#!/usr/bin/python3
"""Thread scaling of the whole default run, two builds measured turn about.

For each repeat, each getme binary given runs `getme smooth MESH OUT --threads T --json` for every
thread count T, one after the other, so every column sees the same machine state (this VM's speed
drifts by tens of percent within an hour: docs/benchmarks.md). Prints, per binary, the medians of
the engine's seconds and of each phase's at every thread count, the speed-up of the last thread
count over the first (whole run and per phase), the per-repeat speed-ups, and whether the outputs
of all runs were the same bytes.

Usage: bench/thread_scaling.py MESH GETME [GETME ...] [--threads 1,2] [--repeats N]

The issue-16 measure (docs/benchmarks.md, "Finding while claiming"):
  build/bin/getme-meshgen hybrid h55.vtk --size 55 --seed 1
  bench/thread_scaling.py h55.vtk OTHER_BUILD/bin/getme build/bin/getme --repeats 3
"""
import argparse
import filecmp
import json
import os
import statistics
import subprocess
import tempfile

PHASES = ["untangle", "simultaneous", "sequential", "polish"]


def run_once(getme, mesh, output, threads):
    completed = subprocess.run([getme, "smooth", mesh, output, "--threads", str(threads), "--json"],
                               check=True, capture_output=True, text=True)
    result = json.loads(completed.stdout.strip().splitlines()[-1])
    phases = {phase["phase"]: phase["seconds"] for phase in result["phases"]}
    return {"engine": result["seconds"], **{name: phases.get(name, 0.0) for name in PHASES}}


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mesh")
    parser.add_argument("getme", nargs="+", help="getme binaries to compare")
    parser.add_argument("--threads", default="1,2", help="thread counts, comma-separated")
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    thread_counts = [int(t) for t in args.threads.split(",")]
    if len(thread_counts) < 2:
        parser.error("--threads needs at least two thread counts")

    runs = {(getme, threads): [] for getme in args.getme for threads in thread_counts}
    same_bytes = True
    with tempfile.TemporaryDirectory() as scratch:
        reference = None
        for repeat in range(args.repeats):
            for index, getme in enumerate(args.getme):
                for threads in thread_counts:
                    output = os.path.join(scratch, f"out{index}-{threads}.vtu")
                    runs[(getme, threads)].append(run_once(getme, args.mesh, output, threads))
                    if reference is None:
                        reference = output + ".reference"
                        os.replace(output, reference)
                    elif not filecmp.cmp(reference, output, shallow=False):
                        same_bytes = False
                    print(f"repeat {repeat + 1}: {getme} --threads {threads}: "
                          f"{runs[(getme, threads)][-1]['engine']:.3f} s", flush=True)

    first, last = thread_counts[0], thread_counts[-1]
    print()
    print("| getme | " + " | ".join(f"engine s, {t} t" for t in thread_counts) +
          f" | speed-up {first} → {last} t | " +
          " | ".join(f"{phase} {first} → {last} t" for phase in PHASES[1:]) + " |")
    print("|---" * (len(thread_counts) + 2 + len(PHASES) - 1) + "|")
    for getme in args.getme:
        median = {t: {key: statistics.median(run[key] for run in runs[(getme, t)])
                      for key in ["engine"] + PHASES} for t in thread_counts}
        cells = [f"{median[t]['engine']:.2f}" for t in thread_counts]
        cells.append(f"{median[first]['engine'] / median[last]['engine']:.3f}")
        for phase in PHASES[1:]:
            cells.append(f"{median[first][phase]:.2f} → {median[last][phase]:.2f}")
        print(f"| {getme} | " + " | ".join(cells) + " |")
    print()
    for getme in args.getme:
        ratios = [a["engine"] / b["engine"] for a, b in zip(runs[(getme, first)], runs[(getme, last)])]
        print(f"{getme}: per-repeat speed-ups " + ", ".join(f"{r:.3f}" for r in ratios))
    print("outputs: " + ("all the same bytes" if same_bytes else "DIFFERENT bytes"))


if __name__ == "__main__":
    main()
