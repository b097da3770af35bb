"""The package's one mirror of the wire mappings (the C++ side's wire/getme_wire/): how meshio's
cell types, parameter keys and report fields map to getme.v1's fields, the node order of the
wire, the chunk layout, and the names of the wire's enums. The other modules take these from here
and keep no table of their own.
"""

from __future__ import annotations

from typing import List, NamedTuple, Optional, Tuple

from getme._stubs import params_pb2, smoother_pb2

# The one prism permutation, mirroring core/getme/elements/node_orders.h (kVtkWedgeToPaperPrism)
# and docs/node-orders.md. meshio's "wedge" is in Gmsh's prism order, which is the paper's, while
# the wire (proto/getme/v1/mesh.proto) sends VTK wedges, whose triangle (0, 1, 2) is mirrored. The
# permutation is its own inverse: it converts meshio → wire and wire → meshio alike.
PRISM_PERMUTATION = (0, 2, 1, 3, 5, 4)


class ElementGroup(NamedTuple):
    """One element type as meshio, the wire and the parameters name it (the C++ side's
    kWireElementGroups, wire/getme_wire/mesh_fields.h)."""
    meshio: str  # meshio cell type
    field: str  # getme.v1.Mesh field (and MeshSize field)
    name: str  # one element of the field
    nodes: int  # nodes per element
    permutation: Optional[Tuple[int, ...]]  # meshio → wire node order (and back); None: the same
    parameter_key: str  # getme.v1.PerType field
    report_field: str  # getme.v1.QualityReport's TypeQuality field


# In the order of the wire's element numbering (tetrahedra, hexahedra, wedges, pyramids). meshio's
# tetra, hexahedron and pyramid are numbered as VTK numbers them, which is the wire's order.
ELEMENT_GROUPS = (
    ElementGroup("tetra", "tetrahedra", "tetrahedron", 4, None, "tetrahedron", "tetrahedra"),
    ElementGroup("hexahedron", "hexahedra", "hexahedron", 8, None, "hexahedron", "hexahedra"),
    ElementGroup("wedge", "wedges", "wedge", 6, PRISM_PERMUTATION, "prism", "wedges"),
    ElementGroup("pyramid", "pyramids", "pyramid", 5, None, "pyramid", "pyramids"),
)
GROUP_BY_MESHIO = {group.meshio: group for group in ELEMENT_GROUPS}

# Linear cells of dimension 0–2 (VTK vertex … quad, as meshio names them): not sent, returned
# untouched; they follow their nodes, as in the CLI (client/formats/vtk_cell_type.h).
PASSTHROUGH_CELLS = frozenset({"vertex", "line", "triangle", "quad", "polygon", "pixel"})

# Node indices (connectivity, fixed_nodes) are uint32 on the wire.
NODE_INDEX_MAX = 2**32 - 1

# PerType keys: the proto's names, and meshio's names for the same types (a meshio "wedge" is the
# engine's prism).
PER_TYPE_KEYS = {
    **{group.parameter_key: group.parameter_key for group in ELEMENT_GROUPS},
    **{group.meshio: group.parameter_key for group in ELEMENT_GROUPS},
}


class ChunkField(NamedTuple):
    """A repeated field of getme.v1.Mesh as the chunker cuts it."""
    field: str
    values_per_item: int  # values of one node, element or id, kept in one chunk
    bytes_per_value: int  # upper bound of the encoded bytes of one value


# The fields of getme.v1.Mesh in declaration order, mirroring kFields of
# wire/getme_wire/mesh_chunker.cc: doubles are packed 8 bytes, uint32 varints take at most 5,
# uint64 varints at most 10.
CHUNK_FIELDS = (
    ChunkField("coordinates", 3, 8),
    *(ChunkField(group.field, group.nodes, 5) for group in ELEMENT_GROUPS),
    ChunkField("fixed_nodes", 1, 5),
    ChunkField("node_ids", 1, 10),
    ChunkField("element_ids", 1, 10),
    ChunkField("group_triangles", 3, 5),
    ChunkField("group_quads", 4, 5),
    ChunkField("triangle_groups", 1, 5),
    ChunkField("quad_groups", 1, 5),
)
# Cell data that tags triangles and quads with their surface group, first found first: gmsh's
# physical groups, MEDIT references, SU2 markers, CGNS boundary conditions, OpenFOAM patches,
# Exodus side sets (as `getme smooth` reads them: kGroupTagArrays, client/formats/mesh_file.cc).
SURFACE_TAG_ARRAYS = ("gmsh:physical", "medit:ref", "su2:tag", "cgns:bc", "openfoam:patch",
                      "exodus:sideset")
# About 1 MB per chunk (kDefaultChunkBytes, wire/getme_wire/mesh_chunker.h), far below gRPC's
# 4 MB message limit; a smaller budget is raised to MIN_CHUNK_BYTES.
DEFAULT_CHUNK_BYTES = 1 << 20
MIN_CHUNK_BYTES = 64


