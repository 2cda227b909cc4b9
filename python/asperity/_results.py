"""Result objects: the library's results with the keys of the CLI's JSON.

:class:`Report` (:func:`asperity.evaluate`) is a frozen class built in Rust from the library's
report (``asperity._native.Report``: typed fields, arrays made once, read-only);
:class:`SweepResult` and :class:`CycleResult` wrap a frozen record built in Rust
(``asperity._native.Record``: the same attributes, made once in Rust). Every other result (GFMD,
PSD, gauge) holds the plain dict the library produced (``to_dict()``: the keys and numbers of
``asperity run|sweep|gfmd|psd --format json``, JSON-serialisable, unavailable values None) and
reads it as attributes: a nested object becomes a result (``report.pr.sigma``), a list of
numbers a numpy array (None becomes NaN), a list of objects a list of results. Each attribute is
built once and kept (``r.pr.sigma is r.pr.sigma``); its arrays are read-only, so that the one
kept cannot be changed by a caller (``np.array(r.a_r)`` gives a copy to write to).
"""

from __future__ import annotations

import copy
import math
from typing import Any, Callable, Dict, Iterator, List, Optional, Tuple, TypeVar, cast

import numpy as np

from . import _native
from ._native import Report

_T = TypeVar("_T")

__all__ = [
    "Result",
    "Report",
    "SweepResult",
    "GfmdResult",
    "PsdResult",
    "CycleResult",
    "PullOffResult",
    "GfmdCycleResult",
    "GfmdSweepResult",
]


def _is_number(x: Any) -> bool:
    return x is None or (isinstance(x, (int, float)) and not isinstance(x, bool))


def _num(x: Any) -> float:
    return math.nan if x is None else float(x)


def _wrap(v: Any) -> Any:
    if isinstance(v, dict):
        return Result(v)
    if isinstance(v, list):
        if v and all(isinstance(x, dict) for x in v):
            return [Result(x) for x in v]
        if all(_is_number(x) for x in v):
            return np.array([math.nan if x is None else x for x in v], dtype=float)
    return v


def _memo(obj: Any, name: str, make: Callable[[], _T]) -> _T:
    """The attribute `name` of the result `obj`, made by `make` on first reading and kept (its
    arrays read-only)."""
    cache: Dict[str, Any] = obj.__dict__.setdefault("_memo", {})
    if name not in cache:
        v = make()
        if isinstance(v, np.ndarray):
            v.flags.writeable = False
        cache[name] = v
    return cast(_T, cache[name])


def _column(rows: List[Dict[str, Any]], name: str) -> Optional[np.ndarray]:
    """The column `name` of `rows` as an array (bools: bool, strings: str, numbers: float with
    None as NaN); None where the rows have no such key."""
    if not rows or name not in rows[0]:
        return None
    col = [r.get(name) for r in rows]
    if all(isinstance(x, bool) for x in col):
        return np.array(col, dtype=bool)
    if all(isinstance(x, str) for x in col):
        return np.array(col, dtype=str)
    return np.array([math.nan if x is None else x for x in col], dtype=float)


def _opt(x: Any) -> Optional[float]:
    return None if x is None else float(x)


def _pair(x: Any) -> Optional[Tuple[float, float]]:
    return None if x is None else (_num(x[0]), _num(x[1]))


class Result:
    """A result read as attributes; ``to_dict()`` gives the plain dict (the CLI's JSON keys)."""

    def __init__(self, data: Dict[str, Any]) -> None:
        object.__setattr__(self, "_data", data)

    def __getattr__(self, name: str) -> Any:
        data = object.__getattribute__(self, "_data")
        if name not in data:
            raise AttributeError(f"{type(self).__name__} has no field {name!r} (fields: {', '.join(sorted(data))})")
        return _memo(self, name, lambda: _wrap(data[name]))

    def __getitem__(self, key: str) -> Any:
        return self._data[key]

    def __contains__(self, key: object) -> bool:
        return key in self._data

    def __iter__(self) -> Iterator[str]:
        return iter(self._data)

    def keys(self) -> List[str]:
        """The field names (the JSON keys)."""
        return list(self._data)

    def to_dict(self) -> Dict[str, Any]:
        """A deep copy of the plain dict: JSON types only, unavailable values None."""
        return copy.deepcopy(self._data)

    def __dir__(self) -> List[str]:
        return sorted(set(super().__dir__()) | set(self._data))

    def __repr__(self) -> str:
        shown = []
        for k, v in self._data.items():
            if isinstance(v, (int, float, str, bool)) or v is None:
                shown.append(f"{k}={v!r}")
            if len(shown) == 8:
                break
        return f"{type(self).__name__}({', '.join(shown)}, ...)"


