"""Chunked upload and download of meshes, as the C++ client does (client/remote/mesh_chunks.cc):
MeshChunk messages of about 1 MB, far below gRPC's 4 MB message limit, field by field in
declaration order, whole nodes and elements together; the receiver appends every chunk's fields
to the earlier ones."""

from __future__ import annotations

from typing import Iterator, List

import numpy as np

from getme._mesh import WireMesh
from getme._stubs import smoother_pb2

DEFAULT_CHUNK_BYTES = 1 << 20


def mesh_size(wire: WireMesh):
    """SmoothHeader.expected_size: lets the server refuse a mesh over its limits before upload."""
    return smoother_pb2.MeshSize(nodes=wire.nodes, tetrahedra=len(wire.tetrahedra) // 4,
                                 hexahedra=len(wire.hexahedra) // 8, wedges=len(wire.wedges) // 6,
                                 pyramids=len(wire.pyramids) // 5)


def _fields(wire: WireMesh):
    """(Mesh field, values, values per item, upper bound of encoded bytes per value): doubles
    are packed 8 bytes, uint32 varints at most 5, uint64 at most 10."""
    fields = [("coordinates", wire.coordinates, 3, 8), ("tetrahedra", wire.tetrahedra, 4, 5),
              ("hexahedra", wire.hexahedra, 8, 5), ("wedges", wire.wedges, 6, 5),
              ("pyramids", wire.pyramids, 5, 5), ("fixed_nodes", wire.fixed_nodes, 1, 5)]
    if wire.element_ids is not None:
        fields.append(("element_ids", wire.element_ids, 1, 10))
    return fields


def mesh_chunks(wire: WireMesh, chunk_bytes: int = DEFAULT_CHUNK_BYTES) -> Iterator:
    """MeshChunk messages whose fields concatenate to the mesh. A mesh with no data at all still
    yields one (empty) chunk, so the server sees it and can name the empty mesh."""
    budget_per_chunk = max(chunk_bytes, 64)
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
