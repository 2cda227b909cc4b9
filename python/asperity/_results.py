"""Result objects: the library's results with the keys of the CLI's JSON.

:class:`Report` (:func:`asperity.evaluate`) is a frozen class built in Rust from the library's
report (``asperity._native.Report``: typed fields, arrays made once, read-only). Every other
result wraps a frozen record built in Rust from the library's report (``asperity._native.Record``,
also :class:`Result`): each key an attribute made once (``r.x is r.x``; a nested object a
record, a list of numbers a read-only float64 numpy array with null as NaN, a list of objects
a list of records), each key of ``rows`` (or a PSD's ``table``) a column array, ``to_dict()``
the plain dict (the keys and numbers of ``asperity ... --format json``, JSON types,
unavailable values None). The classes here only name the attributes' types for a type checker
and make their typed parts once (``_parts``: a load cycle as :class:`CycleResult`, a bracket as
a tuple); ``np.array(r.a_r)`` gives a copy to write to.
"""

from __future__ import annotations

from typing import Any, Callable, ClassVar, Dict, List, Optional, Tuple

import numpy as np

from . import _native
from ._native import Report

__all__ = [
    "Result",
    "Report",
    "SweepResult",
    "GfmdResult",
    "PsdResult",
    "GaugeResult",
    "CycleResult",
    "PullOffResult",
    "GfmdCycleResult",
    "GfmdSweepResult",
]

#: Every result but :class:`Report`: a frozen record built in Rust, its keys as attributes.
Result = _native.Record

#: A result class's typed parts: attribute name → how it is made from the record's attribute
#: (None where the record has no such key).
Parts = Dict[str, Callable[[Any], Any]]


def _pair(x: Any) -> Optional[Tuple[float, float]]:
    """A bracket as a tuple (None where there is none; null ends as NaN)."""
    return None if x is None else (float(x[0]), float(x[1]))


def _as(cls: Callable[[Any], Any]) -> Callable[[Any], Any]:
    """A part as the result class `cls` (None where absent)."""
    return lambda x: None if x is None else cls(x)


def _list(x: Any) -> List[Any]:
    """A list (the record reads an empty one as an empty array)."""
    return [] if x is None else list(x)


def _texts(x: Any) -> List[Optional[str]]:
    """A list of optional strings (the record reads one of Nones only as a NaN array)."""
    return [] if x is None else [v if isinstance(v, str) else None for v in x]


def _counts(x: Any) -> np.ndarray:
    """A column of counts as a read-only int array."""
    a = np.asarray(x, dtype=int)
    a.flags.writeable = False
    return a


class _Rows(Result):
    """A result with ``rows``: ``len(r)`` rows, each row key a column array."""

    __slots__ = ()

    rows: List[Result]

    def __len__(self) -> int:
        return len(self.rows)


class _Path(_Rows):
    """A load path: rows in the order visited, each on the loading or unloading branch, with
    the pull-off and jump-in read from it."""

    __slots__ = ()
    _parts: ClassVar[Parts] = {"pull_off_bracket": _pair}

    branch: np.ndarray
    p: np.ndarray
    a_r: np.ndarray
    mean_gap_rel: np.ndarray
    mean_contact_stress: np.ndarray
    pull_off_pressure: Optional[float]
    pull_off_bracket: Optional[Tuple[float, float]]
    jump_in_pressure: Optional[float]

    @property
    def loading(self) -> np.ndarray:
        """Per row: whether it is on the loading leg (``branch == "loading"``)."""
        return np.asarray(self.branch == "loading", dtype=bool)


class PullOffResult(Result):
    """The pull-off read-out (:func:`asperity.pull_off`, ``SweepResult.pull_off``): the object
    under ``pull_off`` of ``asperity run --pull-off --format json`` (docs/physics.md §6.4).

    Fields: ``pull_off_pressure`` (the theory's pull-off p*, ≤ 0, along the tensile path 0,
    −10⁻⁴, −2·10⁻⁴, … bisected to 3 %) with ``pull_off_bracket`` and ``tension_bound``;
    ``bam_pull_off_pressure`` and ``gap_dmt_pull_off_pressure`` (the two DMT routes from the
    PSD alone, None where a route did not converge, with the reason in ``notes``); ``gfmd``
    (GFMD's measured pull-off at the nearest stored case: ``pull_off_pressure``,
    ``pull_off_pressure_err``, ``thickness_qr``, ``gamma_factor``, ``gamma_glo``, ``seeds``,
    ``distance``; None where none is within reach); ``trust``: ``known``, ``measured_model``,
    ``cases`` (each with ``gfmd``, ``gfmd_err``, ``theory_ratio``, ``bam_ratio``,
    ``gap_dmt_ratio``: each pull-off over GFMD's), the ranges ``theory_ratio``, ``bam_ratio``,
    ``gap_dmt_ratio`` over those cases, ``bracketed`` and ``summary``. The ratios are what was
    measured: none of the three pull-offs is an estimate of GFMD's. ``estimate`` is the one
    estimate (docs/physics.md §6.5): an empirical correlation gauged on GFMD's stored pull-offs,
    ``pull_off_pressure`` (None outside the measured range, the reasons in ``outside``) with its
    ``band``, ``band_factor``, ``band_held``, ``coefficients``, ``held_out`` and ``summary``.
    """

    __slots__ = ()
    _parts: ClassVar[Parts] = {"pull_off_bracket": _pair, "notes": _list}

    pull_off_pressure: float
    pull_off_bracket: Optional[Tuple[float, float]]
    tension_bound: float
    bam_pull_off_pressure: Optional[float]
    gap_dmt_pull_off_pressure: Optional[float]
    gfmd: Optional[Result]
    trust: Result
    notes: List[str]
    estimate: Result


