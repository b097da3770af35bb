#!/usr/bin/python3
"""The Python client package `getme` (client/python, as built into build/python) against a real
getme-server, with the C++ CLI's local run as the reference: meshes read and written by meshio
(make_test_meshes.py), results compared with `getme smooth IN OUT.vtk` and `getme quality --json`
bit for bit, progress streams checked against the report, and the error paths.

Usage: test_python_client.py --package-dir build/python --server-binary getme-server
         --cli-binary getme --meshes DIR --work-dir DIR [unittest options]
"""

import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import time
import unittest

import grpc
import meshio
import numpy as np

from server_process import ServerProcess, unused_address

ARGS = None
SERVER = None
getme = None  # imported from --package-dir in setUpModule


def setUpModule():
    global SERVER, getme
    sys.path.insert(0, ARGS.package_dir)
    import getme as package
    getme = package
    # The package under test, not some other installed copy.
    assert os.path.realpath(getme.__file__).startswith(os.path.realpath(ARGS.package_dir)), \
        getme.__file__
    # Every progress event (no throttling), so the stream can be checked against the report.
    SERVER = ServerProcess(ARGS.server_binary, "--progress_interval=0s", "--workers=2")


def tearDownModule():
    code = SERVER.stop()
    if code != 0:
        raise AssertionError(f"getme-server exited {code}:\n{''.join(SERVER.log)}")


def mesh_path(name):
    """A mesh of make_test_meshes.py by name, or a path as it is."""
    return os.path.join(ARGS.meshes, name)


def manifest():
    with open(mesh_path("meshes.json")) as f:
        return json.load(f)


def run_cli(*args):
    completed = subprocess.run([ARGS.cli_binary, *args], capture_output=True, text=True,
                               timeout=120)
    if completed.returncode != 0:
        raise AssertionError(f"getme {' '.join(args)} failed: {completed.stderr}")
    return completed.stdout


def cli_smooth(name, *options):
    """The CLI's local (in-process) run, read back with meshio. ASCII output: meshio 5.0's
    VTK 5.1 reader takes a binary "int" array for int64 and fails on the CLI's `valid` array;
    the CLI prints doubles so that they read back exactly."""
    with tempfile.TemporaryDirectory(dir=ARGS.work_dir) as directory:
        out = os.path.join(directory, "out.vtk")
        stdout = run_cli("smooth", mesh_path(name), out, "--json", "--quiet", "--ascii", *options)
        result = [json.loads(line) for line in stdout.splitlines() if line.startswith("{")][-1]
        return meshio.read(out), result


def cli_quality(name, *options):
    return json.loads(run_cli("quality", mesh_path(name), "--json", *options))


def as_numpy(mesh):
    """(points, cells) with one array per volume type, concatenated over meshio's blocks."""
    cells = {}
    for block in mesh.cells:
        if block.type in ("tetra", "hexahedron", "wedge", "pyramid"):
            cells.setdefault(block.type, []).append(block.data)
    return mesh.points.copy(), {t: np.concatenate(parts) for t, parts in cells.items()}


class Chunks(unittest.TestCase):
    """The upload's chunking (getme._chunks), as the C++ client's MeshChunker does it."""

    def test_chunks_concatenate_to_the_mesh_in_whole_items_within_budget(self):
        from getme import _chunks, _mesh
        points, cells = as_numpy(meshio.read(mesh_path("surface.vtk")))
        wire = _mesh.to_wire(points, cells, fixed=[3, 5, 8])
        budget = 1000
        chunks = list(_chunks.mesh_chunks(wire, budget))
        self.assertGreater(len(chunks), 50)  # ~73 kB of values in 1 kB chunks
        sizes = {"coordinates": 3, "tetrahedra": 4, "hexahedra": 8, "wedges": 6, "pyramids": 5}
        for chunk in chunks:
            self.assertLessEqual(chunk.ByteSize(), budget + 64)
            for field, per_item in sizes.items():
                self.assertEqual(len(getattr(chunk.mesh, field)) % per_item, 0, field)
        for field in ("coordinates", "tetrahedra", "hexahedra", "wedges", "pyramids",
                      "fixed_nodes"):
            joined = [v for chunk in chunks for v in getattr(chunk.mesh, field)]
            self.assertEqual(joined, getattr(wire, field).tolist(), field)
        # Wedges go out in VTK order, the other types as given.
        self.assertEqual(wire.wedges.reshape(-1, 6).tolist(),
                         cells["wedge"][:, [0, 2, 1, 3, 5, 4]].tolist())
        self.assertEqual(wire.tetrahedra.reshape(-1, 4).tolist(), cells["tetra"].tolist())

    def test_an_empty_mesh_is_one_empty_chunk(self):
        from getme import _chunks, _mesh
        chunks = list(_chunks.mesh_chunks(_mesh.to_wire(np.zeros((0, 3)), {})))
        self.assertEqual(len(chunks), 1)
        self.assertEqual(chunks[0].ByteSize(), 0)

    def test_element_ids_only_when_cells_are_not_in_wire_order(self):
        from getme import _mesh
        mesh = meshio.read(mesh_path("surface.vtk"))  # triangles first, types interleaved
        wire = _mesh.to_wire(mesh.points, mesh.cells)
        counts = [len(b.data) for b in mesh.cells]
        starts = np.cumsum([0] + counts[:-1])
        expected = [i for t in ("tetra", "hexahedron", "wedge", "pyramid")
                    for b, start in zip(mesh.cells, starts) if b.type == t
                    for i in range(start, start + len(b.data))]
        self.assertEqual(wire.element_ids.tolist(), expected)
        points, cells = as_numpy(mesh)
        ordered = {t: cells[t] for t in ("tetra", "hexahedron", "wedge", "pyramid")}
        self.assertIsNone(_mesh.to_wire(points, ordered).element_ids)


