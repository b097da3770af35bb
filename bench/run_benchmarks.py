#!/usr/bin/python3
"""Runs every benchmark behind docs/benchmarks.md and stores the data in docs/benchmarks/.

Usage: bench/run_benchmarks.py BUILD_DIR [--quick] [--shared DIR] [--out DIR] [--repeats N]
                               [--work DIR] [--max-elements N] [--skip-service] [--skip-micro]
bench/run.sh builds first and then calls this, then bench/benchmarks_doc.py. Everything it writes
under --out (default docs/benchmarks) comes from the runs: machine.json (machine, date, commit,
commands), data/<group>/*.json and *.trace.jsonl (getme-bench), micro/*.json (Google Benchmark),
plots/*.svg (`getme report`). Meshes, generated or smoothed, stay in --work (default
BUILD_DIR/bench-work): the large ones must never be committed.
"""
import argparse
import csv
import datetime
import glob
import json
import os
import platform
import shlex
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
METHODS = "smart-laplace,simultaneous,sequential,getme,warpage"

# The Mesquite meshes of the paper-style tables, with Mesquite 2.99's final q_mean and time
# (../shared/meshes/README.md, issue 5): GETMe's time to reach q_mean − 0.005 is measured.
MESQUITE_REFERENCE = os.path.join(HERE, "driver", "mesquite_reference.tsv")


def read_mesquite_reference():
    with open(MESQUITE_REFERENCE, newline="") as f:
        rows = csv.DictReader((line for line in f if not line.startswith("#")), delimiter="\t")
        return [row for row in rows]


# Generated meshes in the roles of the paper's Sections 4.1–4.3, by getme-meshgen kind and
# arguments (the driver hands them to meshgen's own parser, so any kind meshgen knows plugs in by
# name). Until the paper-style generators (plate, ring, sized vessel) land, hybrid blocks of the
# same size stand in for plate and ring; replace the specs here when they do.
# name: (full spec, quick spec, extra getme-bench flags)
PAPER_MESHES = {
    "plate-like": ("hybrid --size 17 --seed 1", "hybrid --size 9 --seed 1", []),
    "ring-like": ("hybrid --size 23 --distortion 0.45 --seed 2",
                  "hybrid --size 11 --distortion 0.45 --seed 2", []),
    # Wall fixed, caps free (docs/thin-layers.md): the paper's aorta setting.
    "vessel": ("vessel --length 42 --bend-angle 1.5 --fix-wall --seed 1",
               "vessel --length 6 --fix-wall --seed 1", ["--free-boundary"]),
}

# Scaling: hybrid blocks of n³ cubes, about 6.3 n³ elements (11: 9,977; 24: 87,296), from ~10k
# to ~10M. Every size runs the same capped number of simultaneous iterations, so the cost per
# element-iteration compares across sizes; repeats shrink with size (a 10M run takes minutes).
SCALING_SIZES = [11, 26, 55, 117]
QUICK_SCALING_SIZES = [11, 26]
SCALING_ITERATIONS = 100
# The service-overhead mesh (~110k elements); the full run also smooths the largest scaling mesh
# completely, in-process and through the service (issue 5: 10M elements within the machine's RAM).
SERVICE_SIZE = 26


def approximate_elements(size):
    return int(6.3 * size ** 3)


def run(cmd, **kwargs):
    print("+ " + " ".join(shlex.quote(c) for c in cmd), file=sys.stderr, flush=True)
    return subprocess.run(cmd, check=True, **kwargs)