class CycleResult(_Path):
    """The theory's path along a load cycle (:func:`asperity.cycle`, ``SweepResult.cycle``,
    ``GfmdCycleResult.theory_cycle``): the object under ``cycle`` of
    ``asperity sweep --cycle --format json``.

    Columns by row (in the order the path visits the loads: loading up, unloading back down and
    on into tension at p* = 0, −p₁, −2p₁, … to the pull-off): ``branch``, ``p``, ``a_r``,
    ``mean_gap_rel`` (NaN under tension, where the mean gap is not defined),
    ``mean_contact_stress`` (NaN on the unloading branch inside a hysteresis window),
    ``on_unloading_branch`` (bool: the theory's unloading, highest stable branch);
    ``a_r_unloading_pinned`` (a_r of the pinned unloading branch below the top load, NaN where
    null: loading rows, past that branch's pull-off, and t·q_r > 0.3; docs/physics.md §6.6);
    ``loading`` (bool). Fields: ``unloading_branch_ends`` (p* below which the unloading branch no longer
    exists, where the range holds it), ``jump_in_pressure``, ``pull_off_pressure`` (the
    theory's pull-off, ≤ 0) with ``pull_off_bracket``, ``tension_bound`` (the most tension any
    contact branch could hold, the coarsest scale's Griffith stress) and ``note`` (why the path
    ends where it does).
    """

    __slots__ = ()

    on_unloading_branch: np.ndarray
    a_r_unloading_pinned: np.ndarray
    unloading_branch_ends: Optional[float]
    tension_bound: Optional[float]
    note: str


class SweepResult(_Rows):
    """A sweep (:func:`asperity.sweep`): the object of ``asperity sweep --format json``.

    Column arrays by the row keys (``res.p``, ``res.a_r``, ``res.a_r_unloading``,
    ``res.mean_gap_rel``, ``res.mean_contact_stress``, ``res.thickness_qr``, ``res.gamma``, ...;
    NaN where a row has no number), ``res.values`` (the swept knob's values), ``res.reasons``
    (None where a row converged, else why not), ``res.rows`` (the rows as records); with
    ``cycle=True`` also ``cycle`` (the theory's path along the load cycle, a
    :class:`CycleResult`) and ``pull_off`` (a :class:`PullOffResult`), None otherwise (the
    CLI's ``sweep --cycle`` keys).
    """

    __slots__ = ()
    _parts: ClassVar[Parts] = {
        "cycle": _as(CycleResult),
        "pull_off": _as(PullOffResult),
        "reasons": _texts,
        "window_edges": _list,
    }

    preset: str
    over: str
    scene: Result
    evaluations: int
    full_contact_pressure: float
    monotone: bool
    failed_loads: np.ndarray
    failed_values: np.ndarray
    note: Optional[str]
    jump_in_pressure: Optional[float]
    pull_off_pressure: Optional[float]
    window_edges: List[Result]
    values: np.ndarray
    reasons: List[Optional[str]]
    cycle: Optional[CycleResult]
    pull_off: Optional[PullOffResult]
    p: np.ndarray
    a_r: np.ndarray
    mean_gap_rel: np.ndarray
    mean_contact_stress: np.ndarray
    contact_stress_variance: np.ndarray
    a_r_unloading: np.ndarray
    thickness_qr: np.ndarray
    gamma: np.ndarray
    converged: np.ndarray


class GfmdResult(Result):
    """A GFMD run (:func:`asperity.gfmd`): the object of ``asperity gfmd --format json``
    (``a_r``, ``mean_contact_stress``, ``contact_stress_variance``, ``pr`` (a ``Pr``:
    ``sigma``, ``density``), ``mean_gap``, ``mean_gap_rel``, ``iterations``, ``residual``,
    ``converged``, ``grid``, ``theory`` on the same map, ``reduction``, timings; docs/python.md
    lists every key) and ``heights``, the map it ran on (m, rows along y; not in
    ``to_dict()``)."""

    __slots__ = ()
    _parts: ClassVar[Parts] = {"pr": lambda x: _native.Pr(x.to_dict())}

    a_r: float
    mean_contact_stress: float
    contact_stress_variance: float
    pr: _native.Pr
    mean_gap: float
    mean_gap_rel: float
    iterations: int
    pk_iterations: int
    residual: float
    tolerance: float
    converged: bool
    grid: int
    seed: Optional[int]
    pressure: float
    pressure_pa: float
    thickness_qr: Optional[float]
    gamma: float
    range_m: float
    system_size_m: float
    spacing_m: float
    grid_spec: Optional[Result]
    rms_gradient: float
    rms_height_m: float
    contact_nodes: int
    adhesion_resolution: float
    reduction: Optional[Result]
    theory: Optional[Result]
    theory_error: Optional[str]
    elapsed_s: float
    solve_elapsed_s: float
    theory_elapsed_s: float
    heights: np.ndarray