class SweepResult(_native.Record):
    """A sweep (:func:`asperity.sweep`): the object of ``asperity sweep --format json``, a
    frozen record built in Rust (``asperity._native.Record``).

    Column arrays by the row keys (``res.p``, ``res.a_r``, ``res.a_r_unloading``,
    ``res.mean_gap_rel``, ``res.mean_contact_stress``, ``res.thickness_qr``, ``res.gamma``, ...;
    NaN where a row has no number), ``res.values`` (the swept knob's values), ``res.reasons``
    (None where a row converged, else why not), ``res.rows`` (the rows as records).
    """

    __slots__ = ()

    # the fields' and main columns' types for a type checker; at run time they are the
    # record's attributes, made once in Rust
    preset: str
    over: str
    scene: _native.Record
    rows: List[_native.Record]
    evaluations: int
    values: np.ndarray
    p: np.ndarray
    a_r: np.ndarray
    mean_gap_rel: np.ndarray
    mean_contact_stress: np.ndarray
    contact_stress_variance: np.ndarray
    a_r_unloading: np.ndarray
    thickness_qr: np.ndarray
    gamma: np.ndarray
    converged: np.ndarray

    @property
    def reasons(self) -> List[Optional[str]]:
        """Per row: None where it converged, else the reason it has no numbers."""
        return list(self["reasons"]) if "reasons" in self else []

    @property
    def cycle(self) -> Optional["CycleResult"]:
        """With ``cycle=True``: the theory's path along the load cycle (the CLI's
        ``sweep --cycle`` key ``cycle``); else None."""
        return CycleResult(self["cycle"]) if "cycle" in self else None

    @property
    def pull_off(self) -> Optional["PullOffResult"]:
        """With ``cycle=True``: the pull-off read-out (the CLI's ``sweep --cycle`` key
        ``pull_off``, :func:`asperity.pull_off`); else None."""
        return PullOffResult(self["pull_off"]) if "pull_off" in self else None

    def __len__(self) -> int:
        return len(self.rows)


class _OnMap(Result):
    """A GFMD result with ``heights``: the map it ran on (m, rows along y), kept out of
    ``to_dict()`` (the CLI's JSON has no map)."""

    heights: Any  # a 2-D numpy array (m, rows along y)

    def __init__(self, data: Dict[str, Any]) -> None:
        heights = data.pop("heights", None)
        super().__init__(data)
        object.__setattr__(self, "heights", heights)


class GfmdResult(_OnMap):
    """A GFMD run (:func:`asperity.gfmd`): the object of ``asperity gfmd --format json``
    (``a_r``, ``mean_contact_stress``, ``contact_stress_variance``, ``pr``, ``mean_gap``,
    ``mean_gap_rel``, ``iterations``, ``residual``, ``converged``, ``grid``, ``theory`` on the
    same map, ``reduction``, timings) and ``heights``, the map it ran on (m, rows along y)."""

    # the fields' types for a type checker; at run time they are read from the dict
    a_r: float
    mean_contact_stress: float
    contact_stress_variance: float
    pr: Result
    mean_gap: float
    mean_gap_rel: float
    iterations: int
    residual: float
    converged: bool
    grid: int
    theory: Optional[Result]
    elapsed_s: float


class PsdResult(Result):
    """The PSD of a map (:func:`asperity.psd`): the object of ``asperity psd --format json``
    and the table as arrays ``q`` (1/m), ``psd`` (C(q), m⁴, isotropic 2-D [S-2]), ``modes``."""

    # the fields' types for a type checker; at run time they are read from the dict
    file: str
    system_size_m: float
    rms_height_m: float
    rms_gradient: float
    rms_curvature: float
    hurst: Optional[float]
    hurst_error: Optional[float]
    rolloff_wavelength_m: Optional[float]
    short_wavelength_m: Optional[float]
    self_affine: bool
    line_scan: bool
    table: List[Result]

    @property
    def q(self) -> np.ndarray:
        return _memo(self, "q", lambda: np.array([b["q"] for b in self._data["table"]], dtype=float))

    @property
    def psd(self) -> np.ndarray:
        return _memo(self, "psd", lambda: np.array([b["psd"] for b in self._data["table"]], dtype=float))

    @property
    def modes(self) -> np.ndarray:
        return _memo(self, "modes", lambda: np.array([b["modes"] for b in self._data["table"]], dtype=int))


