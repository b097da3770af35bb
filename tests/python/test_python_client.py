#!/usr/bin/python3
"""A Python client of getme.v1.Smoother: generates stubs from the repo's protos with protoc and
grpc_python_plugin, starts getme-server on a free loopback port, smooths a distorted 3x3x3 hex
block in chunks, and checks the progress stream (in order, final event last) and the result
(q_mean improved, boundary nodes unmoved). Uses Debian's python3-grpcio and python3-protobuf."""

import argparse
import importlib
import os
import random
import socket
import subprocess
import sys
import tempfile
import time

PASSED = 0
FAILED = 0


def check(condition, what):
    global PASSED, FAILED
    if condition:
        PASSED += 1
        print(f"ok   {what}")
    else:
        FAILED += 1
        print(f"FAIL {what}")


def generate_stubs(proto_dir, out_dir):
    protos = [os.path.join("getme", "v1", name + ".proto")
              for name in ("mesh", "params", "quality", "smoother")]
    subprocess.run(["/usr/bin/protoc", "-I", proto_dir, f"--python_out={out_dir}",
                    f"--grpc_out={out_dir}",
                    "--plugin=protoc-gen-grpc=/usr/bin/grpc_python_plugin"] + protos,
                   check=True)
    for package in ("getme", os.path.join("getme", "v1")):
        open(os.path.join(out_dir, package, "__init__.py"), "a").close()
    sys.path.insert(0, out_dir)


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def hex_block(n, distortion, seed):
    """(n+1)^3 nodes, n^3 hexahedra in VTK order; interior nodes moved randomly."""
    rng = random.Random(seed)
    coordinates, interior = [], []
    for k in range(n + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                inside = 0 < i < n and 0 < j < n and 0 < k < n
                interior.append(inside)
                d = [rng.uniform(-distortion, distortion) if inside else 0.0 for _ in range(3)]
                coordinates += [i + d[0], j + d[1], k + d[2]]

    def node(i, j, k):
        return (k * (n + 1) + j) * (n + 1) + i

    hexahedra = []
    for k in range(n):
        for j in range(n):
            for i in range(n):
                hexahedra += [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k),
                              node(i, j + 1, k), node(i, j, k + 1), node(i + 1, j, k + 1),
                              node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)]
    return coordinates, hexahedra, interior


def requests(pb, coordinates, hexahedra, nodes_per_chunk):
    header = pb.SmoothHeader()
    header.result_options.coordinates_only = True
    header.expected_size.nodes = len(coordinates) // 3
    header.expected_size.hexahedra = len(hexahedra) // 8
    yield pb.SmoothRequest(header=header)
    # Several chunks on purpose: fields append across chunks.
    for start in range(0, len(coordinates), 3 * nodes_per_chunk):
        chunk = pb.MeshChunk()
        chunk.mesh.coordinates.extend(coordinates[start:start + 3 * nodes_per_chunk])
        yield pb.SmoothRequest(chunk=chunk)
    chunk = pb.MeshChunk()
    chunk.mesh.hexahedra.extend(hexahedra)
    yield pb.SmoothRequest(chunk=chunk)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--server-binary", required=True)
    parser.add_argument("--proto-dir", required=True)
    args = parser.parse_args()

    import grpc

    with tempfile.TemporaryDirectory() as stubs:
        generate_stubs(args.proto_dir, stubs)
        pb = importlib.import_module("getme.v1.smoother_pb2")
        pb_grpc = importlib.import_module("getme.v1.smoother_pb2_grpc")

        port = free_port()
        server = subprocess.Popen([args.server_binary, f"--listen=127.0.0.1:{port}"],
                                  stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            channel = grpc.insecure_channel(f"127.0.0.1:{port}")
            grpc.channel_ready_future(channel).result(timeout=30)
            stub = pb_grpc.SmootherStub(channel)

            coordinates, hexahedra, interior = hex_block(3, 0.3, seed=5)
            events, result, received, late_events = [], None, [], 0
            for response in stub.Smooth(requests(pb, coordinates, hexahedra, 20), timeout=120):
                kind = response.WhichOneof("kind")
                if kind == "progress":
                    late_events += result is not None
                    events.append(response.progress)
                elif kind == "result":
                    result = response.result
                else:
                    received.extend(response.chunk.mesh.coordinates)

            check(late_events == 0, "every progress event came before the result")
            check(len(events) >= 3, f"{len(events)} progress events arrived")
            check(all(b.sequence > a.sequence for a, b in zip(events, events[1:])),
                  "event sequence numbers increase")
            check(events and events[-1].final, "the last event is marked final")
            check(not any(e.final for e in events[:-1]), "no event before the last is final")
            simultaneous = [e for e in events if e.phase == pb.PHASE_SIMULTANEOUS]
            check(simultaneous and simultaneous[0].phase < pb.PHASE_SEQUENTIAL
                  and events.index(simultaneous[-1]) < max(
                      i for i, e in enumerate(events) if e.phase == pb.PHASE_SEQUENTIAL),
                  "simultaneous phase events come before sequential ones")
            check(all(b.iteration >= a.iteration for a, b in zip(simultaneous, simultaneous[1:])),
                  "iterations within a phase do not go back")
            check(result is not None, "a result arrived")
            if result is not None:
                check(result.after.q_mean > result.before.q_mean,
                      f"q_mean improved: {result.before.q_mean:.6f} -> {result.after.q_mean:.6f}")
                check(result.after.q_min >= result.before.q_min, "q_min did not drop")
                check(result.coordinates_only and result.nodes == len(coordinates) // 3,
                      "coordinates-only result for every node")
            check(len(received) == len(coordinates), "all coordinates came back")
            boundary_kept = all(received[3 * v:3 * v + 3] == coordinates[3 * v:3 * v + 3]
                                for v in range(len(interior)) if not interior[v])
            check(boundary_kept, "boundary nodes did not move")
            check(any(received[3 * v:3 * v + 3] != coordinates[3 * v:3 * v + 3]
                      for v in range(len(interior)) if interior[v]), "interior nodes moved")

            # An error path: a node index out of range is INVALID_ARGUMENT naming the node.
            bad = list(hexahedra)
            bad[5] = 999
            try:
                for _ in stub.Smooth(requests(pb, coordinates, bad, 1000), timeout=60):
                    pass
                check(False, "an out-of-range node index is refused")
            except grpc.RpcError as error:
                check(error.code() == grpc.StatusCode.INVALID_ARGUMENT and
                      "999" in error.details(),
                      f"out-of-range node index: {error.code().name}: {error.details()}")
            channel.close()
        finally:
            server.terminate()
            try:
                code = server.wait(timeout=30)
            except subprocess.TimeoutExpired:
                server.kill()
                code = -1
            check(code == 0, f"getme-server exits 0 on SIGTERM (got {code})")

    print(f"{PASSED} passed, {FAILED} failed")
    return 0 if FAILED == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
