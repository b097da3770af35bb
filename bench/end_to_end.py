#!/usr/bin/python3
"""The headline comparison of docs/benchmarks.md (issue 14): the whole default run a user waits for,
end to end, against Mesquite's whole run.

Usage: bench/end_to_end.py BUILD_DIR [--shared DIR] [--work DIR] [--repeats N] [--threads 1,2]
                           [--baseline-bin GETME] [--doc docs/benchmarks.md]

For every shared mesh and every generator mesh it times `getme smooth IN OUT --threads N --json
--quiet` (reading, smoothing with every default phase, writing) as a subprocess, N = 1 and 2, and
takes the median of the repeats. Mesquite's figures (final q_min / q_mean and its optimisation
time, single thread) are read from ../shared/meshes/README.md at run time. With --baseline-bin the
default of an older getme (e.g. the commit before the polish) runs too, so a table can show what
"today's default" reached. With --doc the tables replace the block between
`<!-- BEGIN generated: end-to-end -->` and `<!-- END generated: end-to-end -->`; otherwise they
are printed.
"""
import argparse
import datetime
import json
import math
import os
import re
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# Shared meshes, by path below --shared. Tangled ones have no Mesquite figure (its default
# untangler fails on pave3/pave_cyl, README) but are part of the default run's promise.
SHARED = [
    "mesquite/tire.vtk", "mesquite/flat-tet-sphere.vtk", "mesquite/cub_fru.vtk",
    "mesquite/mixed-hex-pyr-tet.vtk", "mesquite/cub_wedge_like.vtk",
    "su2/knowles-mixed-beam.vtk", "mesquite/hex_5_tangled.vtk", "mesquite/tet_4_tangled.vtk",
    "mesquite/pave3.vtk", "mesquite/pave_cyl.vtk", "mesquite/cube-clip-5.vtk",
    "mesquite/1000hex-block-internal-bias.vtk",
]

# Generator meshes: name -> getme-meshgen arguments (KIND, then options; OUT is added).
GENERATED = {
    "plate": ["plate", "--elements", "34050", "--seed", "1"],
    "ring": ["ring", "--elements", "83210", "--seed", "1"],
    "hybrid-20": ["hybrid", "--size", "20", "--seed", "1"],
    "artery-S-sharp": ["artery", "--mesh-size", "0.5", "--junction-fillet", "0"],
    "artery-S": ["artery", "--mesh-size", "0.5"],
    "artery-M": ["artery"],
    "artery-M-sharp": ["artery", "--junction-fillet", "0"],
    "artery-M-in": ["artery", "--outer-layers", "0"],
    "artery-L": ["artery", "--mesh-size", "0.2"],
    "artery-L-sharp": ["artery", "--mesh-size", "0.2", "--junction-fillet", "0"],
    "artery-L-in": ["artery", "--mesh-size", "0.2", "--outer-layers", "0"],
}

BEGIN = "<!-- BEGIN generated: end-to-end -->"
END = "<!-- END generated: end-to-end -->"


def mesquite_reference(shared):
    """{file name: (q_min, q_mean, seconds)} from the README's reference table rows
    `| tire.vtk | 0.0442 → 0.1637 | 0.7930 → 0.8109 | 0.08 |`."""
    reference = {}
    row = re.compile(r"^\|\s*(?:\.\./su2/)?([\w.-]+\.vtk)\s*\|\s*[\d.]+.*?→\s*([\d.]+)\s*\|"
                     r"\s*[\d.]+\s*→\s*([\d.]+)\s*\|\s*([\d.]+)\s*\|")
    with open(os.path.join(shared, "README.md")) as f:
        for line in f:
            match = row.match(line)
            if match:
                reference[match.group(1)] = tuple(float(match.group(i)) for i in (2, 3, 4))
    return reference


def smooth(getme, mesh, out, threads):
    """One end-to-end run: (wall seconds, result JSON or None, error text)."""
    cmd = [getme, "smooth", mesh, out, "--threads", str(threads), "--json", "--quiet"]
    start = time.perf_counter()
    run = subprocess.run(cmd, capture_output=True, text=True)
    wall = time.perf_counter() - start
    lines = [json.loads(line) for line in run.stdout.splitlines() if line.startswith("{")]
    result = lines[-1] if lines and lines[-1].get("event") == "result" else None
    return wall, result, run.stderr.strip()


def measure(getme, mesh, work, threads, repeats):
    walls, result, error = [], None, ""
    out = os.path.join(work, "e2e-out.vtk")
    for _ in range(repeats):
        wall, result, error = smooth(getme, mesh, out, threads)
        if result is None:
            return None, error
        walls.append(wall)
    return {"median": statistics.median(walls), "min": min(walls), "max": max(walls),
            "result": result}, ""


def seconds(m):
    if m is None:
        return "failed"
    if m["min"] == m["max"]:
        return f"{m['median']:.3f}"
    return f"{m['median']:.3f} ({m['min']:.3f}–{m['max']:.3f})"


