"""What the server reports, as plain dataclasses (converted from the getme.v1 messages).

Element types are named as meshio names them ("tetra", "hexahedron", "wedge", "pyramid"), phases
by the lower-case name of getme.v1.Phase without its prefix ("untangle", "simultaneous",
"sequential", "warpage", "smart_laplace", "laplace", "polish"); both mappings are _wire's.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Dict, List

from getme._wire import ELEMENT_GROUPS, ITERATION_COUNTERS, phase_name


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
class SmoothReport:
    """What a smoothing job did (getme.v1.SmoothResult).

    before, after: QualityReport of the input and of the smoothed mesh; q_min, q_mean,
    invalid_elements and histogram are the after values. phases: PhaseSummary per phase run, in
    order. iterations: per phase name ("untangle", "simultaneous", "sequential", "laplace",
    "polish": sweeps).
    seconds: smoothing time on the server, without queueing and transfer. threads: the engine
    threads the job used.
    """
    job_id: str
    before: QualityReport
    after: QualityReport
    phases: List[PhaseSummary]
    iterations: Dict[str, int]
    seconds: float
    threads: int

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
                            threads=result.threads)


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


__all__ = ["TypeQuality", "QualityReport", "PhaseSummary", "SmoothReport", "ProgressEvent"]