def output_of(cmd, default=""):
    try:
        return subprocess.run(cmd, check=True, capture_output=True, text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return default


def machine_header(build, mode, repeats, argv):
    cpu = ""
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    with open("/proc/meminfo") as f:
        mem_kb = int(f.readline().split()[1])
    compiler = ""
    cache = os.path.join(build, "CMakeCache.txt")
    build_type = ""
    if os.path.exists(cache):
        with open(cache) as f:
            for line in f:
                if line.startswith("CMAKE_CXX_COMPILER:"):
                    compiler = output_of([line.split("=", 1)[1].strip(), "--version"]).split("\n")[0]
                if line.startswith("CMAKE_BUILD_TYPE:"):
                    build_type = line.split("=", 1)[1].strip()
    commit = output_of(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], "unknown")
    dirty = output_of(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no"])
    return {
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
        "commit": commit + ("+local changes" if dirty else ""),
        "mode": mode,
        "repeats": repeats,
        "cpu": cpu,
        "cores": os.cpu_count(),
        "memory_gb": round(mem_kb / 1024 / 1024, 1),
        "kernel": platform.release(),
        "os": output_of(["sh", "-c", ". /etc/os-release && echo $PRETTY_NAME"]),
        "compiler": compiler,
        "build_type": build_type,
        "load_average_start": list(os.getloadavg()),
        "command": os.environ.get("GETME_BENCH_COMMAND") or " ".join(shlex.quote(a) for a in argv),
        "driver_commands": [],
    }


class Runner:
    def __init__(self, args):
        self.args = args
        self.bin = os.path.join(args.build, "bin")
        self.bench = os.path.join(self.bin, "getme-bench")
        self.work = args.work or os.path.join(args.build, "bench-work")
        self.data = os.path.join(args.out, "data")
        self.commands = []

    def getme_bench(self, group, extra):
        """Runs getme-bench into work/<group>; returns that directory."""
        work = os.path.join(self.work, group)
        os.makedirs(work, exist_ok=True)
        cmd = [self.bench, "--out", work]
        if "--repeats" not in extra:
            cmd += ["--repeats", str(self.args.repeats)]
        cmd += extra
        self.commands.append(" ".join(shlex.quote(c) for c in
                                      ["build/bin/getme-bench"] + cmd[1:2] + [f"<work>/{group}"] +
                                      cmd[3:]))
        # A failing measurement is recorded in its JSON and the table; the rest still counts.
        result = subprocess.run(cmd, stdout=subprocess.DEVNULL)
        if result.returncode not in (0, 1):
            raise SystemExit(f"getme-bench failed ({result.returncode}): {' '.join(cmd)}")
        return work

    def keep(self, group, work):
        """Copies the JSON and traces (not the meshes) of work into data/<group>."""
        target = os.path.join(self.data, group)
        os.makedirs(target, exist_ok=True)
        for path in glob.glob(os.path.join(work, "*.json")) + glob.glob(
                os.path.join(work, "*.trace.jsonl")):
            shutil.copy(path, target)

    def shared(self):
        mesquite = os.path.join(self.args.shared, "mesquite")
        work = None
        for row in read_mesquite_reference():
            if not row["mesh"].endswith(".vtk"):
                continue
            path = os.path.join(mesquite, row["mesh"])
            if not os.path.exists(path):
                print(f"note: {path} missing, skipped", file=sys.stderr)
                continue
            target = float(row["q_mean"]) - 0.005
            work = self.getme_bench("shared", ["--mesh", path, "--methods", METHODS,
                                               "--target-q-mean", f"{target:.4f}",
                                               "--write-meshes"])
        if work:
            self.keep("shared", work)

    def paper(self):
        work = None
        for name, (full, quick, flags) in PAPER_MESHES.items():
            spec = quick if self.args.quick else full
            work = self.getme_bench("generated", ["--generate", spec, "--name", name, "--methods",
                                                  METHODS, "--write-meshes"] + flags)
        if work:
            self.keep("generated", work)

    def scaling(self):
        sizes = QUICK_SCALING_SIZES if self.args.quick else SCALING_SIZES
        work = None
        for size in sizes:
            elements = approximate_elements(size)
            if elements > self.args.max_elements:
                continue
            repeats = max(1, min(self.args.repeats, 2_000_000 // elements))
            work = self.getme_bench("scaling", [
                "--generate", f"hybrid --size {size} --seed 1", "--name", f"hybrid-{size}",
                "--methods", "simultaneous", "--threads", "1,2", "--max-iterations",
                str(SCALING_ITERATIONS), "--repeats", str(repeats)])
        if work:
            self.keep("scaling", work)

    def service(self):
        sizes = [SERVICE_SIZE] if self.args.quick else [SERVICE_SIZE, SCALING_SIZES[-1]]
        work = None
        for size in sizes:
            if approximate_elements(size) > self.args.max_elements:
                continue
            # The largest mesh: one repeat, both threads (it is about memory and completion).
            extra = ["--threads", "1"] if size == SERVICE_SIZE else ["--threads", "2",
                                                                     "--repeats", "1"]
            work = self.getme_bench("service", [
                "--generate", f"hybrid --size {size} --seed 1", "--name", f"hybrid-{size}",
                "--methods", "getme", "--service"] + extra)
        if work:
            self.keep("service", work)

    def micro(self):
        """Runs every Google Benchmark executable of the build (getme_micro*, bench/micro)."""
        target = os.path.join(self.args.out, "micro")
        shutil.rmtree(target, ignore_errors=True)
        binaries = glob.glob(os.path.join(self.bin, "getme_micro*")) + glob.glob(
            os.path.join(self.bin, "getme-micro*"))
        for binary in sorted(binaries):
            os.makedirs(target, exist_ok=True)
            out = os.path.join(target, os.path.basename(binary) + ".json")
            cmd = [binary, "--benchmark_out_format=json", f"--benchmark_out={out}",
                   f"--benchmark_repetitions={self.args.repeats}",
                   "--benchmark_report_aggregates_only=true"]
            if self.args.quick:
                cmd.append("--benchmark_min_time=0.05")
            if os.path.basename(binary) == "getme_micro_bench":
                # Its own flag: the largest mesh of its size-dependent benchmarks.
                largest = 100_000 if self.args.quick else min(self.args.max_elements, 10_000_000)
                cmd.append(f"--max_elements={largest}")
            self.commands.append(" ".join(["build/bin/" + os.path.basename(binary)] + cmd[1:2] +
                                          ["--benchmark_out=<out>"] + cmd[3:]))
            print(f"+ {' '.join(cmd)}", file=sys.stderr, flush=True)
            run(cmd, stdout=subprocess.DEVNULL)

    def plots(self):
        """`getme report` on the getme trace of every table mesh: histograms and q against time."""
        plots = os.path.join(self.args.out, "plots")
        shutil.rmtree(plots, ignore_errors=True)
        os.makedirs(plots)
        getme = os.path.join(self.bin, "getme")
        for group in ("shared", "generated"):
            work = os.path.join(self.work, group)
            for measurement in sorted(glob.glob(os.path.join(work, "*.getme.t1.json"))):
                with open(measurement) as f:
                    m = json.load(f)
                if "error" in m:
                    continue
                stem = measurement[:-len(".json")]
                before = m["spec"] if m["source"] == "file" else os.path.join(work, m["mesh"] + ".vtk")
                picture = os.path.join(plots, os.path.basename(stem) + ".svg")
                run([getme, "report", before, stem + ".vtk", "--trace", stem + ".trace.jsonl",
                     "-o", picture, "--title", f"{m['mesh']}: getme"], stdout=subprocess.DEVNULL)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("build")
    parser.add_argument("--quick", action="store_true",
                        help="small meshes, 1 repeat, scaling to ~100k elements (minutes)")
    parser.add_argument("--shared", default=os.path.join(ROOT, "..", "shared", "meshes"))
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "benchmarks"))
    parser.add_argument("--work", help="scratch for meshes (default BUILD/bench-work)")
    parser.add_argument("--repeats", type=int, help="default: 1 with --quick, else 5")
    parser.add_argument("--max-elements", type=int, default=20_000_000,
                        help="skip scaling and service meshes larger than this")
    parser.add_argument("--skip-service", action="store_true")
    parser.add_argument("--skip-micro", action="store_true")
    args = parser.parse_args()
    if args.repeats is None:
        args.repeats = 1 if args.quick else 5
    if not os.path.exists(os.path.join(args.build, "bin", "getme-bench")):
        raise SystemExit(f"{args.build}/bin/getme-bench not found: build first (bench/run.sh)")

    header = machine_header(args.build, "quick" if args.quick else "full", args.repeats, sys.argv)
    runner = Runner(args)
    shutil.rmtree(runner.data, ignore_errors=True)
    shutil.rmtree(runner.work, ignore_errors=True)
    runner.shared()
    runner.paper()
    runner.scaling()
    if not args.skip_service:
        runner.service()
    if not args.skip_micro:
        runner.micro()
    runner.plots()
    header["load_average_end"] = list(os.getloadavg())
    header["driver_commands"] = runner.commands
    with open(os.path.join(args.out, "machine.json"), "w") as f:
        json.dump(header, f, indent=2)
        f.write("\n")


if __name__ == "__main__":
    main()