class SmoothMeshio(unittest.TestCase):
    def test_points_match_the_cli_bit_for_bit(self):
        mesh = meshio.read(mesh_path("surface.vtk"))
        smoothed, report = getme.smooth(mesh, SERVER.address)
        reference, _ = cli_smooth("surface.vtk")
        self.assertIsInstance(smoothed, meshio.Mesh)
        self.assertEqual(smoothed.points.dtype, np.float64)
        self.assertTrue(np.array_equal(smoothed.points, reference.points))
        self.assertFalse(np.array_equal(smoothed.points, mesh.points), "nothing moved")
        self.assertGreater(report.q_min, report.before.q_min)

    def test_report_matches_the_cli(self):
        mesh = meshio.read(mesh_path("surface.vtk"))
        _, report = getme.smooth(mesh, SERVER.address)
        _, cli = cli_smooth("surface.vtk")
        self.assertEqual(report.before.q_min, cli["q_min_before"])
        self.assertEqual(report.before.q_mean, cli["q_mean_before"])
        self.assertEqual(report.q_min, cli["q_min"])
        self.assertEqual(report.q_mean, cli["q_mean"])
        self.assertEqual(report.invalid_elements, cli["invalid"])
        self.assertEqual(report.after.warpage_max, cli["warpage_max"])
        self.assertEqual(report.after.elements, cli["elements"])
        for phase in ("untangle", "simultaneous", "sequential", "laplace"):
            self.assertEqual(report.iterations[phase], cli[f"iterations_{phase}"], phase)
        self.assertEqual([(p.phase, p.iterations, p.q_min, p.q_mean) for p in report.phases],
                         [(p["phase"], p["iterations"], p["q_min"], p["q_mean"])
                          for p in cli["phases"]])
        self.assertEqual(sum(report.after.histogram), cli["elements"])
        self.assertEqual(len(report.histogram), 20)
        self.assertTrue(report.job_id)

    def test_surface_cells_and_data_come_back_untouched(self):
        mesh = meshio.read(mesh_path("surface.vtk"))
        original = meshio.read(mesh_path("surface.vtk"))
        smoothed, _ = getme.smooth(mesh, SERVER.address)
        self.assertEqual([b.type for b in smoothed.cells], [b.type for b in original.cells])
        self.assertIn("triangle", [b.type for b in smoothed.cells])
        self.assertIn("quad", [b.type for b in smoothed.cells])
        for got, want in zip(smoothed.cells, original.cells):
            self.assertTrue(np.array_equal(got.data, want.data), got.type)
        self.assertEqual(sorted(smoothed.cell_data), sorted(original.cell_data))
        for name, arrays in original.cell_data.items():
            for got, want in zip(smoothed.cell_data[name], arrays):
                self.assertTrue(np.array_equal(got, want), name)
        self.assertTrue(np.array_equal(smoothed.point_data["temperature"],
                                       original.point_data["temperature"]))
        # The input is left as it was, and the result does not share its arrays.
        self.assertTrue(np.array_equal(mesh.points, original.points))
        self.assertIsNot(smoothed.cells[0].data, mesh.cells[0].data)

    def test_point_data_fixed_matches_the_cli(self):
        mesh = meshio.read(mesh_path("fixed.vtk"))
        smoothed, _ = getme.smooth(mesh, SERVER.address)
        reference, _ = cli_smooth("fixed.vtk")
        self.assertTrue(np.array_equal(smoothed.points, reference.points))
        fixed = manifest()["fixed_nodes"]
        self.assertTrue(np.array_equal(smoothed.points[fixed], mesh.points[fixed]))
        free = np.setdiff1d(manifest()["interior_nodes"], fixed)
        moved = np.any(smoothed.points[free] != mesh.points[free], axis=1)
        self.assertGreater(moved.mean(), 0.9)

    def test_small_chunks_give_the_same_result(self):
        mesh = meshio.read(mesh_path("surface.vtk"))
        whole, _ = getme.smooth(mesh, SERVER.address)
        chunked, _ = getme.smooth(mesh, SERVER.address, chunk_bytes=2048)
        self.assertTrue(np.array_equal(whole.points, chunked.points))

    def test_method_and_max_iterations_match_the_cli(self):
        mesh = meshio.read(mesh_path("surface.vtk"))
        smoothed, report = getme.smooth(mesh, SERVER.address, method="smart-laplace",
                                        max_iterations=3, threads=2)
        reference, cli = cli_smooth("surface.vtk", "--method", "smart-laplace",
                                    "--max-iterations", "3")
        self.assertTrue(np.array_equal(smoothed.points, reference.points))
        self.assertEqual([p.phase for p in report.phases], ["smart_laplace"])
        self.assertEqual(report.phases[0].iterations, cli["phases"][0]["iterations"])
        self.assertLessEqual(report.phases[0].iterations, 3)
        self.assertEqual(report.threads, 2)

    def test_max_iterations_caps_both_polish_stages_as_the_cli_does(self):
        mesh = meshio.read(mesh_path("surface.vtk"))
        smoothed, report = getme.smooth(mesh, SERVER.address, max_iterations=2)
        reference, cli = cli_smooth("surface.vtk", "--max-iterations", "2")
        self.assertTrue(np.array_equal(smoothed.points, reference.points))
        self.assertEqual(report.iterations["polish"], cli["iterations_polish"])
        # Two stages run here (worst elements, then the mean; q_min is far above a third of q_mean,
        # so no worst-cluster stage), each capped at 2 sweeps.
        self.assertLessEqual(report.iterations["polish"], 4)
        self.assertGreaterEqual(report.iterations["polish"], 1)