class _Rows(Result):
    """A result with ``rows``: a row key reads as a column array (``res.a_r``), after the
    result's own keys."""

    def __getattr__(self, name: str) -> Any:
        data = object.__getattribute__(self, "_data")
        if name in data:
            return _memo(self, name, lambda: _wrap(data[name]))
        rows = data.get("rows", [])
        if _column(rows[:1], name) is None:
            raise AttributeError(f"{type(self).__name__} has no field or column {name!r}")
        return _memo(self, name, lambda: _column(rows, name))

    def __len__(self) -> int:
        return len(self._data.get("rows", []))

    def _col(self, name: str) -> np.ndarray:
        def make() -> np.ndarray:
            col = _column(self._data.get("rows", []), name)
            return np.array([], dtype=float) if col is None else col

        return _memo(self, name, make)

    @property
    def branch(self) -> np.ndarray:
        """Per row: ``"loading"`` (rising load) or ``"unloading"`` (falling load, on through
        tension to pull-off)."""
        return self._col("branch")

    @property
    def p(self) -> np.ndarray:
        """Per row: the load p* (negative: tension), in the order the path visits them."""
        return self._col("p")

    @property
    def a_r(self) -> np.ndarray:
        """Per row: the relative contact area a_r [S-3]."""
        return self._col("a_r")

    @property
    def mean_gap_rel(self) -> np.ndarray:
        """Per row: the mean gap ū/h_rms (NaN where it is not defined)."""
        return self._col("mean_gap_rel")

    @property
    def mean_contact_stress(self) -> np.ndarray:
        """Per row: σ̄_c*, the mean stress in the contact (reduced by E*ḡ; NaN where missing)."""
        return self._col("mean_contact_stress")

    @property
    def loading(self) -> np.ndarray:
        """Per row: whether it is on the loading leg (``branch == "loading"``)."""
        return np.asarray(self.branch == "loading", dtype=bool)

    @property
    def pull_off_pressure(self) -> Optional[float]:
        """The pull-off p* (≤ 0: the most tension the contact held; 0 without adhesion);
        None where the path was not continued into tension."""
        return _opt(self._data.get("pull_off_pressure"))

    @property
    def pull_off_bracket(self) -> Optional[Tuple[float, float]]:
        """(the first p* lost, the last p* held) around the pull-off; None where there is none."""
        return _pair(self._data.get("pull_off_bracket"))

    @property
    def jump_in_pressure(self) -> Optional[float]:
        """The load at which loading jumps into more contact; None: no jump in the range."""
        return _opt(self._data.get("jump_in_pressure"))


class CycleResult(_native.Record):
    """The theory's path along a load cycle (:func:`asperity.cycle`, ``SweepResult.cycle``):
    the object under ``cycle`` of ``asperity sweep --cycle --format json``, a frozen record
    built in Rust.

    Columns by row (in the order the path visits the loads: loading up, unloading back down and
    on into tension at p* = 0, −p₁, −2p₁, … to the pull-off): ``branch``, ``p``, ``a_r``,
    ``mean_gap_rel`` (NaN under tension, where the mean gap is not defined),
    ``mean_contact_stress`` (NaN on the unloading branch inside a hysteresis window),
    ``on_unloading_branch`` (bool: the theory's unloading, highest stable branch). Fields:
    ``unloading_branch_ends`` (p* below which the unloading branch no longer exists, where the
    range holds it), ``jump_in_pressure``, ``pull_off_pressure`` (the theory's pull-off, ≤ 0)
    with ``pull_off_bracket``, ``tension_bound`` (the most tension any contact branch could
    hold, the coarsest scale's Griffith stress) and ``note`` (why the path ends where it does).
    """

    __slots__ = ()

    # the fields' and columns' types for a type checker; at run time they are the record's
    # attributes, made once in Rust
    rows: List[_native.Record]
    branch: np.ndarray
    p: np.ndarray
    a_r: np.ndarray
    mean_gap_rel: np.ndarray
    mean_contact_stress: np.ndarray
    on_unloading_branch: np.ndarray
    unloading_branch_ends: Optional[float]
    jump_in_pressure: Optional[float]
    pull_off_pressure: Optional[float]
    tension_bound: Optional[float]
    note: str

    @property
    def loading(self) -> np.ndarray:
        """Per row: whether it is on the loading leg (``branch == "loading"``)."""
        return np.asarray(self.branch == "loading", dtype=bool)

    @property
    def pull_off_bracket(self) -> Optional[Tuple[float, float]]:
        """(the first p* lost, the last p* held) around the pull-off; None where there is none."""
        return _pair(self["pull_off_bracket"])

    def __len__(self) -> int:
        return len(self.rows)

    def __repr__(self) -> str:
        return (
            f"CycleResult(rows={len(self)}, pull_off_pressure={self.pull_off_pressure!r}, "
            f"jump_in_pressure={self.jump_in_pressure!r}, ...)"
        )