class GfmdSweepResult(_Path):
    """A one-way GFMD load sweep (:func:`asperity.gfmd_sweep`): the object of
    ``asperity gfmd --from A --to B --format json``.

    Columns by row, in the order the loads were visited: ``p``, ``a_r``, ``mean_gap_rel``,
    ``mean_gap`` (m), ``mean_contact_stress``, ``contact_stress_variance``, ``elastic_energy``,
    ``converged``, ``residual``, ``iterations``. Fields: ``grid``, ``seed``, ``reduction``,
    ``theory`` (the theory's sweep on the same map), ``theory_error``, ``iterations``,
    ``elapsed_s``; an unloading sweep (B < A) also has ``branch`` per row and the fields of
    :class:`GfmdCycleResult` (``pull_off_pressure``, ``note``, ``theory_cycle``, ...); and
    ``heights``, the map it ran on (m, rows along y).
    """

    __slots__ = ()
    _parts: ClassVar[Parts] = {**_Path._parts, "theory_cycle": _as(CycleResult)}

    grid: int
    seed: Optional[int]
    reduction: Optional[Result]
    theory: Optional[Result]
    theory_error: Optional[str]
    iterations: int
    elapsed_s: float
    heights: np.ndarray


class GfmdCycleResult(GfmdSweepResult):
    """GFMD's load cycle (:func:`asperity.gfmd_cycle`): the object of
    ``asperity gfmd --cycle --format json``.

    Columns by row (loads in the order visited; tensile loads lost are not rows): ``branch``,
    ``p``, ``a_r``, ``mean_gap_rel``, ``mean_gap`` (m), ``mean_contact_stress``,
    ``contact_stress_variance``, ``elastic_energy``, ``converged``, ``residual``, ... Fields:
    ``pull_off_pressure`` (the most tensile p* the contact held; 0 without adhesion) with
    ``pull_off_bracket``, ``jump_in_pressure`` with ``jump_in_bracket``, ``note``, ``grid``,
    ``seed``, ``reduction``, ``theory`` (the theory's sweep on the same map, both branches),
    ``theory_cycle`` (its path along the same cycle to its own pull-off, a
    :class:`CycleResult`; None where the theory failed: ``theory_error`` says why),
    ``theory_error``, ``iterations`` (all steps), ``elapsed_s``; and ``heights``, the map it
    ran on (m, rows along y), as :class:`GfmdResult`'s.
    """

    __slots__ = ()
    _parts: ClassVar[Parts] = {**GfmdSweepResult._parts, "jump_in_bracket": _pair}

    jump_in_bracket: Optional[Tuple[float, float]]
    note: Optional[str]
    theory_cycle: Optional[CycleResult]


class PsdResult(Result):
    """The PSD of a map (:func:`asperity.psd`): the object of ``asperity psd --format json``
    and the table as arrays ``q`` (1/m), ``psd`` (C(q), m⁴, isotropic 2-D [S-2]), ``modes``
    (ints)."""

    __slots__ = ()
    _parts: ClassVar[Parts] = {"modes": _counts}

    file: str
    points: np.ndarray
    system_size_m: float
    rms_height_m: float
    rms_gradient: float
    rms_curvature: float
    hurst: Optional[float]
    hurst_error: Optional[float]
    rolloff_wavelength_m: Optional[float]
    rolloff_wavelength_range_m: Optional[np.ndarray]
    short_wavelength_m: Optional[float]
    short_wavelength_range_m: Optional[np.ndarray]
    self_affine: bool
    line_scan: bool
    window: str
    detrend: str
    elapsed_s: float
    table: List[Result]
    q: np.ndarray
    psd: np.ndarray
    modes: np.ndarray


class GaugeResult(Result):
    """A gauge (:func:`asperity.gauge`): the object of ``asperity gauge --format json``:
    ``reference``, ``params`` (each with its value and standard error), ``correlation``,
    ``condition_number``, ``residuals``, ``chi2``, ``chi2_reduced``, ``points``,
    ``evaluations``, ``termination``, ``model``, ``start``, ``elapsed_s`` (``gfmd`` and
    ``saved_preset`` are None from Python)."""

    __slots__ = ()

    reference: str
    gfmd: Optional[Result]
    saved_preset: Optional[str]
    params: List[Result]
    correlation: List[List[float]]
    condition_number: float
    residuals: List[Result]
    chi2: float
    chi2_reduced: Optional[float]
    points: int
    evaluations: int
    termination: str
    model: Result
    start: Result
    elapsed_s: float
