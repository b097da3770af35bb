#!/usr/bin/python3
"""Meshes whose worst elements touch the boundary (issue 15's sliding targets), made by gmsh.

    /usr/bin/python3 bench/boundary_meshes.py OUTDIR [--mesh-size H]

writes OUTDIR/sphere-slice.msh (the unit ball cut by the slab |z| < 0.06: tetrahedra about
1.5 deep, nearly every node on the boundary) and OUTDIR/shell.msh (the spherical shell between
radii 1 and 1.08: one to two tetrahedra through its thickness), both MSH 4.1 with their boundary
surfaces in physical groups, so that a sliding boundary keeps them apart. gmsh's own random seed
is fixed, so the files are the same on every run of the same gmsh.
"""

import argparse
import os
import sys

import gmsh


def mesh_and_write(path, mesh_size):
    gmsh.option.setNumber("Mesh.MeshSizeMin", mesh_size)
    gmsh.option.setNumber("Mesh.MeshSizeMax", mesh_size)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    gmsh.option.setNumber("Mesh.RandomSeed", 1)
    gmsh.option.setNumber("Mesh.Algorithm3D", 1)
    gmsh.model.occ.synchronize()
    for dim, tag in gmsh.model.getEntities(2):
        gmsh.model.addPhysicalGroup(2, [tag], tag)
    volumes = [tag for _, tag in gmsh.model.getEntities(3)]
    gmsh.model.addPhysicalGroup(3, volumes, 1)
    gmsh.model.mesh.generate(3)
    gmsh.write(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir")
    parser.add_argument("--mesh-size", type=float, default=0.08)
    args = parser.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    gmsh.initialize(readConfigFiles=False)
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.option.setNumber("General.NumThreads", 1)
    gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)

    gmsh.model.add("sphere-slice")
    ball = gmsh.model.occ.addSphere(0, 0, 0, 1)
    slab = gmsh.model.occ.addBox(-2, -2, -0.06, 4, 4, 0.12)
    gmsh.model.occ.intersect([(3, ball)], [(3, slab)])
    mesh_and_write(os.path.join(args.outdir, "sphere-slice.msh"), args.mesh_size)
    gmsh.model.remove()

    gmsh.model.add("shell")
    outer = gmsh.model.occ.addSphere(0, 0, 0, 1.08)
    inner = gmsh.model.occ.addSphere(0, 0, 0, 1.0)
    gmsh.model.occ.cut([(3, outer)], [(3, inner)])
    mesh_and_write(os.path.join(args.outdir, "shell.msh"), args.mesh_size)
    gmsh.finalize()
    return 0


if __name__ == "__main__":
    sys.exit(main())