def phases(result):
    names = {"untangle": "u", "simultaneous": "sim", "sequential": "seq", "polish": "pol",
             "layers": "lay"}
    return " ".join(f"{names.get(p['phase'], p['phase'])} {p['iterations']}/{p['seconds']:.3f}"
                    for p in result["phases"])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("build")
    parser.add_argument("--shared", default=os.path.join(ROOT, "..", "shared", "meshes"))
    parser.add_argument("--work", default=None)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--threads", default="1,2")
    parser.add_argument("--baseline-bin", default=None)
    parser.add_argument("--only", default=None, help="comma-separated mesh names")
    parser.add_argument("--doc", default=None)
    args = parser.parse_args()

    getme = os.path.join(args.build, "bin", "getme")
    meshgen = os.path.join(args.build, "bin", "getme-meshgen")
    work = args.work or os.path.join(args.build, "bench-work", "end-to-end")
    os.makedirs(work, exist_ok=True)
    threads = [int(t) for t in args.threads.split(",")]
    reference = mesquite_reference(args.shared)
    only = set(args.only.split(",")) if args.only else None

    meshes = []  # (name, path, is_shared)
    for relative in SHARED:
        name = os.path.basename(relative)
        if only is None or name in only:
            meshes.append((name, os.path.join(args.shared, relative), True))
    for name, spec in GENERATED.items():
        if only is not None and name not in only:
            continue
        path = os.path.join(work, name + ".vtk")
        if not os.path.exists(path):
            subprocess.run([meshgen, spec[0], path] + spec[1:], check=True, capture_output=True)
        meshes.append((name, path, False))

    started = datetime.datetime.now(datetime.timezone.utc)
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no"],
                           capture_output=True, text=True).stdout.strip()
    rows, ratios, checks = [], [], []
    for name, path, shared in meshes:
        print(f"{name} ...", file=sys.stderr, flush=True)
        measured = {}
        error = ""
        for t in threads:
            measured[t], error = measure(getme, path, work, t, args.repeats)
        last = measured[threads[-1]]
        if last is None:
            rows.append(f"| {name} | | failed: {error[:160].replace('|', '/')} |")
            continue
        result = last["result"]
        baseline = ""
        if args.baseline_bin:
            old, _ = measure(args.baseline_bin, path, work, threads[-1], 1)
            baseline = (f"{old['result']['q_min']:.4f} / {old['result']['q_mean']:.4f}"
                        if old else "failed")
        ref = reference.get(name) if shared else None
        quality = f"{result['q_min']:.4f} / {result['q_mean']:.4f}"
        mesquite = f"{ref[0]:.4f} / {ref[1]:.4f}" if ref else "–"
        mesquite_s = f"{ref[2]:.2f}" if ref else "–"
        ratio = ""
        verdict = ""
        if ref:
            r = ref[2] / last["median"]
            ratios.append(r)
            ratio = f"{r:.2f}"
            q_ok = result["q_min"] >= ref[0] - 5e-5 and result["q_mean"] >= ref[1] - 0.002 - 5e-5
            verdict = ("yes" if q_ok else "**no**") + " / " + ("yes" if r > 1 else "**no**")
            checks.append((name, q_ok, r))
        cells = [name, f"{result['elements']:,}",
                 f"{result['q_min_before']:.4f} / {result['q_mean_before']:.4f}"]
        cells += [seconds(measured[t]) for t in threads]
        cells += [f"{result['seconds']:.3f}", phases(result), quality]
        cells += [baseline] if args.baseline_bin else []
        cells += [mesquite, mesquite_s, ratio, verdict]
        rows.append("| " + " | ".join(cells) + " |")

    header = ["mesh", "elements", "q_min / q_mean before"]
    header += [f"getme s, {t} thread{'s' if t > 1 else ''} (median, min–max)" for t in threads]
    header += [f"engine s ({threads[-1]} t)", "phases: iterations/s", "getme q_min / q_mean"]
    header += ["default before issue 14: q_min / q_mean"] if args.baseline_bin else []
    header += ["Mesquite q_min / q_mean", "Mesquite s", f"Mesquite s / getme s ({threads[-1]} t)",
               "quality met / faster"]
    lines = [
        f"Measured {started:%Y-%m-%d %H:%M} UTC, commit `{commit}{'+local changes' if dirty else ''}`,"
        f" {args.repeats} repeats per row, by `bench/end_to_end.py {args.build}"
        f"{' --baseline-bin ' + args.baseline_bin if args.baseline_bin else ''}`.",
        "",
        "| " + " | ".join(header) + " |",
        "|" + "---|" * len(header),
    ] + rows
    if ratios:
        geomean = math.exp(sum(math.log(r) for r in ratios) / len(ratios))
        lines += ["", f"Geometric mean of Mesquite's time over getme's ({threads[-1]} threads, end "
                  f"to end) over the {len(ratios)} meshes with a Mesquite figure: **{geomean:.2f}**."
                  f" Quality targets met on {sum(1 for c in checks if c[1])} of {len(checks)};"
                  f" faster on {sum(1 for c in checks if c[2] > 1)} of {len(checks)}."]
    text = "\n".join(lines) + "\n"
    if args.doc:
        with open(args.doc) as f:
            doc = f.read()
        start, end = doc.index(BEGIN) + len(BEGIN), doc.index(END)
        with open(args.doc, "w") as f:
            f.write(doc[:start] + "\n" + text + doc[end:])
    else:
        print(text)


if __name__ == "__main__":
    main()
