"""The caller's mesh (a meshio.Mesh or numpy arrays) ↔ the wire's getme.v1.Mesh fields.

Node orders: meshio's tetra, hexahedron and pyramid are VTK's, which is the wire's. meshio's
"wedge" is in Gmsh prism order (meshio permutes VTK wedges when it reads and writes VTK files),
while the wire wants VTK wedges, whose triangle (0, 1, 2) is mirrored (proto/getme/v1/mesh.proto,
docs/node-orders.md): both directions are the permutation _wire.PRISM_PERMUTATION. The element
types, their wire fields and node orders are the table _wire.ELEMENT_GROUPS.

Only what the wire cannot represent is checked here (shapes, negative or over-uint32 indices, a
`fixed` array of the wrong length); the server checks the mesh itself and names what is wrong
(INVALID_ARGUMENT), so a node index out of range gets the server's message.
"""

from __future__ import annotations

import copy
import dataclasses
from typing import Callable, Dict, List, Optional, Tuple

import numpy as np

from getme._wire import (ELEMENT_GROUPS, GROUP_BY_MESHIO, NODE_INDEX_MAX, PASSTHROUGH_CELLS,
                         SURFACE_TAG_ARRAYS)


@dataclasses.dataclass
class WireMesh:
    """The arrays of a getme.v1.Mesh, flat and in wire order; element_ids is None when the wire
    numbering (tetrahedra, hexahedra, wedges, pyramids, each in the order given) already is the
    caller's cell numbering."""
    coordinates: np.ndarray  # float64, 3 per node
    tetrahedra: np.ndarray  # int64 node indices, flat
    hexahedra: np.ndarray
    wedges: np.ndarray
    pyramids: np.ndarray
    fixed_nodes: np.ndarray
    element_ids: Optional[np.ndarray]
    # Surface groups of a sliding boundary (mesh.proto): tagged triangles and quads, flat, and
    # one tag per face; None when not sent.
    group_triangles: Optional[np.ndarray] = None
    group_quads: Optional[np.ndarray] = None
    triangle_groups: Optional[np.ndarray] = None
    quad_groups: Optional[np.ndarray] = None

    @property
    def nodes(self) -> int:
        return len(self.coordinates) // 3


@dataclasses.dataclass
class MeshInput:
    """A parsed input: its wire mesh and how to build the same kind of mesh with new points."""
    wire: WireMesh
    with_points: Callable[[np.ndarray], object]


def _blocks(cells) -> List[Tuple[str, object]]:
    """(type, data) per cell block, in the caller's order."""
    if isinstance(cells, dict):
        return list(cells.items())
    blocks = []
    for index, block in enumerate(cells):
        if hasattr(block, "type") and hasattr(block, "data"):
            blocks.append((block.type, block.data))
        elif isinstance(block, tuple) and len(block) == 2:
            blocks.append(block)
        else:
            raise TypeError(f"cell block {index}: expected a meshio.CellBlock or a (type, data) "
                            f"pair, got {type(block).__name__}")
    return blocks


def _points(points) -> np.ndarray:
    array = np.asarray(points)
    if array.ndim != 2 or array.shape[1] != 3:
        raise ValueError(f"points: expected an (n, 3) array, got shape {array.shape}")
    if array.dtype.kind not in "fiu":
        raise TypeError(f"points: expected numbers, got dtype {array.dtype}")
    return np.ascontiguousarray(array, dtype=np.float64)


def _node_indices(what: str, data, nodes_per_cell: int) -> np.ndarray:
    array = np.asarray(data)
    if array.ndim != 2 or array.shape[1] != nodes_per_cell:
        if array.size == 0:
            return np.zeros((0, nodes_per_cell), dtype=np.int64)
        raise ValueError(f"{what}: expected an (m, {nodes_per_cell}) array of node indices, got "
                         f"shape {array.shape}")
    if array.size == 0:
        return array.astype(np.int64)
    if array.dtype.kind not in "iu":
        raise TypeError(f"{what}: node indices must be integers, got dtype {array.dtype}")
    _check_index_range(what, array)
    return array.astype(np.int64, copy=False)