class IterationCounter(NamedTuple):
    """A phase whose iterations the result counts and the parameters cap."""
    phase: str  # as phase_name() names it
    result_field: str  # getme.v1.SmoothResult's count
    max_iterations_field: Optional[str]  # getme.v1.SmoothingParameters' cap; None: none


ITERATION_COUNTERS = (
    IterationCounter("untangle", "iterations_untangle", "untangle_max_iterations"),
    IterationCounter("simultaneous", "iterations_simultaneous", "simultaneous_max_iterations"),
    IterationCounter("sequential", "iterations_sequential", "sequential_max_iterations"),
    IterationCounter("laplace", "iterations_laplace", "laplace_max_iterations"),
    IterationCounter("polish", "iterations_polish", "polish_max_sweeps"),
    # Passes over the kept boundary-layer columns (keep_layers): a few, with no cap of their own.
    IterationCounter("layers", "iterations_layers", None),
)

# Keywords of smooth() that spell a getme.v1.SmoothingParameters field otherwise: the CLI's
# --feature-angle.
PARAMETER_ALIASES = {"feature_angle": "feature_angle_degrees"}

# Why kept boundary-layer columns stop (getme.v1.LayerReport's ends_* fields), named as the CLI's
# --json names them.
LAYER_ENDS = ("tetrahedron", "pyramid", "prism_side", "isotropic", "other_column", "boundary")

_PHASE_PREFIX = "PHASE_"
_METHOD_PREFIX = "METHOD_"
_BOUNDARY_PREFIX = "BOUNDARY_"


def phase_name(phase: int) -> str:
    """"simultaneous" for PHASE_SIMULTANEOUS; "unspecified" for 0; "phase_N" for unknown N."""
    try:
        name = smoother_pb2.Phase.Name(phase)
    except ValueError:
        return f"phase_{phase}"
    return name[len(_PHASE_PREFIX):].lower()


def method_value(name: str) -> Optional[int]:
    """The getme.v1.Method of "getme", "smart-laplace", "METHOD_LAPLACE", ... (any case); None
    for an unknown name."""
    key = name.strip().upper().replace("-", "_")
    if not key.startswith(_METHOD_PREFIX):
        key = _METHOD_PREFIX + key
    if key in params_pb2.Method.keys():
        return params_pb2.Method.Value(key)
    return None


def method_names() -> List[str]:
    """The method names method_value() knows, lower case without prefix, in the proto's order
    (METHOD_UNSPECIFIED left out)."""
    return [key[len(_METHOD_PREFIX):].lower() for key in params_pb2.Method.keys()
            if key != _METHOD_PREFIX + "UNSPECIFIED"]


def is_method(value: int) -> bool:
    """Whether `value` is a getme.v1.Method value."""
    return value in params_pb2.Method.values()


def boundary_value(name: str) -> Optional[int]:
    """The getme.v1.Boundary of "fixed", "slide", "free" or "BOUNDARY_SLIDE", ... (any case);
    None for an unknown name."""
    key = name.strip().upper()
    if not key.startswith(_BOUNDARY_PREFIX):
        key = _BOUNDARY_PREFIX + key
    if key in params_pb2.Boundary.keys() and key != _BOUNDARY_PREFIX + "UNSPECIFIED":
        return params_pb2.Boundary.Value(key)
    return None


def boundary_names() -> List[str]:
    """"fixed", "slide", "free": the names boundary_value() knows, in the proto's order."""
    return [key[len(_BOUNDARY_PREFIX):].lower() for key in params_pb2.Boundary.keys()
            if key != _BOUNDARY_PREFIX + "UNSPECIFIED"]


def boundary_name(value: int) -> str:
    """"slide" for BOUNDARY_SLIDE; "unspecified" for 0 (a server that predates the field);
    "boundary_N" for unknown N."""
    try:
        name = params_pb2.Boundary.Name(value)
    except ValueError:
        return f"boundary_{value}"
    return name[len(_BOUNDARY_PREFIX):].lower()


__all__ = [
    "PRISM_PERMUTATION", "ElementGroup", "ELEMENT_GROUPS", "GROUP_BY_MESHIO", "PASSTHROUGH_CELLS",
    "NODE_INDEX_MAX", "PER_TYPE_KEYS", "ChunkField", "CHUNK_FIELDS", "SURFACE_TAG_ARRAYS",
    "DEFAULT_CHUNK_BYTES",
    "MIN_CHUNK_BYTES", "IterationCounter", "ITERATION_COUNTERS", "PARAMETER_ALIASES", "LAYER_ENDS",
    "phase_name", "method_value", "method_names", "is_method", "boundary_value", "boundary_names",
    "boundary_name",
]
