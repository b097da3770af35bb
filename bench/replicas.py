#!/usr/bin/python3
"""Replicas sharing a job store (issue 18): throughput and latency of many small jobs through one
getme-server and through three replicas sharing one Redis, and the store's overhead on one
100k-element job against the in-process registry.

Usage: bench/replicas.py BUILD_DIR [--jobs 48] [--clients 6] [--repeats 5] [--work DIR]

Every job is the whole default run (`getme smooth IN OUT --server ADDR --quiet`, a real client
process: upload, queue, smoothing, progress, download, writing), so latency is what a pipeline
calling the CLI waits for. Clients send jobs round robin to the replicas. redis-server runs on a
free loopback port with nothing persisted. Prints Markdown tables for docs/benchmarks.md.
"""
import argparse
import concurrent.futures
import os
import re
import socket
import statistics
import subprocess
import sys
import tempfile
import time


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def wait_for(path, pattern, timeout=30):
    deadline = time.time() + timeout
    while time.time() < deadline:
        if os.path.exists(path):
            match = re.search(pattern, open(path, encoding="utf-8", errors="replace").read())
            if match:
                return match
        time.sleep(0.05)
    sys.exit(f"{path}: no match for {pattern!r} within {timeout} s")


class Cluster:
    """`replicas` getme-server processes, sharing a fresh redis-server when `store` is true."""

    def __init__(self, build, work, replicas, workers, store):
        self.processes = []
        self.addresses = []
        flags = [f"--workers={workers}", "--http_listen="]
        if store:
            port = free_port()
            redis_dir = tempfile.mkdtemp(dir=work)
            self.processes.append(subprocess.Popen(
                ["/usr/bin/redis-server", "--port", str(port), "--bind", "127.0.0.1", "--save", "",
                 "--appendonly", "no", "--dir", redis_dir],
                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL))
            time.sleep(0.3)
            flags.append(f"--job_store=redis://127.0.0.1:{port}")
        for i in range(replicas):
            log = os.path.join(work, f"replica-{store}-{i}-{time.time_ns()}.log")
            with open(log, "w", encoding="utf-8") as out:
                self.processes.append(subprocess.Popen(
                    [os.path.join(build, "bin", "getme-server"), "--listen=127.0.0.1:0"] + flags,
                    stdout=out, stderr=subprocess.STDOUT))
            port = wait_for(log, r"listening on port (\d+)").group(1)
            self.addresses.append(f"127.0.0.1:{port}")

    def close(self):
        for process in reversed(self.processes):
            process.terminate()
        for process in self.processes:
            process.wait(timeout=60)


def smooth(build, mesh, out, address):
    start = time.perf_counter()
    subprocess.run([os.path.join(build, "bin", "getme"), "smooth", mesh, out, "--server", address,
                    "--quiet"], check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def many_small_jobs(build, work, mesh, cluster, jobs, clients):
    def one(i):
        return smooth(build, mesh, os.path.join(work, f"small-{i}.vtk"),
                      cluster.addresses[i % len(cluster.addresses)])

    start = time.perf_counter()
    with concurrent.futures.ThreadPoolExecutor(clients) as pool:
        latencies = sorted(pool.map(one, range(jobs)))
    wall = time.perf_counter() - start
    return wall, latencies


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("build")
    parser.add_argument("--jobs", type=int, default=48)
    parser.add_argument("--clients", type=int, default=6)
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--work", default=tempfile.mkdtemp(prefix="getme-replicas-"))
    args = parser.parse_args()
    build = os.path.abspath(args.build)
    meshgen = os.path.join(build, "bin", "getme-meshgen")
    small = os.path.join(args.work, "tet-12.vtk")
    large = os.path.join(args.work, "hybrid-26.vtk")
    subprocess.run([meshgen, "tet", small, "--size", "12"], check=True, stdout=subprocess.DEVNULL)
    subprocess.run([meshgen, "hybrid", large, "--size", "26"], check=True,
                   stdout=subprocess.DEVNULL)

    print(f"| setup | jobs | clients | wall s | jobs/s | latency median s | latency p95 s |")
    print("|---|---|---|---|---|---|---|")
    for label, replicas, workers, store in [
            ("1 server, in-process registry, 2 workers", 1, 2, False),
            ("1 replica + Redis store, 2 workers", 1, 2, True),
            ("3 replicas + Redis store, 1 worker each", 3, 1, True)]:
        cluster = Cluster(build, args.work, replicas, workers, store)
        try:
            wall, latencies = many_small_jobs(build, args.work, small, cluster, args.jobs,
                                              args.clients)
        finally:
            cluster.close()
        p95 = latencies[min(len(latencies) - 1, int(0.95 * len(latencies)))]
        print(f"| {label} | {args.jobs} | {args.clients} | {wall:.2f} | {args.jobs / wall:.2f} | "
              f"{statistics.median(latencies):.3f} | {p95:.3f} |")

    print()
    print("| setup | one hybrid-26 job (116,906 elements), median of "
          f"{args.repeats} s (min–max) |")
    print("|---|---|")
    medians = {}
    for label, store in [("in-process registry", False), ("Redis store", True)]:
        cluster = Cluster(build, args.work, 1, 1, store)
        try:
            times = sorted(smooth(build, large, os.path.join(args.work, "large.vtk"),
                                  cluster.addresses[0]) for _ in range(args.repeats))
        finally:
            cluster.close()
        medians[store] = statistics.median(times)
        print(f"| {label} | {medians[store]:.3f} ({times[0]:.3f}–{times[-1]:.3f}) |")
    print(f"\nstore overhead: {100 * (medians[True] / medians[False] - 1):+.1f} %")


if __name__ == "__main__":
    main()