def _check_index_range(what: str, array: np.ndarray) -> None:
    """ValueError naming the first index the wire's uint32 cannot carry."""
    flat = array.reshape(-1)
    bad = np.flatnonzero((flat < 0) | (flat > NODE_INDEX_MAX))
    if bad.size:
        position = int(bad[0])
        if array.ndim == 2:
            where = f"cell {position // array.shape[1]}, node {position % array.shape[1]}"
        else:
            where = f"entry {position}"
        raise ValueError(f"{what}: node index {flat[position]} at {where} is not in "
                         f"[0, {NODE_INDEX_MAX}]")


def _fixed_from_argument(fixed, nodes: int) -> np.ndarray:
    array = np.asarray(fixed)
    if array.dtype == np.bool_:
        if array.shape != (nodes,):
            raise ValueError(f"fixed: a boolean mask needs one entry per point ({nodes}), got "
                             f"shape {array.shape}")
        return np.flatnonzero(array)
    if array.size == 0:
        return np.zeros(0, dtype=np.int64)
    if array.ndim != 1 or array.dtype.kind not in "iu":
        raise TypeError(f"fixed: expected a boolean mask or a list of node indices, got dtype "
                        f"{array.dtype} shape {array.shape}")
    _check_index_range("fixed", array)
    return array.astype(np.int64)


def _fixed_from_point_data(point_data, nodes: int) -> np.ndarray:
    """Nodes with a nonzero point-data value `fixed` (the CLI's convention, grid_mesh.h)."""
    if not point_data or "fixed" not in point_data:
        return np.zeros(0, dtype=np.int64)
    array = np.asarray(point_data["fixed"])
    if array.ndim == 2 and array.shape[1] == 1:
        array = array[:, 0]
    if array.shape != (nodes,):
        raise ValueError(f"point_data['fixed']: expected one value per point ({nodes}), got shape "
                         f"{array.shape}")
    return np.flatnonzero(array)


def to_wire(points, cells, point_data=None, fixed=None, with_fixed: bool = True) -> WireMesh:
    """The wire arrays for points and cells (dict or meshio cell blocks); fixed nodes are the
    union of `fixed` (boolean mask or index list) and a nonzero point_data['fixed']."""
    coordinates = _points(points)
    nodes = len(coordinates)
    per_field: Dict[str, List[np.ndarray]] = {group.field: [] for group in ELEMENT_GROUPS}
    ids_per_field: Dict[str, List[np.ndarray]] = {field: [] for field in per_field}
    first_cell = 0
    for index, (cell_type, data) in enumerate(_blocks(cells)):
        if cell_type in GROUP_BY_MESHIO:
            group = GROUP_BY_MESHIO[cell_type]
            array = _node_indices(f"cell block {index} ({cell_type})", data, group.nodes)
            if group.permutation is not None:
                array = array[:, group.permutation]
            per_field[group.field].append(array.reshape(-1))
            ids_per_field[group.field].append(np.arange(first_cell, first_cell + len(array)))
            first_cell += len(array)
        elif cell_type in PASSTHROUGH_CELLS or str(cell_type).startswith("polygon"):
            first_cell += len(data)
        else:
            raise ValueError(
                f"cell block {index}: cell type {cell_type!r} cannot be smoothed or passed through "
                f"(volume cells: {', '.join(GROUP_BY_MESHIO)}; passed through: "
                f"{', '.join(sorted(PASSTHROUGH_CELLS))})")

    def joined(parts: List[np.ndarray]) -> np.ndarray:
        return np.concatenate(parts) if parts else np.zeros(0, dtype=np.int64)

    element_ids = joined([ids for field in per_field for ids in ids_per_field[field]])
    if np.array_equal(element_ids, np.arange(len(element_ids))):
        element_ids = None
    fixed_nodes = np.zeros(0, dtype=np.int64)
    if with_fixed:
        fixed_nodes = _fixed_from_point_data(point_data, nodes)
        if fixed is not None:
            fixed_nodes = np.union1d(fixed_nodes, _fixed_from_argument(fixed, nodes))
        fixed_nodes = fixed_nodes.astype(np.int64)
    return WireMesh(coordinates=coordinates.reshape(-1), fixed_nodes=fixed_nodes,
                    element_ids=element_ids,
                    **{field: joined(parts) for field, parts in per_field.items()})


