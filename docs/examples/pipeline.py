#!/usr/bin/python3
"""gmsh → getme → solver, in Python: mesh the vessel of vessel.geo with gmsh's API, smooth the
meshio.Mesh on a getme-server with live progress, and hand the smoothed mesh on (here: written as
.vtu, for ParaView or a solver that reads VTK XML), with every surface cell, tag and array kept.

Environment: GETME_SERVER (default 127.0.0.1:50051). Needs the getme package on the path
(pip install ./client/python, or PYTHONPATH=build/python)."""

import os
import pathlib

import gmsh
import meshio

import getme

server = os.environ.get("GETME_SERVER", "127.0.0.1:50051")
geometry = pathlib.Path(__file__).resolve().parent / "vessel.geo"

# 1. Mesh with gmsh: tetrahedra, prisms, hexahedra and pyramids, physical groups by name.
gmsh.initialize(["-noenv"], readConfigFiles=False)
gmsh.option.setNumber("General.Terminal", 0)
gmsh.open(str(geometry))
gmsh.model.mesh.generate(3)
gmsh.write("vessel.msh")
gmsh.finalize()

# 2. Smooth on the server; progress arrives while it runs.
mesh = meshio.read("vessel.msh")
def show(event):
    if event.phase_done:
        print(f"{event.phase:>12} done after {event.iteration} iterations: "
              f"q_min {event.q_min:.4f}, q_mean {event.q_mean:.4f}")

smoothed, report = getme.smooth(mesh, server, method="getme", progress=show)
print(f"q_min {report.before.q_min:.4f} -> {report.q_min:.4f}, "
      f"q_mean {report.before.q_mean:.4f} -> {report.q_mean:.4f} in {report.seconds:.2f} s")

# 3. Hand on: the same cells, tags and groups as gmsh wrote, with the smoothed points.
smoothed.write("vessel-smooth.vtu")
print("after:", getme.quality(smoothed, server).histogram)