class SmoothNumpy(unittest.TestCase):
    def test_tuple_in_tuple_out_matching_the_cli(self):
        points, cells = as_numpy(meshio.read(mesh_path("surface.vtk")))
        result, report = getme.smooth((points, cells), SERVER.address)
        reference, _ = cli_smooth("surface.vtk")
        self.assertIsInstance(result, tuple)
        self.assertEqual(len(result), 2)
        self.assertIs(result[1], cells)
        self.assertTrue(np.array_equal(result[0], reference.points))
        self.assertEqual(report.after.elements, sum(len(c) for c in cells.values()))

    def test_dict_in_dict_out(self):
        points, cells = as_numpy(meshio.read(mesh_path("surface.vtk")))
        result, _ = getme.smooth({"points": points, "cells": cells}, SERVER.address)
        reference, _ = cli_smooth("surface.vtk")
        self.assertEqual(sorted(result), ["cells", "points"])
        self.assertTrue(np.array_equal(result["points"], reference.points))

    def test_fixed_mask_and_index_list_match_point_data_fixed(self):
        points, cells = as_numpy(meshio.read(mesh_path("surface.vtk")))
        reference, _ = cli_smooth("fixed.vtk")
        fixed = manifest()["fixed_nodes"]
        mask = np.zeros(len(points), dtype=bool)
        mask[fixed] = True
        by_mask, _ = getme.smooth((points, cells), SERVER.address, fixed=mask)
        by_list, _ = getme.smooth((points, cells), SERVER.address, fixed=fixed)
        self.assertTrue(np.array_equal(by_mask[0], reference.points))
        self.assertTrue(np.array_equal(by_list[0], reference.points))
        self.assertTrue(np.array_equal(by_list[0][fixed], points[fixed]))

    def test_wedges_are_sent_in_vtk_order(self):
        """A regular Gmsh-order prism (meshio's wedge) must reach the server as a valid element
        of quality 1; sent unpermuted it would be inverted."""
        regular = meshio.read(mesh_path("regular.vtk"))
        report = getme.quality(as_numpy(regular), SERVER.address)
        self.assertEqual(report.by_type["wedge"].count, 1)
        self.assertAlmostEqual(report.by_type["wedge"].q_min, 1.0, delta=1e-12)