class PullOffResult(_native.Record):
    """The pull-off read-out (:func:`asperity.pull_off`, ``SweepResult.pull_off``): the object
    under ``pull_off`` of ``asperity run --pull-off --format json``, a frozen record built in
    Rust (docs/physics.md §6.4).

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

    pull_off_pressure: float
    tension_bound: float
    bam_pull_off_pressure: Optional[float]
    gap_dmt_pull_off_pressure: Optional[float]
    gfmd: Optional[_native.Record]
    trust: _native.Record
    notes: List[str]
    estimate: _native.Record

    @property
    def pull_off_bracket(self) -> Optional[Tuple[float, float]]:
        """(the first p* lost, the last p* held) of the theory's tensile path."""
        return _pair(self["pull_off_bracket"])

    def __repr__(self) -> str:
        return (
            f"PullOffResult(pull_off_pressure={self.pull_off_pressure!r}, "
            f"bam_pull_off_pressure={self.bam_pull_off_pressure!r}, "
            f"gap_dmt_pull_off_pressure={self.gap_dmt_pull_off_pressure!r}, ...)"
        )


class GfmdCycleResult(_OnMap, _Rows):
    """GFMD's load cycle (:func:`asperity.gfmd_cycle`): the object of
    ``asperity gfmd --cycle --format json``.

    Columns by row (loads in the order visited; tensile loads lost are not rows): ``branch``,
    ``p``, ``a_r``, ``mean_gap_rel``, ``mean_gap`` (m), ``mean_contact_stress``,
    ``contact_stress_variance``, ``elastic_energy``, ``converged``, ``residual``, ... Fields:
    ``pull_off_pressure`` (the most tensile p* the contact held; 0 without adhesion) with
    ``pull_off_bracket``, ``jump_in_pressure`` with ``jump_in_bracket``, ``note``, ``grid``,
    ``seed``, ``reduction``, ``theory`` (the theory's sweep on the same map, both branches),
    ``theory_cycle`` (its path along the same cycle to its own pull-off, a
    :class:`CycleResult`), ``theory_error``, ``iterations`` (all steps), ``elapsed_s``; and
    ``heights``, the map it ran on (m, rows along y), as :class:`GfmdResult`'s.
    """

    @property
    def theory_cycle(self) -> Optional[CycleResult]:
        """The theory's path along the same cycle on the map's spectrum (None where the
        theory failed: ``theory_error`` says why)."""
        c = self._data.get("theory_cycle")
        return None if c is None else CycleResult(c)

    @property
    def jump_in_bracket(self) -> Optional[Tuple[float, float]]:
        """(the load before the jump-in, the load after it); None: no jump."""
        return _pair(self._data.get("jump_in_bracket"))

    def __repr__(self) -> str:
        d = self._data
        return (
            f"GfmdCycleResult(grid={d.get('grid')!r}, rows={len(self)}, "
            f"pull_off_pressure={d.get('pull_off_pressure')!r}, jump_in_pressure={d.get('jump_in_pressure')!r}, ...)"
        )


class GfmdSweepResult(_OnMap, _Rows):
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

    def __repr__(self) -> str:
        d = self._data
        return f"GfmdSweepResult(grid={d.get('grid')!r}, rows={len(self)}, ...)"
