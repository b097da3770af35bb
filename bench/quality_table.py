#!/usr/bin/python3
"""Runs `getme smooth --json` over the meshes of docs/quality.md and prints its Markdown tables.

Usage: bench/quality_table.py BUILD_DIR SHARED_MESHES_DIR [--threads N]
Writes scratch meshes to a temporary directory; every number in the output comes from the run.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from end_to_end import mesquite_reference  # noqa: E402  (Mesquite's figures, from the README)

# Meshes with a Mesquite figure, by path below the shared directory.
MESQUITE_MESHES = ["mesquite/tire.vtk", "mesquite/flat-tet-sphere.vtk", "mesquite/cub_fru.vtk",
                   "mesquite/mixed-hex-pyr-tet.vtk", "mesquite/cub_wedge_like.vtk",
                   "su2/knowles-mixed-beam.vtk"]
METHODS = ["smart-laplace", "laplace", "simultaneous", "sequential", "getme", "warpage"]


def smooth(getme, mesh, extra, threads, workdir):
    out = os.path.join(workdir, "out.vtk")
    cmd = [getme, "smooth", mesh, out, "--json", "--quiet", "--threads", str(threads)] + extra
    run = subprocess.run(cmd, capture_output=True, text=True)
    lines = [json.loads(line) for line in run.stdout.splitlines() if line.startswith("{")]
    final = lines[-1] if lines else {"event": "error", "message": run.stderr.strip()}
    return " ".join(cmd[1:2] + [os.path.basename(mesh)] + cmd[4:]), final


def row(name, method, result):
    if result.get("event") != "result":
        return f"| {name} | {method} | failed: {result.get('message', '')} |||||||"
    iterations = "/".join(str(result[k]) for k in (
        "iterations_untangle", "iterations_simultaneous", "iterations_sequential",
        "iterations_laplace", "iterations_polish"))
    return (f"| {name} | {method} | {iterations} | {result['q_min_before']:.4f} / "
            f"{result['q_mean_before']:.4f} | {result['q_min']:.4f} / {result['q_mean']:.4f} | "
            f"{result['invalid_before']} → {result['invalid']} | {result['seconds']:.3f} | "
            f"{result['threads']} |")


HEADER = ("| mesh | method | iterations (untangle/sim./seq./Laplace/polish) | q_min / q_mean before | "
          "q_min / q_mean after | invalid | seconds | threads |\n|---|---|---|---|---|---|---|---|")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build")
    parser.add_argument("shared")
    parser.add_argument("--threads", type=int, default=1)
    args = parser.parse_args()
    getme = os.path.join(args.build, "bin", "getme")
    meshgen = os.path.join(args.build, "bin", "getme-meshgen")
    mesquite = os.path.join(args.shared, "mesquite")
    reference = mesquite_reference(args.shared)
    with tempfile.TemporaryDirectory() as workdir:
        print("### Shared Mesquite meshes against Mesquite's feasible Newton\n")
        print(HEADER)
        for relative in MESQUITE_MESHES:
            name = os.path.basename(relative)
            path = os.path.join(args.shared, relative)
            q_min, q_mean, seconds = reference[name]
            print(f"| {name} | Mesquite 2.99 (README) | | | {q_min:.4f} / {q_mean:.4f} | | "
                  f"{seconds:.2f} | 1 |")
            for method in METHODS:
                _, result = smooth(getme, path, ["--method", method], args.threads, workdir)
                print(row(name, method, result))
            for flag in ("--no-polish", "--literal"):
                _, result = smooth(getme, path, [flag], args.threads, workdir)
                print(row(name, "getme " + flag, result))
        print("\n### Other shared meshes\n")
        print(HEADER)
        for name in ("tet_4_tangled.vtk", "hex_5_tangled.vtk", "pave3.vtk", "pave_cyl.vtk",
                     "1000hex-block-internal-bias.vtk", "cube-clip-5.vtk",
                     "large_box_hex_1000.vtk", "small_box_hex_1000.vtk"):
            _, result = smooth(getme, os.path.join(mesquite, name), [], args.threads, workdir)
            print(row(name, "getme", result))

        print("\n### Generated meshes\n")
        print(HEADER)
        example = os.path.join(os.path.dirname(__file__), "..", "tests", "data",
                               "hybrid-example.vtk")
        for method in ("smart-laplace", "getme", "warpage"):
            _, result = smooth(getme, example, ["--method", method], args.threads, workdir)
            print(row("hybrid-example.vtk", method, result))
        vessel = os.path.join(workdir, "vessel.vtk")
        pinned = os.path.join(workdir, "vessel-pinned.vtk")
        geometry = ["--length", "3", "--mesh-size", "0.2"]
        subprocess.run([meshgen, "vessel", vessel, "--fix-wall"] + geometry, check=True,
                       capture_output=True)
        subprocess.run([meshgen, "vessel", pinned] + geometry, check=True, capture_output=True)
        for label, extra in (("smart-laplace", ["--method", "smart-laplace"]),
                             ("getme", []), ("getme --literal", ["--literal"])):
            _, result = smooth(getme, vessel, ["--free-boundary"] + extra, args.threads, workdir)
            print(row("vessel, wall fixed, caps free", label, result))
        for label, extra in (("getme", []), ("getme --no-polish", ["--no-polish"])):
            _, result = smooth(getme, pinned, extra, args.threads, workdir)
            print(row("vessel, whole boundary fixed", label, result))
        # The artery (curved, tapered, two branches, 6 inward + 2 outward layers, growth 1.2,
        # first layer 0.5 % of the wall edge), whole boundary fixed: issue 14's thin-layer case.
        for label, options in (("artery S, sharp junctions", ["--mesh-size", "0.5",
                                                              "--junction-fillet", "0"]),
                               ("artery M, rounded junctions", [])):
            artery = os.path.join(workdir, "artery.vtk")
            subprocess.run([meshgen, "artery", artery] + options, check=True, capture_output=True)
            for method, extra in (("getme", []), ("getme --no-polish", ["--no-polish"])):
                _, result = smooth(getme, artery, extra, args.threads, workdir)
                print(row(label + ", whole boundary fixed", method, result))


if __name__ == "__main__":
    sys.exit(main())