class Progress(unittest.TestCase):
    def test_every_event_in_order_with_a_final_one(self):
        mesh = meshio.read(mesh_path("surface.vtk"))
        events = []
        _, report = getme.smooth(mesh, SERVER.address, progress=events.append)
        self.assertTrue(all(isinstance(e, getme.ProgressEvent) for e in events))
        # The server throttles nothing here: sequence numbers run 1, 2, 3, ... without gaps.
        self.assertEqual([e.sequence for e in events], list(range(1, len(events) + 1)))
        self.assertTrue(events[-1].final)
        self.assertFalse(any(e.final for e in events[:-1]))
        self.assertEqual({e.job_id for e in events}, {report.job_id})
        phases = [e.phase for e in events if not e.final]
        order = ["simultaneous", "sequential", "polish"]
        self.assertEqual(sorted(set(phases), key=phases.index), order)
        self.assertEqual(phases, sorted(phases, key=order.index))
        # One event per simultaneous iteration (polish: per sweep), then each phase's end with the
        # state it hands on.
        self.assertEqual(sum(e.phase == "simultaneous" and not e.phase_done for e in events),
                         report.iterations["simultaneous"])
        self.assertEqual(sum(e.phase == "polish" and not (e.phase_done or e.final) for e in events),
                         report.iterations["polish"])
        self.assertGreaterEqual(report.iterations["polish"], 1)
        ends = [e for e in events if e.phase_done]
        self.assertEqual([(e.phase, e.iteration, e.q_min, e.q_mean) for e in ends],
                         [(p.phase, p.iterations, p.q_min, p.q_mean) for p in report.phases])
        self.assertEqual((events[-1].q_min, events[-1].q_mean), (report.q_min, report.q_mean))
        elapsed = [e.elapsed_seconds for e in events]
        self.assertEqual(elapsed, sorted(elapsed))

    def test_polish_false_ends_after_the_sequential_substep(self):
        mesh = meshio.read(mesh_path("surface.vtk"))
        events = []
        _, report = getme.smooth(mesh, SERVER.address, progress=events.append, polish=False)
        self.assertEqual(report.iterations["polish"], 0)
        self.assertEqual([p.phase for p in report.phases], ["simultaneous", "sequential"])
        self.assertNotIn("polish", {e.phase for e in events})

    def test_an_exception_in_the_callback_cancels_and_propagates(self):
        mesh = meshio.read(mesh_path("surface.vtk"))
        seen = []

        def stop_at_third(event):
            seen.append(event)
            if len(seen) == 3:
                raise KeyError("stop")

        with self.assertRaises(KeyError):
            getme.smooth(mesh, SERVER.address, progress=stop_at_third)
        self.assertEqual(len(seen), 3)
        # The server cancelled the job: GetJob (smoother.proto) tells its final state.
        from getme.v1 import smoother_pb2, smoother_pb2_grpc
        with grpc.insecure_channel(SERVER.address) as channel:
            stub = smoother_pb2_grpc.SmootherStub(channel)
            deadline = time.monotonic() + 10
            while True:
                job = stub.GetJob(smoother_pb2.GetJobRequest(job_id=seen[0].job_id), timeout=10)
                if job.state > smoother_pb2.JOB_STATE_RUNNING or time.monotonic() > deadline:
                    break
                time.sleep(0.05)
        self.assertEqual(smoother_pb2.JobState.Name(job.state), "JOB_STATE_CANCELLED")


class Quality(unittest.TestCase):
    def assert_matches_cli(self, report, cli):
        self.assertEqual(report.elements, cli["elements"])
        self.assertEqual(report.q_min, cli["q_min"])
        self.assertEqual(report.q_mean, cli["q_mean"])
        self.assertEqual(report.invalid_elements, cli["invalid"])
        self.assertEqual(report.warpage_max, cli["warpage_max"])
        self.assertEqual(report.warpage_mean, cli["warpage_mean"])
        self.assertEqual(report.histogram, cli["histogram"])
        for name, cli_name in (("tetra", "tetrahedron"), ("hexahedron", "hexahedron"),
                               ("wedge", "prism"), ("pyramid", "pyramid")):
            got, want = report.by_type[name], cli["by_type"][cli_name]
            self.assertEqual((got.count, got.q_min, got.q_mean, got.invalid_elements),
                             (want["count"], want["q_min"], want["q_mean"], want["invalid"]),
                             name)

    def test_matches_cli_json(self):
        report = getme.quality(meshio.read(mesh_path("surface.vtk")), SERVER.address)
        self.assertIsInstance(report, getme.QualityReport)
        self.assert_matches_cli(report, cli_quality("surface.vtk"))

    def test_bins(self):
        report = getme.quality(meshio.read(mesh_path("surface.vtk")), SERVER.address, bins=7)
        self.assertEqual(len(report.histogram), 7)
        self.assert_matches_cli(report, cli_quality("surface.vtk", "--bins", "7"))

    def test_invalid_elements_are_named_by_cell_index(self):
        report = getme.quality(meshio.read(mesh_path("inverted.vtk")), SERVER.address)
        cli = cli_quality("inverted.vtk")
        self.assert_matches_cli(report, cli)
        inverted = manifest()["inverted_cells"]
        self.assertEqual(sorted(report.first_invalid_elements), inverted)
        self.assertEqual(sorted(cli["first_invalid_cells"]), inverted)
        self.assertEqual([t.invalid_elements for t in report.by_type.values()], [1, 1, 1, 1])

    def test_regular_element_of_each_type_has_quality_one(self):
        report = getme.quality(meshio.read(mesh_path("regular.vtk")), SERVER.address)
        self.assert_matches_cli(report, cli_quality("regular.vtk"))
        for name, quality in report.by_type.items():
            self.assertEqual(quality.count, 1, name)
            self.assertEqual(quality.invalid_elements, 0, name)
            self.assertAlmostEqual(quality.q_min, 1.0, delta=1e-12, msg=name)


