"""getme: a Python client of getme-server, GETMe smoothing of mixed volume meshes (tetrahedra,
hexahedra, wedges/prisms, pyramids) over gRPC (service getme.v1.Smoother, proto/getme/v1).

    import meshio, getme

    mesh = meshio.read("in.vtk")
    smoothed, report = getme.smooth(mesh, "localhost:50051", method="getme",
                                    progress=lambda e: print(e.phase, e.iteration, e.q_min))
    print(report.before.q_min, "->", report.q_min)
    smoothed.write("out.vtk")

    report = getme.quality(mesh, "localhost:50051", bins=10)

Files in every format the getme CLI reads and writes (SU2, CGNS, OpenFOAM polyMesh, Exodus II,
Gmsh, VTK, MEDIT; docs/formats.md) come in and go out as meshio.Mesh objects through the CLI's
own readers and writers:

    mesh = getme.read("wing.su2")          # the getme CLI: GETME_CLI, else `getme` on PATH
    smoothed, report = getme.smooth(mesh, "localhost:50051")
    getme.write("wing-smooth.cgns", smoothed)

numpy input works without meshio: getme.smooth((points, {"tetra": tets, "wedge": prisms}))
returns (new_points, cells). Failed calls raise getme.Error (.code: grpc.StatusCode, .details:
the server's message); bad arguments raise TypeError / ValueError before anything is sent.

Depends on python3-grpcio, python3-protobuf and python3-numpy; meshio is optional (the package
never imports it: a meshio.Mesh is recognised by its attributes).
"""

from getme._client import DEFAULT_SERVER, quality, smooth
from getme._errors import Error
from getme._files import FileError, read, write
from getme._params import parameter_names
from getme._report import (BoundarySlideReport, LayerReport, LayerState, PhaseSummary,
                           ProgressEvent, QualityReport, SmoothReport, TypeQuality)

__version__ = "0.1.0"

__all__ = [
    "smooth", "quality", "read", "write", "Error", "FileError", "ProgressEvent", "SmoothReport", "QualityReport",
    "TypeQuality", "PhaseSummary", "BoundarySlideReport", "LayerReport", "LayerState",
    "parameter_names", "DEFAULT_SERVER",
]