def add_surface_groups(wire: WireMesh, cells, cell_data) -> None:
    """Sets the wire's surface groups from the triangle and quad blocks that cell_data tags
    (SURFACE_TAG_ARRAYS: gmsh:physical, else medit:ref; one array per cell block, as meshio keeps
    them). Faces tagged 0 carry no group and are not sent, as the CLI does."""
    if not cell_data:
        return
    name = next((name for name in SURFACE_TAG_ARRAYS if name in cell_data), None)
    if name is None:
        return
    per_size = {3: ([], []), 4: ([], [])}
    for index, ((cell_type, data), tags) in enumerate(zip(_blocks(cells), cell_data[name])):
        size = {"triangle": 3, "quad": 4}.get(cell_type)
        if size is None:
            continue
        faces = _node_indices(f"cell block {index} ({cell_type})", data, size)
        tags = np.asarray(tags)
        if tags.shape != (len(faces),) or tags.dtype.kind not in "iu":
            raise ValueError(f"cell_data[{name!r}] of cell block {index} ({cell_type}): expected "
                             f"{len(faces)} integer tags, got shape {tags.shape}, "
                             f"dtype {tags.dtype}")
        tagged = tags != 0
        if np.any(tags[tagged] < 0) or np.any(tags[tagged] > NODE_INDEX_MAX):
            raise ValueError(f"cell_data[{name!r}] of cell block {index} ({cell_type}): surface "
                             f"group tags must be from 1 to {NODE_INDEX_MAX}")
        per_size[size][0].append(faces[tagged].reshape(-1))
        per_size[size][1].append(tags[tagged].astype(np.int64))

    def joined(parts):
        return np.concatenate(parts) if parts else np.zeros(0, dtype=np.int64)

    wire.group_triangles, wire.triangle_groups = joined(per_size[3][0]), joined(per_size[3][1])
    wire.group_quads, wire.quad_groups = joined(per_size[4][0]), joined(per_size[4][1])


def parse(mesh, fixed=None, with_fixed: bool = True, surface_groups: bool = False) -> MeshInput:
    """The wire mesh of `mesh`: a meshio.Mesh (or any object with points, cells as meshio cell
    blocks and point_data), a (points, cells[, point_data]) tuple, a dict with those keys, or an
    object with those attributes whose cells is a dict of numpy arrays. Without with_fixed, fixed
    nodes are neither read nor sent. With surface_groups, the triangles and quads that the
    cell_data tags (a meshio.Mesh's, or a dict's "cell_data") are sent as surface groups."""
    if isinstance(mesh, tuple):
        if len(mesh) not in (2, 3):
            raise TypeError(f"a mesh tuple is (points, cells) or (points, cells, point_data), got "
                            f"{len(mesh)} items")
        point_data = mesh[2] if len(mesh) == 3 else None
        wire = to_wire(mesh[0], mesh[1], point_data, fixed, with_fixed)
        return MeshInput(wire, lambda points: (points,) + mesh[1:])
    if isinstance(mesh, dict):
        if "points" not in mesh or "cells" not in mesh:
            raise TypeError("a mesh dict needs the keys 'points' and 'cells'")
        wire = to_wire(mesh["points"], mesh["cells"], mesh.get("point_data"), fixed, with_fixed)
        if surface_groups:
            add_surface_groups(wire, mesh["cells"], mesh.get("cell_data"))
        return MeshInput(wire, lambda points: {**mesh, "points": points})
    if hasattr(mesh, "points") and hasattr(mesh, "cells"):
        wire = to_wire(mesh.points, mesh.cells, getattr(mesh, "point_data", None), fixed,
                       with_fixed)
        if surface_groups:
            add_surface_groups(wire, mesh.cells, getattr(mesh, "cell_data", None))

        # A deep copy (cells, cell_data, point_data, field_data, sets: the result does not share
        # them with the input), with the new points in place of the old ones.
        def with_points(points):
            return copy.deepcopy(mesh, memo={id(mesh.points): points})

        return MeshInput(wire, with_points)
    raise TypeError(f"expected a meshio.Mesh, a (points, cells) tuple, or a dict or object with "
                    f"points and cells, got {type(mesh).__name__}")


__all__ = ["WireMesh", "MeshInput", "add_surface_groups", "parse", "to_wire"]