class Errors(unittest.TestCase):
    def assert_error(self, context, code, *fragments):
        error = context.exception
        self.assertIsInstance(error, getme.Error)
        self.assertEqual(error.code, code, error.details)
        for fragment in fragments:
            self.assertIn(fragment, error.details)
        self.assertIn(error.details, str(error))

    def test_invalid_mesh_without_untangling(self):
        # The server refuses it with FAILED_PRECONDITION (a valid request for a mesh in the
        # wrong state), naming the first invalid element by its cell index.
        mesh = meshio.read(mesh_path("inverted.vtk"))
        with self.assertRaises(getme.Error) as context:
            getme.smooth(mesh, SERVER.address, untangle=False)
        self.assert_error(context, grpc.StatusCode.FAILED_PRECONDITION, "invalid")
        named = re.search(r"element_ids: ([0-9, ]+)\)", context.exception.details)
        self.assertIsNotNone(named, context.exception.details)
        self.assertEqual(sorted(int(i) for i in named.group(1).split(", ")),
                         manifest()["inverted_cells"])

    def test_invalid_mesh_is_untangled_by_default(self):
        # An interior node pushed through its neighbours inverts elements that untangling can
        # repair (unlike inverted.vtk's cells, whose boundary nodes are fixed).
        mesh = meshio.read(mesh_path("surface.vtk"))
        mesh.points[manifest()["interior_nodes"][0]] += [1.2, 0, 0]
        smoothed, report = getme.smooth(mesh, SERVER.address)
        self.assertGreater(report.before.invalid_elements, 0)
        self.assertEqual(report.invalid_elements, 0)
        self.assertGreater(report.iterations["untangle"], 0)
        with tempfile.TemporaryDirectory(dir=ARGS.work_dir) as directory:
            tangled = os.path.join(directory, "tangled.vtk")
            meshio.write(tangled, mesh, file_format="vtk")
            reference, cli = cli_smooth(tangled)
        self.assertEqual(cli["invalid_before"], report.before.invalid_elements)
        self.assertTrue(np.array_equal(smoothed.points, reference.points))

    def test_node_index_out_of_range(self):
        points, cells = as_numpy(meshio.read(mesh_path("surface.vtk")))
        cells["tetra"][3, 2] = len(points) + 7
        with self.assertRaises(getme.Error) as context:
            getme.smooth((points, cells), SERVER.address)
        self.assert_error(context, grpc.StatusCode.INVALID_ARGUMENT, str(len(points) + 7),
                          "out of range")

    def test_fixed_node_out_of_range(self):
        points, cells = as_numpy(meshio.read(mesh_path("surface.vtk")))
        with self.assertRaises(getme.Error) as context:
            getme.smooth((points, cells), SERVER.address, fixed=[1, len(points)])
        self.assert_error(context, grpc.StatusCode.INVALID_ARGUMENT, "fixed_nodes",
                          str(len(points)))

    def test_parameter_out_of_range(self):
        mesh = meshio.read(mesh_path("regular.vtk"))
        with self.assertRaises(getme.Error) as context:
            getme.smooth(mesh, SERVER.address, simultaneous_rho=3.0)
        self.assert_error(context, grpc.StatusCode.INVALID_ARGUMENT, "simultaneous_rho")

    def test_unknown_parameters_are_a_type_error_before_any_call(self):
        mesh = meshio.read(mesh_path("regular.vtk"))
        with self.assertRaises(TypeError) as context:
            getme.smooth(mesh, unused_address(), sigma=1.0, max_iteration=5)
        self.assertIn("max_iteration, sigma", str(context.exception))

    def test_parameter_of_the_wrong_type(self):
        mesh = meshio.read(mesh_path("regular.vtk"))
        for params in ({"threads": "2"}, {"untangle": 1}, {"simultaneous_rho": "0.5"},
                       {"sequential_sigma": 0.8}):
            with self.assertRaises(TypeError, msg=str(params)):
                getme.smooth(mesh, unused_address(), **params)
        with self.assertRaises(ValueError):
            getme.smooth(mesh, unused_address(), method="gradient")

    def test_unsupported_cell_type(self):
        points = np.zeros((10, 3))
        with self.assertRaises(ValueError) as context:
            getme.smooth((points, {"tetra10": np.arange(10)[None, :]}), unused_address())
        self.assertIn("tetra10", str(context.exception))

    def test_server_down(self):
        mesh = meshio.read(mesh_path("regular.vtk"))
        with self.assertRaises(getme.Error) as context:
            getme.smooth(mesh, unused_address(), timeout=30)
        self.assert_error(context, grpc.StatusCode.UNAVAILABLE)
        with self.assertRaises(getme.Error) as context:
            getme.quality(mesh, unused_address(), timeout=30)
        self.assert_error(context, grpc.StatusCode.UNAVAILABLE)

    def test_timeout(self):
        mesh = meshio.read(mesh_path("surface.vtk"))
        with self.assertRaises(getme.Error) as context:
            getme.smooth(mesh, SERVER.address, timeout=0.001)
        self.assert_error(context, grpc.StatusCode.DEADLINE_EXCEEDED)


