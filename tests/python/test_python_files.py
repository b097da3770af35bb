#!/usr/bin/python3
"""getme.read / getme.write (client/python/getme/_files.py) through the real getme CLI, with
meshio's own readers as the independent reference: what getme.read returns must be what meshio
reads from the same file, and what getme.write writes must read back in meshio as the mesh
given. The error paths carry the CLI's message (which names the line) or the right exception.

Usage: test_python_files.py --package-dir build/python --cli-binary getme --hybrid VTK
         --shared-meshes DIR --work-dir DIR [unittest options]
"""

import argparse
import os
import sys
import unittest

import meshio
import numpy as np

ARGS = None
getme = None  # imported from --package-dir in setUpModule


def setUpModule():
    global getme
    sys.path.insert(0, ARGS.package_dir)
    import getme as package
    getme = package
    assert os.path.realpath(getme.__file__).startswith(os.path.realpath(ARGS.package_dir)), \
        getme.__file__
    os.makedirs(ARGS.work_dir, exist_ok=True)


def work_path(name):
    return os.path.join(ARGS.work_dir, name)


def cell_list(mesh):
    """Every cell as (meshio type, node tuple), in order, whatever the block split."""
    return [(block.type, tuple(int(n) for n in row)) for block in mesh.cells
            for row in block.data]


def volume_cells(mesh):
    return [c for c in cell_list(mesh) if c[0] in ("tetra", "hexahedron", "wedge", "pyramid")]


class ReadTest(unittest.TestCase):
    def test_vtk_reads_as_meshio_reads_it(self):
        ours = getme.read(ARGS.hybrid, cli=ARGS.cli_binary)
        reference = meshio.read(ARGS.hybrid)
        np.testing.assert_array_equal(ours.points, reference.points)
        self.assertEqual(cell_list(ours), cell_list(reference))
        self.assertEqual(len(cell_list(ours)), 2529)
        np.testing.assert_array_equal(np.concatenate(ours.cell_data["mean_ratio"]).ravel(),
                                      np.concatenate(reference.cell_data["mean_ratio"]).ravel())

    def test_cli_from_environment(self):
        os.environ["GETME_CLI"] = ARGS.cli_binary
        try:
            mesh = getme.read(ARGS.hybrid)
        finally:
            del os.environ["GETME_CLI"]
        self.assertEqual(len(mesh.points), 768)

    def test_missing_file(self):
        with self.assertRaises(FileNotFoundError) as caught:
            getme.read(work_path("no-such.vtk"), cli=ARGS.cli_binary)
        self.assertIn("no-such.vtk", str(caught.exception))

    def test_malformed_file_names_the_line(self):
        path = work_path("broken.msh")
        with open(path, "w") as f:
            f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n$EndNodes\n")
        with self.assertRaises(getme.FileError) as caught:
            getme.read(path, cli=ARGS.cli_binary)
        self.assertEqual(caught.exception.path, path)
        self.assertRegex(caught.exception.message, r"line 7")

    def test_unknown_format_name(self):
        with self.assertRaises(ValueError) as caught:
            getme.read(ARGS.hybrid, file_format="stl", cli=ARGS.cli_binary)
        self.assertIn("stl", str(caught.exception))

    def test_missing_cli(self):
        with self.assertRaises(FileNotFoundError):
            getme.read(ARGS.hybrid, cli=work_path("no-such-getme"))


class WriteTest(unittest.TestCase):
    def test_msh2_reads_back_in_meshio(self):
        mesh = meshio.read(ARGS.hybrid)
        path = work_path("written.msh")
        getme.write(path, mesh, file_format="msh2", binary=False, cli=ARGS.cli_binary)
        with open(path) as f:
            self.assertEqual(f.read(32).split("\n")[1], "2.2 0 8")
        back = meshio.read(path)
        np.testing.assert_array_equal(back.points, mesh.points)
        self.assertEqual(volume_cells(back), volume_cells(mesh))

    def test_binary_vtu_round_trip_through_read(self):
        mesh = meshio.read(ARGS.hybrid)
        path = work_path("written.vtu")
        getme.write(path, mesh, binary=True, cli=ARGS.cli_binary)
        with open(path, "rb") as f:
            self.assertNotIn(b'format="ascii"', f.read())
        back = getme.read(path, cli=ARGS.cli_binary)
        np.testing.assert_array_equal(back.points, mesh.points)
        self.assertEqual(cell_list(back), cell_list(mesh))

    def test_unwritable_format(self):
        mesh = meshio.read(ARGS.hybrid)
        with self.assertRaises(getme.FileError) as caught:
            getme.write(work_path("written.mesh"), mesh, binary=True, cli=ARGS.cli_binary)
        self.assertIn("binary", caught.exception.message)


class Su2Test(unittest.TestCase):
    """The shared SU2 file numbers 6,304 elements mirror-wise; getme.read hands them out in
    meshio's orders, renumbered (docs/formats.md, "SU2"); meshio's own SU2 reader leaves them
    inverted (and takes SU2's wedges for Gmsh prisms). The VTK twin of the file, read by meshio, is the reference geometry."""

    def test_mirrored_elements_come_out_valid(self):
        path = os.path.join(ARGS.shared_meshes, "su2", "knowles-mixed-beam.su2")
        ours = getme.read(path, cli=ARGS.cli_binary)
        twin = meshio.read(os.path.join(ARGS.shared_meshes, "su2", "knowles-mixed-beam.vtk"))
        np.testing.assert_allclose(ours.points, twin.points, rtol=0, atol=1e-12)
        ours_cells = volume_cells(ours)
        twin_cells = volume_cells(twin)
        self.assertEqual(len(ours_cells), len(twin_cells))
        # The same elements (as node sets; the twin lists them by type), and none inverted at
        # the corner checked, where 6,304 of the file's own rows are.
        self.assertEqual(sorted((t, sorted(n)) for t, n in ours_cells),
                         sorted((t, sorted(n)) for t, n in twin_cells))
        inverted = sum(1 for t, n in ours_cells if signed_volume(ours.points, t, n) <= 0)
        self.assertEqual(inverted, 0)


def signed_volume(points, cell_type, nodes):
    """6 × the volume of the element's first corner tetrahedron in meshio's node orders (tetra,
    pyramid and hexahedron as VTK; wedge as Gmsh): the corner at node 0 with its three
    neighbours in the order that is positive for a valid element."""
    p = points[list(nodes)]
    if cell_type == "tetra":
        a, b, c = p[1] - p[0], p[2] - p[0], p[3] - p[0]
    elif cell_type == "hexahedron":
        a, b, c = p[1] - p[0], p[3] - p[0], p[4] - p[0]
    elif cell_type == "pyramid":
        a, b, c = p[1] - p[0], p[3] - p[0], p[4] - p[0]
    else:  # wedge, Gmsh order: triangle (0, 1, 2) below (3, 4, 5)
        a, b, c = p[1] - p[0], p[2] - p[0], p[3] - p[0]
    return float(np.dot(np.cross(a, b), c))


if __name__ == "__main__":
    parser = argparse.ArgumentParser()
    parser.add_argument("--package-dir", required=True)
    parser.add_argument("--cli-binary", required=True)
    parser.add_argument("--hybrid", required=True)
    parser.add_argument("--shared-meshes", required=True)
    parser.add_argument("--work-dir", required=True)
    ARGS, rest = parser.parse_known_args()
    unittest.main(argv=[sys.argv[0], *rest])
