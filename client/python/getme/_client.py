"""smooth() and quality(): the getme.v1.Smoother calls Smooth and EvaluateQuality."""

from __future__ import annotations

import contextlib
import numbers
from typing import Callable, Optional

import grpc

from getme import _chunks, _mesh, _params
from getme._errors import Error, from_rpc_error
from getme._report import ProgressEvent, QualityReport, SmoothReport
from getme._stubs import params_pb2, smoother_pb2, smoother_pb2_grpc

DEFAULT_SERVER = "localhost:50051"


@contextlib.contextmanager
def _channel(server):
    """A channel to "host:port" (closed afterwards), or the caller's grpc.Channel as it is."""
    if isinstance(server, grpc.Channel):
        yield server
        return
    # Results come in ~1 MB chunks, but a server may choose larger ones: do not refuse them.
    channel = grpc.insecure_channel(server, options=[("grpc.max_receive_message_length", -1)])
    try:
        yield channel
    finally:
        channel.close()


def _check_bins(bins) -> None:
    if isinstance(bins, bool) or not isinstance(bins, numbers.Integral) or not 1 <= bins < 2**32:
        raise ValueError(f"bins: expected a positive integer, got {bins!r}")


def _smooth_requests(header, wire, chunk_bytes):
    yield smoother_pb2.SmoothRequest(header=header)
    for chunk in _chunks.mesh_chunks(wire, chunk_bytes):
        yield smoother_pb2.SmoothRequest(chunk=chunk)


def _quality_requests(header, wire, chunk_bytes):
    yield smoother_pb2.EvaluateQualityRequest(header=header)
    for chunk in _chunks.mesh_chunks(wire, chunk_bytes):
        yield smoother_pb2.EvaluateQualityRequest(chunk=chunk)


def _protocol_error(call, message: str) -> Error:
    call.cancel()
    return Error(grpc.StatusCode.INTERNAL, message)


def _read_result(call, progress):
    """Reads a Smooth response stream: progress events, the SmoothResult, then mesh chunks (the
    order smoother.proto gives). A protocol violation cancels the call."""
    result = None
    assembler = _chunks.CoordinateAssembler()
    for response in call:
        kind = response.WhichOneof("kind")
        if kind == "progress":
            if result is not None:
                raise _protocol_error(call, "the server sent a progress event after the result")
            if progress is not None:
                progress(ProgressEvent.from_proto(response.progress))
        elif kind == "result":
            if result is not None:
                raise _protocol_error(call, "the server sent two results")
            result = response.result
        elif kind == "chunk":
            if result is None:
                raise _protocol_error(call, "the server sent mesh chunks before the result")
            assembler.add(response.chunk)
        else:
            raise _protocol_error(call, "the server sent an empty SmoothResponse")
    if result is None:
        raise Error(grpc.StatusCode.INTERNAL, "the server ended the stream without a result")
    if assembler.count != 3 * result.nodes:
        raise Error(grpc.StatusCode.FAILED_PRECONDITION,
                    f"the result stream ended with {assembler.count} coordinates, but the result "
                    f"announced {result.nodes} nodes ({3 * result.nodes} coordinates)")
    return result, assembler.points()


