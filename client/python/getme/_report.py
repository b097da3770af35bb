"""What the server reports, as plain dataclasses (converted from the getme.v1 messages).

Element types are named as meshio names them ("tetra", "hexahedron", "wedge", "pyramid"), phases
by the lower-case name of getme.v1.Phase without its prefix ("untangle", "simultaneous",
"sequential", "warpage", "smart_laplace", "laplace", "polish", "layers"), boundaries likewise
("fixed", "slide", "free"); these mappings are _wire's.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Dict, List, Optional

from getme._wire import ELEMENT_GROUPS, ITERATION_COUNTERS, LAYER_ENDS, boundary_name, phase_name


@dataclass(frozen=True)
class TypeQuality:
    """Mean ratio statistics (paper Def. 3) of the elements of one type."""
    count: int
    q_min: float  # 1 when count is 0
    q_mean: float  # 0 when count is 0
    invalid_elements: int


@dataclass(frozen=True)
class QualityReport:
    """The quality of a whole mesh (getme.v1.QualityReport).

    Invalid (inverted or degenerate) elements count as q = 0 in q_min and q_mean.
    first_invalid_elements holds at most 10 cell indices: the position of the cell in the mesh
    given (a meshio.Mesh's cells counted over all its cell blocks, as meshio.Mesh.cells lists
    them, surface cells included; numpy input: over the cells dict in its order). histogram[i]
    counts the elements with q in [i/n, (i+1)/n), n = len(histogram), q = 1 in the last bin.
    by_type maps "tetra", "hexahedron", "wedge", "pyramid" to TypeQuality. warpage_max and
    warpage_mean (0 = planar quad faces, up to 2) are taken over elements with quad faces.
    """
    elements: int
    q_min: float
    q_mean: float
    invalid_elements: int
    first_invalid_elements: List[int]
    warpage_max: float
    warpage_mean: float
    by_type: Dict[str, TypeQuality]
    histogram: List[int]

    @staticmethod
    def from_proto(report) -> "QualityReport":
        by_type = {}
        for group in ELEMENT_GROUPS:
            wire = getattr(report, group.report_field)
            by_type[group.meshio] = TypeQuality(count=wire.count, q_min=wire.q_min,
                                                q_mean=wire.q_mean,
                                                invalid_elements=wire.invalid_elements)
        return QualityReport(elements=report.elements, q_min=report.q_min, q_mean=report.q_mean,
                             invalid_elements=report.invalid_elements,
                             first_invalid_elements=list(report.first_invalid_elements),
                             warpage_max=report.warpage_max, warpage_mean=report.warpage_mean,
                             by_type=by_type, histogram=list(report.histogram))


@dataclass(frozen=True)
class PhaseSummary:
    """One phase the engine ran: its iterations (sequential phases: picks), time and the state
    it handed on."""
    phase: str
    iterations: int
    seconds: float
    q_min: float
    q_mean: float
    reverted_nodes: int


@dataclass(frozen=True)
class BoundarySlideReport:
    """What a sliding boundary (boundary="slide") or kept layers (keep_layers=True) did
    (getme.v1.BoundarySlideReport).

    sliding_nodes: boundary nodes that could slide (not corners, not fixed); slid_nodes: those
    that moved; max_distance: the largest distance of one from the input's surface; layer_nodes:
    nodes above the walls in kept boundary-layer columns. feature_edges, feature_curves and
    corners describe the input's surface as the slide saw it (0 with keep_layers alone), with
    surface_groups (its groups, plus group 0) and interior_grouped_faces (tagged faces not on the
    boundary, left out).
    """
    sliding_nodes: int
    slid_nodes: int
    max_distance: float
    layer_nodes: int
    feature_edges: int
    feature_curves: int
    corners: int
    surface_groups: int = 0
    interior_grouped_faces: int = 0

    @staticmethod
    def from_proto(report) -> "BoundarySlideReport":
        return BoundarySlideReport(sliding_nodes=report.sliding_nodes,
                                   slid_nodes=report.slid_nodes, max_distance=report.max_distance,
                                   layer_nodes=report.layer_nodes,
                                   feature_edges=report.feature_edges,
                                   feature_curves=report.feature_curves, corners=report.corners,
                                   surface_groups=report.surface_groups,
                                   interior_grouped_faces=report.interior_grouped_faces)


@dataclass(frozen=True)
class LayerState:
    """The kept layers at one moment (getme.v1.LayerState): first-layer height over the columns
    (min, mean, max), the mean lean of the column edges from the wall normal in degrees, and the
    quality of the columns' elements."""
    first_min: float
    first_mean: float
    first_max: float
    mean_lean_degrees: float
    q_min: float
    q_mean: float

    @staticmethod
    def from_proto(state) -> "LayerState":
        return LayerState(first_min=state.first_min, first_mean=state.first_mean,
                          first_max=state.first_max, mean_lean_degrees=state.mean_lean_degrees,
                          q_min=state.q_min, q_mean=state.q_mean)