def layer_block():
    """A hexahedral boundary-layer block on the wall z = 0, 6 x 6 columns of 10 layers (1 % thick
    at the wall, growing 1.3 x), each interior column shifted sideways as a whole so that a
    sliding wall has an irregular grid to even out; as (points, cells), hexahedra in VTK order."""
    cells, layers = 6, 10
    z = np.concatenate([[0.0], np.cumsum(0.01 * 1.3 ** np.arange(layers))])
    points = []
    for k in range(layers + 1):
        for j in range(cells + 1):
            for i in range(cells + 1):
                x, y = float(i), float(j)
                if 0 < i < cells and 0 < j < cells:
                    x += 0.2 * math.sin(7.0 * i + 3.0 * j)
                    y += 0.2 * math.cos(5.0 * i + 11.0 * j)
                points.append((x, y, z[k]))

    def node(i, j, k):
        return i + (cells + 1) * (j + (cells + 1) * k)

    hexahedra = [[node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                  node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                  node(i, j + 1, k + 1)]
                 for k in range(layers) for j in range(cells) for i in range(cells)]
    return np.array(points), {"hexahedron": np.array(hexahedra, dtype=np.int64)}


class Boundary(unittest.TestCase):
    """boundary=, feature_angle= and keep_layers= (issue 15), against the CLI's local run."""

    def cli_reference(self, points, cells, *options):
        with tempfile.TemporaryDirectory(dir=ARGS.work_dir) as directory:
            path = os.path.join(directory, "layers.vtk")
            meshio.write(path, meshio.Mesh(points, list(cells.items())), file_format="vtk")
            return cli_smooth(path, *options)

    def test_slide_with_kept_layers_matches_the_cli_with_its_reports(self):
        points, cells = layer_block()
        (smoothed, _), report = getme.smooth((points, cells), SERVER.address, boundary="slide",
                                             keep_layers=True)
        reference, cli = self.cli_reference(points, cells, "--boundary", "slide", "--keep-layers")
        self.assertTrue(np.array_equal(smoothed, reference.points))
        self.assertEqual(report.boundary, "slide")
        self.assertEqual(cli["boundary"], "slide")
        slide = report.boundary_slide
        self.assertIsInstance(slide, getme.BoundarySlideReport)
        for key, value in cli["boundary_slide"].items():
            self.assertEqual(getattr(slide, key), value, key)
        self.assertGreater(slide.slid_nodes, 0)
        self.assertEqual((slide.feature_curves, slide.corners), (12, 8))  # a box
        layers = report.layers
        self.assertIsInstance(layers, getme.LayerReport)
        self.assertEqual(layers.columns, 36)
        for key in ("columns", "column_elements", "layer_nodes", "layers", "conflicting_nodes",
                    "ends", "max_height_change"):
            self.assertEqual(getattr(layers, key), cli["layers"][key], key)
        for state in ("before", "after"):
            for key, value in cli["layers"][state].items():
                self.assertEqual(getattr(getattr(layers, state), key), value, f"{state}.{key}")
        self.assertLessEqual(layers.max_height_change, 0.01)
        self.assertEqual(report.phases[0].phase, "layers")
        self.assertEqual(report.iterations["layers"],
                         sum(p.iterations for p in report.phases if p.phase == "layers"))
        self.assertGreaterEqual(report.iterations["layers"], 1)

    def test_tagged_faces_go_along_as_surface_groups(self):
        # A 4 x 4 x 4 hexahedral cube whose top quads are physical groups 7 (x < 2) and 8
        # (x > 2); top nodes moved within the top face, those on x = 2 along y only. The groups'
        # common line is a feature curve: its nodes keep x = 2 exactly. Untagged, it is an
        # ordinary face line and its nodes leave it.
        n = 4
        rng = np.random.default_rng(5)

        def node(i, j, k):
            return i + (n + 1) * (j + (n + 1) * k)

        points = np.array([(i, j, k) for k in range(n + 1) for j in range(n + 1)
                           for i in range(n + 1)], dtype=float)
        for k in range(n + 1):
            for j in range(1, n):
                for i in range(1, n):
                    p = node(i, j, k)
                    if 0 < k < n:
                        points[p] += rng.uniform(-0.3, 0.3, 3)
                    elif k == n:
                        points[p, 1] += rng.uniform(-0.3, 0.3)
                        if i != n // 2:
                            points[p, 0] += rng.uniform(-0.3, 0.3)
        hexahedra = np.array([[node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k),
                               node(i, j + 1, k), node(i, j, k + 1), node(i + 1, j, k + 1),
                               node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)]
                              for k in range(n) for j in range(n) for i in range(n)])
        quads = np.array([[node(i, j, n), node(i + 1, j, n), node(i + 1, j + 1, n),
                           node(i, j + 1, n)] for j in range(n) for i in range(n)])
        line = [node(n // 2, j, n) for j in range(1, n)]
        off_line = {}
        for tagged in (False, True):
            tags = np.array([7 if i < n // 2 else 8 for j in range(n) for i in range(n)])
            mesh = meshio.Mesh(points, [("hexahedron", hexahedra), ("quad", quads)],
                               cell_data={"gmsh:physical": [np.zeros(len(hexahedra), dtype=int),
                                                            tags if tagged else 0 * tags]})
            smoothed, report = getme.smooth(mesh, SERVER.address, boundary="slide")
            self.assertEqual(report.boundary_slide.surface_groups, 3 if tagged else 1)
            off_line[tagged] = max(abs(smoothed.points[p, 0] - 2.0) for p in line)
        self.assertEqual(off_line[True], 0.0)
        self.assertGreater(off_line[False], 1e-3)

    def test_a_held_or_free_boundary_reports_no_slide(self):
        points, cells = layer_block()
        _, report = getme.smooth((points, cells), SERVER.address, max_iterations=3)
        self.assertEqual(report.boundary, "fixed")
        self.assertIsNone(report.boundary_slide)
        self.assertIsNone(report.layers)
        self.assertEqual(report.iterations["layers"], 0)
        # free_boundary=True stays the spelling of boundary="free".
        for params in ({"free_boundary": True}, {"boundary": "free"}, {"boundary": "FREE"}):
            (smoothed, _), report = getme.smooth((points, cells), SERVER.address,
                                                 max_iterations=3, **params)
            self.assertEqual(report.boundary, "free", params)
            self.assertIsNone(report.layers, params)

    def test_feature_angle_reaches_the_server(self):
        points, cells = layer_block()
        # 91 degrees: the box's 90-degree edges are no features any more, and with one surface
        # group there are no group borders either: no feature edges, no corners.
        _, report = getme.smooth((points, cells), SERVER.address, boundary="slide",
                                 feature_angle=91, max_iterations=3)
        self.assertEqual((report.boundary_slide.feature_edges, report.boundary_slide.corners),
                         (0, 0))
        _, cli = self.cli_reference(points, cells, "--boundary", "slide", "--feature-angle", "91",
                                    "--max-iterations", "3")
        self.assertEqual(cli["boundary_slide"]["corners"], 0)

    def test_bad_values_name_the_keyword(self):
        points, cells = layer_block()
        with self.assertRaises(ValueError) as context:
            getme.smooth((points, cells), unused_address(), boundary="sideways")
        self.assertIn("boundary", str(context.exception))
        self.assertIn("fixed, slide, free", str(context.exception))
        with self.assertRaises(TypeError) as context:
            getme.smooth((points, cells), unused_address(), boundary=True)
        self.assertIn("boundary", str(context.exception))
        with self.assertRaises(TypeError) as context:
            getme.smooth((points, cells), unused_address(), feature_angle=30,
                         feature_angle_degrees=40)
        self.assertIn("feature_angle and feature_angle_degrees", str(context.exception))
        with self.assertRaises(TypeError) as context:
            getme.smooth((points, cells), unused_address(), keep_layers="yes")
        self.assertIn("keep_layers", str(context.exception))
        # Values and combinations the server refuses, naming the fields.
        refused = (
            ({"boundary": "slide", "feature_angle": 200}, ["feature_angle_degrees = 200"]),
            ({"feature_angle": 30}, ["feature_angle_degrees", "BOUNDARY_SLIDE"]),
            ({"boundary": "slide", "free_boundary": True},
             ["free_boundary = true", "boundary = BOUNDARY_SLIDE"]),
            ({"boundary": "free", "keep_layers": True},
             ["keep_layers = true", "boundary = BOUNDARY_FREE"]),
            ({"free_boundary": True, "keep_layers": True},
             ["keep_layers = true", "free_boundary = true"]),
        )
        for params, fragments in refused:
            with self.assertRaises(getme.Error, msg=str(params)) as context:
                getme.smooth((points, cells), SERVER.address, **params)
            self.assertEqual(context.exception.code, grpc.StatusCode.INVALID_ARGUMENT, params)
            for fragment in fragments:
                self.assertIn(fragment, context.exception.details, params)

    def test_parameter_names_list_the_keywords(self):
        names = getme.parameter_names()
        for name in ("boundary", "feature_angle", "feature_angle_degrees", "keep_layers",
                     "free_boundary"):
            self.assertIn(name, names)


def make_certificates(directory):
    """A CA and a server certificate for 127.0.0.1 (openssl CLI, EC keys); returns the paths."""
    def openssl(*args):
        subprocess.run(["openssl", *args], check=True, capture_output=True, timeout=60)
    paths = {name: os.path.join(directory, name)
             for name in ("ca.key", "ca.pem", "server.key", "server.csr", "server.pem", "ext")}
    openssl("req", "-x509", "-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:prime256v1", "-nodes",
            "-keyout", paths["ca.key"], "-out", paths["ca.pem"], "-days", "1", "-subj", "/CN=test CA")
    openssl("req", "-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:prime256v1", "-nodes",
            "-keyout", paths["server.key"], "-out", paths["server.csr"], "-subj", "/CN=127.0.0.1")
    with open(paths["ext"], "w") as f:
        f.write("subjectAltName=IP:127.0.0.1,DNS:localhost\n")
    openssl("x509", "-req", "-in", paths["server.csr"], "-CA", paths["ca.pem"], "-CAkey",
            paths["ca.key"], "-CAcreateserial", "-out", paths["server.pem"], "-days", "1",
            "-extfile", paths["ext"])
    return paths


class AccessControl(unittest.TestCase):
    """The package over TLS with a bearer token: the caller passes its own grpc.Channel, as
    docs/reliability.md shows; the server owns jobs by token."""

    TOKEN = "alice-0123456789abcdef"

    @classmethod
    def setUpClass(cls):
        cls.directory = tempfile.mkdtemp(dir=ARGS.work_dir)
        cls.paths = make_certificates(cls.directory)
        tokens = os.path.join(cls.directory, "tokens.txt")
        with open(tokens, "w") as f:
            f.write(f"# test tokens\nalice:{cls.TOKEN}\n")
        cls.server = ServerProcess(ARGS.server_binary, f"--tls_cert={cls.paths['server.pem']}",
                                   f"--tls_key={cls.paths['server.key']}",
                                   f"--auth_tokens_file={tokens}", "--http_listen=")
        with open(cls.paths["ca.pem"], "rb") as f:
            cls.ca = f.read()

    @classmethod
    def tearDownClass(cls):
        code = cls.server.stop()
        log = "".join(cls.server.log)
        if code != 0:
            raise AssertionError(f"getme-server exited {code}:\n{log}")
        if cls.TOKEN in log:
            raise AssertionError("the token appears in the server's log")

    def channel(self, token):
        credentials = grpc.ssl_channel_credentials(root_certificates=self.ca)
        if token is not None:
            credentials = grpc.composite_channel_credentials(
                credentials, grpc.access_token_call_credentials(token))
        return grpc.secure_channel(self.server.address, credentials)

    def test_token_over_tls_smooths(self):
        mesh = meshio.read(mesh_path("surface.vtk"))
        with self.channel(self.TOKEN) as channel:
            smoothed, report = getme.smooth(mesh, channel)
        self.assertEqual(report.invalid_elements, 0)
        self.assertGreaterEqual(report.after.q_min, report.before.q_min)
        self.assertEqual(smoothed.points.shape, mesh.points.shape)

    def test_wrong_or_missing_token_is_unauthenticated(self):
        mesh = meshio.read(mesh_path("surface.vtk"))
        for token in ("mallory-0123456789abcdef", None):
            with self.subTest(token=token), self.channel(token) as channel:
                with self.assertRaises(getme.Error) as context:
                    getme.quality(mesh, channel, timeout=30)
                self.assertEqual(context.exception.code, grpc.StatusCode.UNAUTHENTICATED)
                if token is not None:
                    self.assertNotIn(token, context.exception.details)

    def test_plaintext_is_refused(self):
        mesh = meshio.read(mesh_path("surface.vtk"))
        with self.assertRaises(getme.Error) as context:
            getme.quality(mesh, self.server.address, timeout=10)
        self.assertEqual(context.exception.code, grpc.StatusCode.UNAVAILABLE)


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--package-dir", required=True)
    parser.add_argument("--server-binary", required=True)
    parser.add_argument("--cli-binary", required=True)
    parser.add_argument("--meshes", required=True)
    parser.add_argument("--work-dir", required=True)
    ARGS, rest = parser.parse_known_args()
    os.makedirs(ARGS.work_dir, exist_ok=True)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)
