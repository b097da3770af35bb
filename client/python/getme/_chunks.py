"""Chunked upload and download of meshes, as the C++ chunker cuts them
(wire/getme_wire/mesh_chunker.cc): MeshChunk messages of about 1 MB, far below gRPC's 4 MB
message limit, field by field in declaration order, whole nodes and elements together; the
receiver appends every chunk's fields to the earlier ones. The field layout is
_wire.CHUNK_FIELDS."""

from __future__ import annotations

from typing import Iterator, List

import numpy as np

from getme._mesh import WireMesh
from getme._stubs import smoother_pb2
from getme._wire import CHUNK_FIELDS, DEFAULT_CHUNK_BYTES, ELEMENT_GROUPS, MIN_CHUNK_BYTES


def mesh_size(wire: WireMesh):
    """SmoothHeader.expected_size: lets the server refuse a mesh over its limits before upload."""
    return smoother_pb2.MeshSize(
        nodes=wire.nodes,
        **{group.field: len(getattr(wire, group.field)) // group.nodes for group in ELEMENT_GROUPS})


def _fields(wire: WireMesh):
    """(Mesh field, values, values per item, upper bound of encoded bytes per value) for the
    fields the mesh carries: a WireMesh has no node_ids (its node numbering is the points'
    order), and element_ids only when they differ from the wire's numbering."""
    fields = []
    for layout in CHUNK_FIELDS:
        values = getattr(wire, layout.field, None)
        if values is not None:
            fields.append((layout.field, values, layout.values_per_item, layout.bytes_per_value))
    return fields


def mesh_chunks(wire: WireMesh, chunk_bytes: int = DEFAULT_CHUNK_BYTES) -> Iterator:
    """MeshChunk messages whose fields concatenate to the mesh. A mesh with no data at all still
    yields one (empty) chunk, so the server sees it and can name the empty mesh."""
    budget_per_chunk = max(chunk_bytes, MIN_CHUNK_BYTES)
    chunk = smoother_pb2.MeshChunk()
    budget = budget_per_chunk
    added = False
    handed_out = False
    for name, values, per_item, bytes_per_value in _fields(wire):
        position = 0
        item_bytes = per_item * bytes_per_value
        while position < len(values):
            items = budget // item_bytes
            # At least one item per chunk, however small the budget, so the loop advances.
            if items == 0 and not added:
                items = 1
            if items == 0:
                yield chunk
                handed_out = True
                chunk, budget, added = smoother_pb2.MeshChunk(), budget_per_chunk, False
                continue
            end = min(len(values), position + items * per_item)
            getattr(chunk.mesh, name).extend(values[position:end].tolist())
            budget -= min(budget, (end - position) * bytes_per_value)
            position = end
            added = True
    if added or not handed_out:
        yield chunk


class CoordinateAssembler:
    """Collects the coordinates of result chunks (ResultOptions.coordinates_only)."""

    def __init__(self):
        self._parts: List[np.ndarray] = []
        self._count = 0

    def add(self, chunk) -> None:
        values = chunk.mesh.coordinates
        if len(values):
            self._parts.append(np.array(values, dtype=np.float64))
            self._count += len(values)

    @property
    def count(self) -> int:
        return self._count

    def points(self) -> np.ndarray:
        """The (n, 3) coordinates received."""
        if not self._parts:
            return np.zeros((0, 3), dtype=np.float64)
        return np.concatenate(self._parts).reshape(-1, 3)


__all__ = ["mesh_size", "mesh_chunks", "CoordinateAssembler", "DEFAULT_CHUNK_BYTES"]