@dataclass(frozen=True)
class LayerReport:
    """The boundary-layer columns keep_layers=True found and kept (getme.v1.LayerReport).

    columns: wall faces a column grows from; column_elements; layer_nodes: nodes above the walls,
    moved only with their column; layers; conflicting_nodes: where columns collide (left to the
    ordinary phases). ends: why the columns stop, by "tetrahedron", "pyramid", "prism_side",
    "isotropic" (an element as thick as wide), "other_column", "boundary". before, after:
    LayerState. max_height_change: the largest |after / before - 1| of one layer at one node.
    """
    columns: int
    column_elements: int
    layer_nodes: int
    layers: int
    conflicting_nodes: int
    ends: Dict[str, int]
    before: LayerState
    after: LayerState
    max_height_change: float

    @staticmethod
    def from_proto(report) -> "LayerReport":
        return LayerReport(columns=report.columns, column_elements=report.column_elements,
                           layer_nodes=report.layer_nodes, layers=report.layers,
                           conflicting_nodes=report.conflicting_nodes,
                           ends={end: getattr(report, f"ends_{end}") for end in LAYER_ENDS},
                           before=LayerState.from_proto(report.before),
                           after=LayerState.from_proto(report.after),
                           max_height_change=report.max_height_change)


@dataclass(frozen=True)
class SmoothReport:
    """What a smoothing job did (getme.v1.SmoothResult).

    before, after: QualityReport of the input and of the smoothed mesh; q_min, q_mean,
    invalid_elements and histogram are the after values. phases: PhaseSummary per phase run, in
    order. iterations: per phase name ("untangle", "simultaneous", "sequential", "laplace",
    "polish": sweeps, "layers": passes over the kept columns).
    seconds: smoothing time on the server, without queueing and transfer. threads: the engine
    threads the job used.
    boundary: how the boundary moved, "fixed", "slide" or "free" ("unspecified" from a server
    that predates the field). boundary_slide: a BoundarySlideReport with boundary="slide" or
    keep_layers=True, else None. layers: a LayerReport with keep_layers=True, else None.
    """
    job_id: str
    before: QualityReport
    after: QualityReport
    phases: List[PhaseSummary]
    iterations: Dict[str, int]
    seconds: float
    threads: int
    boundary: str = "fixed"
    boundary_slide: Optional[BoundarySlideReport] = None
    layers: Optional[LayerReport] = None

    @property
    def q_min(self) -> float:
        return self.after.q_min

    @property
    def q_mean(self) -> float:
        return self.after.q_mean

    @property
    def invalid_elements(self) -> int:
        return self.after.invalid_elements

    @property
    def histogram(self) -> List[int]:
        return self.after.histogram

    @staticmethod
    def from_proto(result) -> "SmoothReport":
        phases = [
            PhaseSummary(phase=phase_name(p.phase), iterations=p.iterations, seconds=p.seconds,
                         q_min=p.q_min, q_mean=p.q_mean, reverted_nodes=p.reverted_nodes)
            for p in result.phases
        ]
        iterations = {counter.phase: getattr(result, counter.result_field)
                      for counter in ITERATION_COUNTERS}
        return SmoothReport(job_id=result.job_id, before=QualityReport.from_proto(result.before),
                            after=QualityReport.from_proto(result.after), phases=phases,
                            iterations=iterations, seconds=result.seconds,
                            threads=result.threads, boundary=boundary_name(result.boundary),
                            boundary_slide=(BoundarySlideReport.from_proto(result.boundary_slide)
                                            if result.HasField("boundary_slide") else None),
                            layers=(LayerReport.from_proto(result.layers)
                                    if result.HasField("layers") else None))


@dataclass(frozen=True)
class ProgressEvent:
    """One progress event of a smoothing job (getme.v1.ProgressEvent).

    The engine sends one per iteration of a phase (sequential phases: per sequential_cycle picks),
    then one with phase_done set carrying the state the phase hands on; the last event of a call
    has final set (it repeats the last state). sequence counts 1, 2, 3, ... over the job's
    events; the server throttles intermediate events (getme-server --progress_interval), so a gap
    means events were skipped; phase ends and the final event always arrive.
    """
    job_id: str
    phase: str
    iteration: int
    q_min: float
    q_mean: float
    invalid_elements: int
    reverted_nodes: int
    elapsed_seconds: float
    phase_done: bool
    sequence: int
    final: bool

    @staticmethod
    def from_proto(event) -> "ProgressEvent":
        return ProgressEvent(job_id=event.job_id, phase=phase_name(event.phase),
                             iteration=event.iteration, q_min=event.q_min, q_mean=event.q_mean,
                             invalid_elements=event.invalid_elements,
                             reverted_nodes=event.reverted_nodes,
                             elapsed_seconds=event.elapsed_seconds, phase_done=event.phase_done,
                             sequence=event.sequence, final=event.final)


__all__ = ["TypeQuality", "QualityReport", "PhaseSummary", "BoundarySlideReport", "LayerState",
           "LayerReport", "SmoothReport", "ProgressEvent"]