def smooth(mesh, server=DEFAULT_SERVER, *,
           progress: Optional[Callable[[ProgressEvent], None]] = None,
           timeout: Optional[float] = None, fixed=None, bins: int = 20,
           chunk_bytes: int = _chunks.DEFAULT_CHUNK_BYTES, **params):
    """Smooths a mixed volume mesh on a getme-server; returns (smoothed_mesh, SmoothReport).

    mesh: a meshio.Mesh, or numpy arrays: a (points, cells) or (points, cells, point_data)
      tuple, a dict with keys "points", "cells" (and optionally "point_data"), or an object with
      those attributes. points is an (n, 3) array; cells maps "tetra" (m, 4), "hexahedron"
      (m, 8), "wedge" (m, 6) and "pyramid" (m, 5) to node indices, in meshio's node orders (a
      meshio "wedge" is a Gmsh prism: the client mirrors it to the wire's VTK wedge and back).
      Cells of type vertex, line, triangle, quad, polygon and pixel are not sent: they come back
      untouched with their cell data and follow their nodes. Any other cell type (e.g. tetra10)
      is a ValueError.
    server: "host:port" or a grpc.Channel.
    progress: called with a getme.ProgressEvent for every event the server streams, in order;
      the last one has final set. An exception it raises cancels the job and propagates.
    timeout: seconds until the call fails with DEADLINE_EXCEEDED (the server stops the job too);
      None waits as long as it takes.
    fixed: nodes that must not move, as a boolean mask over the points or a list of node
      indices; nodes with a nonzero point_data "fixed" value are fixed as well. Boundary nodes
      are fixed unless boundary="slide" or boundary="free" says otherwise.
    bins: histogram bins of the reports.
    chunk_bytes: upload message size (about 1 MB by default).
    params: getme.v1.SmoothingParameters fields by name (proto/getme/v1/params.proto), e.g.
      method="getme" (or "simultaneous", "sequential", "warpage", "smart_laplace", "laplace"),
      threads=2, untangle=False, sequential_sigma={"tetra": 0.8};
      max_iterations=N caps every phase, as the CLI's --max-iterations. Unset fields take the
      paper's defaults. An unknown name is a TypeError naming it.
      The boundary, as the CLI's --boundary, --feature-angle and --keep-layers
      (docs/boundary-service.md): boundary="fixed" (the default: boundary nodes stay), "slide"
      (they move along the input's own surface, feature-edge nodes along their edge, corners
      stay) or "free" (they move like the others; free_boundary=True is the older spelling);
      feature_angle=DEG (with boundary="slide": faces meeting at more than DEG degrees have a
      feature edge between them, default 45; the proto's feature_angle_degrees); keep_layers=True
      (boundary-layer columns keep every layer's height; not with boundary="free"). An unknown
      boundary name is a ValueError naming the keyword; a value the server refuses (an angle
      outside [0, 180], free_boundary=True with boundary="slide", ...) an INVALID_ARGUMENT
      getme.Error naming the fields. The report's boundary_slide and layers say what they did.
      With boundary="slide", triangles and quads that the mesh's cell_data tags (gmsh:physical,
      else medit:ref) are sent as surface groups: a node never leaves its group, and group
      borders are feature curves, as with the CLI.

    Returns the smoothed mesh as the same kind as the input (a meshio.Mesh, a deep copy with the
    new points, for a meshio.Mesh; a tuple or dict sharing the input's cells for a tuple or
    dict) with float64 points, and a getme.SmoothReport. Cell and point data come back as given
    (per-cell quality is not part of the wire result; the report carries the statistics).

    Raises getme.Error (with .code, a grpc.StatusCode, and .details, the server's message) when
    the call fails: INVALID_ARGUMENT for a mesh or parameter the server refuses, UNAVAILABLE
    when the server cannot be reached, DEADLINE_EXCEEDED, RESOURCE_EXHAUSTED (queue full), ...
    """
    parameters = _params.to_proto(params)
    _check_bins(bins)
    # A sliding boundary keeps its nodes in the input's surface groups: the tagged faces go along.
    parsed = _mesh.parse(mesh, fixed,
                         surface_groups=parameters.boundary == params_pb2.BOUNDARY_SLIDE)
    header = smoother_pb2.SmoothHeader(
        parameters=parameters,
        result_options=smoother_pb2.ResultOptions(coordinates_only=True, histogram_bins=bins),
        expected_size=_chunks.mesh_size(parsed.wire))
    with _channel(server) as channel:
        stub = smoother_pb2_grpc.SmootherStub(channel)
        call = stub.Smooth(_smooth_requests(header, parsed.wire, chunk_bytes), timeout=timeout)
        try:
            result, points = _read_result(call, progress)
        except grpc.RpcError as error:
            raise from_rpc_error(error) from None
        except BaseException:
            # A failing progress callback or Ctrl-C: stop the job on the server, then propagate.
            call.cancel()
            raise
    if len(points) != parsed.wire.nodes:
        raise Error(grpc.StatusCode.FAILED_PRECONDITION,
                    f"the server returned {len(points)} nodes for a mesh of {parsed.wire.nodes}")
    return parsed.with_points(points), SmoothReport.from_proto(result)


def quality(mesh, server=DEFAULT_SERVER, bins: int = 20, *, timeout: Optional[float] = None,
            chunk_bytes: int = _chunks.DEFAULT_CHUNK_BYTES) -> QualityReport:
    """The mean ratio quality of a mesh's volume elements, evaluated on a getme-server, as a
    getme.QualityReport with a histogram of `bins` bins. mesh, server and timeout as in
    smooth(); fixed nodes play no part. Raises getme.Error as smooth() does."""
    _check_bins(bins)
    parsed = _mesh.parse(mesh, with_fixed=False)
    header = smoother_pb2.EvaluateQualityHeader(histogram_bins=bins,
                                                expected_size=_chunks.mesh_size(parsed.wire))
    with _channel(server) as channel:
        stub = smoother_pb2_grpc.SmootherStub(channel)
        try:
            report = stub.EvaluateQuality(_quality_requests(header, parsed.wire, chunk_bytes),
                                          timeout=timeout)
        except grpc.RpcError as error:
            raise from_rpc_error(error) from None
    return QualityReport.from_proto(report)


__all__ = ["smooth", "quality", "DEFAULT_SERVER"]
