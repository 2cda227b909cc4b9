"""The functions of asperity: the theory at one load, sweeps, GFMD, PSDs, surfaces, gauging.

Each is a thin call of the Rust library (the same calls as the ``asperity`` binary's commands,
so the numbers equal the CLI's JSON for the same scene). Long computations run without the
GIL on a worker thread; Ctrl-C (KeyboardInterrupt) stops a GFMD run or a sweep within a
fraction of a second, and an optional ``progress`` callback gets a dict (``stage``, ``done``,
``total``, ``residual``, ``contact_fraction``) about every 50 ms; an exception it raises stops
the computation and propagates. Results do not depend on the number of threads.
"""

from __future__ import annotations

import io
import math
import os
import warnings
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Union

import numpy as np

from . import _args as a
from . import _native
from ._errors import InputError, ResolutionWarning, UnitWarning
from ._results import (
    CycleResult,
    GaugeResult,
    GfmdCycleResult,
    GfmdResult,
    GfmdSweepResult,
    PsdResult,
    PullOffResult,
    Report,
    Result,
    SweepResult,
)
from ._scene import Scene, Surface, as_map, size_in_metres

__all__ = [
    "evaluate",
    "sweep",
    "sweep_thickness",
    "sweep_gamma",
    "cycle",
    "pull_off",
    "gfmd",
    "gfmd_cycle",
    "gfmd_sweep",
    "generate_surface",
    "psd",
    "read_surface",
    "gauge",
]

Progress = Optional[Callable[[Dict[str, Any]], Any]]


def _scene(scene: Any) -> "_native.SceneCore":
    if not isinstance(scene, Scene):
        raise TypeError(f"scene: expected an asperity.Scene, got {type(scene).__name__}")
    return scene._core


def _opt_number(x: Any, name: str, key: str) -> Optional[float]:
    return None if x is None else a.number(x, name, key)


def _opt_count(x: Any, name: str, key: str) -> Optional[int]:
    return None if x is None else a.count(x, name, key)


def evaluate(
    scene: Scene,
    *,
    sigma_points: int = 201,
    sigma_max: Optional[float] = None,
    rtol: Optional[float] = None,
    adhesion_steps: Optional[float] = None,
    adhesion_points: Optional[float] = None,
    adhesion_tol: Optional[float] = None,
    progress: Progress = None,
) -> Report:
    """Persson theory for one scene at its load p* (``asperity run``): library
    ``asperity::report::point``.

    Returns a :class:`Report`: ``a_r`` (relative contact area [S-3, S-9]),
    ``mean_contact_stress`` σ̄_c* and ``contact_stress_variance`` (reduced by E*ḡ and (E*ḡ)²),
    ``pr.sigma``/``pr.density`` (Pr(σ*), ∫Pr dσ* = a_r; with adhesion the wall at σ* = −σ_a*
    [S-5..S-9, S-14]), the mean gap ``mean_gap`` (m) and ``mean_gap_rel`` (ū/h_rms) with its
    bracket [S-11, S-12], every ``branches`` entry and the hysteresis window
    (``jump_in_pressure``, ``pull_off_pressure``), ``error_estimate`` (absolute, of a_r),
    timings in s (``elapsed_s`` ...). ``to_dict()`` has the keys of
    ``asperity run --format json``.

    Accuracy knobs as the CLI's flags: ``sigma_points`` (points of Pr), ``sigma_max``,
    ``rtol`` (variance ODE), ``adhesion_steps`` (per unit ln q), ``adhesion_points`` (per
    width of Pr), ``adhesion_tol`` (|γ(q_s)/γ_s − 1|).

    Raises :class:`InputError` for a knob out of range, :class:`NotConverged` when the solver
    misses its tolerance.
    """
    return _native.evaluate(
        _scene(scene),
        a.count(sigma_points, "sigma_points", "accuracy.sigma_points"),
        _opt_number(sigma_max, "sigma_max", "accuracy.sigma_max"),
        _opt_number(rtol, "rtol", "accuracy.rtol"),
        _opt_number(adhesion_steps, "adhesion_steps", "accuracy.adhesion_steps"),
        _opt_number(adhesion_points, "adhesion_points", "accuracy.adhesion_points"),
        _opt_number(adhesion_tol, "adhesion_tol", "accuracy.adhesion_tol"),
        a.callback(progress),
    )


def _values(values: Any, field: str) -> List[float]:
    return a.numbers_list(values, field)


_OVER = {
    "pressure": "pressure",
    "thickness": "thickness",
    "thickness_qr": "thickness",
    "gamma": "gamma",
    "surface_energy_j_m2": "gamma",
}


def sweep(
    scene: Scene,
    pressures: Any = None,
    *,
    over: str = "pressure",
    values: Any = None,
    progress: Progress = None,
    cycle: bool = False,
    pressure: None = None,
) -> SweepResult:
    """A sweep of the theory over p* (``over="pressure"``, library
    ``asperity::theory::sweep::sweep``: continuation in the load, one shared energy table for
    the mean gap [S-12]), over t·q_r (``"thickness"``) or over γ_s in J/m² (``"gamma"``,
    library ``asperity::theory::knob::knob_sweep``: each value its own scene at the scene's
    p*, exactly what :func:`evaluate` gives for it).

    ``pressures`` (or ``values``, the name for any knob): ascending; evenly spaced ones (``np.geomspace`` for p* and t·q_r,
    ``np.linspace`` for γ_s) run as one sweep like the CLI's ``--from --to --points``, any
    other list one value at a time.

    Returns a :class:`SweepResult`: arrays by column (``p``, ``a_r``, ``a_r_unloading`` (the
    second, unloading branch), ``branches``, ``mean_gap_rel``, ``mean_gap_lower_rel``,
    ``mean_gap_upper_rel``, ``mean_contact_stress``, ``contact_stress_variance``,
    ``elastic_energy`` (J/m²), ``thickness_qr``, ``gamma``, ...), NaN where a row failed and
    ``reasons`` beside them; ``window_edges``, ``jump_in_pressure``, ``pull_off_pressure``;
    ``to_dict()`` has the keys of ``asperity sweep --format json``.

    ``cycle=True`` (load sweeps over log-spaced loads, ``np.geomspace``): also the theory's
    path along the load cycle, ``res.cycle`` (a :class:`CycleResult`, see :func:`cycle`), as
    ``asperity sweep --cycle``.

    ``pressure`` is not a knob of a sweep: it raises :class:`InputError` naming ``pressures``
    (the loads to sweep); a thickness or γ_s sweep runs at the scene's own p*
    (``scene.replace(pressure=...)``), as the CLI's ``sweep --over thickness --pressure``.
    """
    if pressure is not None:
        raise InputError(
            f"invalid pressure = {pressure!r}: sweep() takes the loads to sweep as `pressures` "
            "(or `values`); a thickness or gamma sweep runs at the scene's p* (scene.replace(pressure=...))",
            field="pressure",
            value=repr(pressure),
            allowed="`pressures` for the loads to sweep, or the scene's pressure",
        )
    knob = _OVER.get(over) if isinstance(over, str) else None
    if knob is None:
        raise InputError(
            f"invalid over = {over!r}: allowed pressure, thickness or gamma",
            field="over",
            value=repr(over),
            allowed="pressure, thickness (thickness_qr) or gamma (surface_energy_j_m2)",
        )
    if (pressures is None) == (values is None):
        raise TypeError("sweep() takes the values to sweep once: as `pressures` (positional) or as `values`")
    field = "pressures" if values is None else "values"
    given = pressures if values is None else values
    return SweepResult(
        _native.sweep(_scene(scene), _values(given, field), knob, a.callback(progress), a.flag(cycle, "cycle"))
    )


def sweep_thickness(scene: Scene, thickness_qr: Any, *, progress: Progress = None) -> SweepResult:
    """:func:`sweep` over t·q_r (finite values, ascending) at the scene's p* ([S] Fig. 7)."""
    return sweep(scene, over="thickness", values=_values(thickness_qr, "thickness_qr"), progress=progress)


def sweep_gamma(scene: Scene, surface_energy_j_m2: Any, *, progress: Progress = None) -> SweepResult:
    """:func:`sweep` over γ_s in J/m² (ascending, from 0 allowed) at the scene's p*."""
    return sweep(scene, over="gamma", values=_values(surface_energy_j_m2, "surface_energy_j_m2"), progress=progress)


def _number(x: Any, field: str) -> float:
    return a.number(x, field)


def _count(x: Any, field: str) -> int:
    return a.count(x, field, "sweep.points")


def cycle(scene: Scene, from_: float, to: float, *, points: int = 64, progress: Progress = None) -> CycleResult:
    """The theory's path along a load cycle (``asperity sweep --cycle``): library
    ``asperity::theory::sweep::sweep`` over ``points`` log-spaced loads from ``from_`` up to
    ``to``, then ``asperity::theory::cycle::path_through_tension``.

    The path goes up on the loading branch (the lowest stable root, [S-3, S-14]), back down on
    the unloading branch (the highest stable root) while it exists, and on below ``from_`` into
    tension at p* = 0, −p₁, −2p₁, … (p₁ = ``from_``) on the contact branch to the theory's
    pull-off, bisected to 3 % (docs/physics.md §6.2); without adhesion it ends at p* → 0.

    Returns a :class:`CycleResult`: columns ``branch`` ("loading"/"unloading"), ``p``,
    ``a_r``, ``mean_gap_rel`` (NaN under tension), ``mean_contact_stress``,
    ``on_unloading_branch``; ``pull_off_pressure`` with ``pull_off_bracket``,
    ``tension_bound``, ``unloading_branch_ends``, ``jump_in_pressure``, ``note``;
    ``to_dict()`` is the ``cycle`` object of ``asperity sweep --cycle --format json``.
    Raises :class:`InputError` for loads out of range (``from_``, ``to`` > ``from_``,
    ``points``).
    """
    f, t, n = _number(from_, "from_"), _number(to, "to"), _count(points, "points")
    return CycleResult(_native.cycle(_scene(scene), f, t, n, a.callback(progress)))


def pull_off(scene: Scene, *, progress: Progress = None) -> PullOffResult:
    """The pull-off read-out of ``scene`` (``asperity run --pull-off``): library
    ``asperity::report::pull_off::pull_off``.

    The theory's pull-off p* (≤ 0, in units of E*ḡ) along the tensile path 0, −10⁻⁴, −2·10⁻⁴,
    … bisected to 3 % (docs/physics.md §6.2), the two DMT routes' from the PSD alone (BAM and
    the gap distribution's attraction, §6.3), GFMD's measured pull-off at the nearest stored
    case, and how far each was measured from GFMD there (§6.4): on the stored set the theory
    holds 0–4 % of GFMD's pull-off and the routes 15–420×, so none is an estimate.

    Returns a :class:`PullOffResult`; ``to_dict()`` is the ``pull_off`` object of
    ``asperity run --pull-off --format json``. Takes 0.1–3 s on system II.
    """
    return PullOffResult(_native.pull_off(_scene(scene), a.callback(progress)))


def gfmd(
    scene: Scene,
    heights: Any = None,
    size: Optional[float] = None,
    *,
    grid: Optional[int] = None,
    seed: int = 1,
    tolerance: float = 1e-8,
    max_iterations: Optional[int] = None,
    bins: Optional[int] = None,
    method: str = "auto",
    rescale: bool = True,
    progress: Progress = None,
) -> GfmdResult:
    """A brute-force GFMD run of the scene (``asperity gfmd``): library
    ``asperity::gfmd::run``, with the theory on the same map's discrete spectrum beside it.

    Without ``heights`` a self-affine map is generated (``seed``) on the preset's reduced grid
    (L/λ_r, λ_r/λ_s, λ_s/Δa of its ``[gfmd]`` table, N = their product) or on ``grid`` N×N
    keeping L/λ_r and λ_s/Δa; γ_s and ρ are rescaled to keep γ̃_glo and the Tabor parameter
    unless ``rescale=False``. With ``heights`` (a square 2-D array in m, rows along y, with
    ``size`` its side in m, or a Topography-like object) GFMD runs on that map (and on the
    map of a scene from :meth:`Scene.with_surface` when no heights are given).

    p* is the scene's, reduced by the map's own ḡ. ``tolerance``: relative force residual;
    ``method``: "auto", "pk" (Polonsky-Keer) or "fire".

    Returns a :class:`GfmdResult` with the keys of ``asperity gfmd --format json`` (``a_r``,
    ``mean_contact_stress``, ``pr``, ``mean_gap_rel``, ``theory``, ``iterations``, ...) and
    ``heights`` (the map). Raises :class:`NotConverged` when the relaxation misses its
    tolerance within ``max_iterations`` steps; Ctrl-C stops it within one step.
    """
    m, knobs = _given_map(heights, size), _gfmd_knobs(grid, seed, tolerance, max_iterations, bins, method, rescale)
    r = GfmdResult(_native.gfmd(_scene(scene), m, knobs, a.callback(progress)))
    _warn_resolution(r)
    return r


def _given_map(heights: Any, size: Any) -> "_native.GivenMap":
    """The map GFMD runs on (None: generated) with its x side in m."""
    if heights is not None:
        arr, size_m, _, _ = as_map(heights, size)
        return arr, size_m
    if size is not None:
        raise InputError(
            f"invalid size = {a.shown(size)}: allowed None without heights",
            field="size",
            value=a.shown(size),
            allowed="None without heights",
        )
    return None, None


def _gfmd_knobs(
    grid: Any, seed: Any, tolerance: Any, max_iterations: Any, bins: Any, method: Any, rescale: Any
) -> "_native.GfmdKnobs":
    """GFMD's knobs checked, as the extension takes them."""
    return (
        _opt_count(grid, "grid", "gfmd.grid"),
        a.seed(seed),
        a.number(tolerance, "tolerance", "gfmd.tolerance"),
        _opt_count(max_iterations, "max_iterations", "gfmd.max_iterations"),
        _opt_count(bins, "bins", "gfmd.bins"),
        a.choice(method, "method", ("auto", "pk", "fire")),
        a.flag(rescale, "rescale"),
    )


def _warn_resolution(res: Result, stacklevel: int = 3) -> None:
    """The CLI's note on an under-resolved attraction, as a :class:`ResolutionWarning`:
    (γ_s/E*)·Δa/ρ² above the library's limit on the grid GFMD ran (a sweep's or cycle's
    under ``reduction``, None for a given map)."""
    red = res["reduction"] if "reduction" in res else None
    r = res["adhesion_resolution"] if "adhesion_resolution" in res else (red or {}).get("adhesion_resolution")
    limit = float(_native.ADHESION_RESOLUTION_MAX)
    if isinstance(r, (int, float)) and r > limit:
        warnings.warn(
            f"(gamma/E*)*da/rho^2 = {r:.3f} > {limit:g}: the attraction is under-resolved on this grid "
            "(docs/physics.md §6); raise points_per_short_wavelength in the preset's [gfmd] table or pass a finer grid",
            ResolutionWarning,
            stacklevel=stacklevel,
        )


def gfmd_cycle(
    scene: Scene,
    from_: float,
    to: float,
    *,
    points: int = 8,
    heights: Any = None,
    size: Optional[float] = None,
    grid: Optional[int] = None,
    seed: int = 1,
    tolerance: float = 1e-8,
    max_iterations: Optional[int] = None,
    bins: Optional[int] = None,
    method: str = "auto",
    rescale: bool = True,
    progress: Progress = None,
) -> GfmdCycleResult:
    """GFMD through the adhesive load cycle (``asperity gfmd --cycle``): library
    ``asperity::gfmd::cycle::run_cycle`` on one map (generated or given as for :func:`gfmd`),
    every load warm-started from the last relaxed state (quasi-static, load control).

    Loading from p* = ``from_`` up to ``to`` over ``points`` log-spaced loads, unloading back
    down to ``from_``, then (with adhesion) into tension at p* = 0, −p₁, −2p₁, … until the body
    leaves the substrate, the bracket bisected to 3 % of the pull-off. Without adhesion
    unloading retraces loading and the pull-off is 0; with adhesion unloading keeps more
    contact than loading at the same load.

    Returns a :class:`GfmdCycleResult`: columns ``branch``, ``p``, ``a_r``, ``mean_gap_rel``,
    ``mean_contact_stress``, ... in the order visited; ``pull_off_pressure`` with
    ``pull_off_bracket``, ``jump_in_pressure`` with ``jump_in_bracket``, ``note``, ``theory``
    (the theory's sweep on the same map) and ``theory_cycle`` (its path along the same cycle, a
    :class:`CycleResult`); ``to_dict()`` has the keys of ``asperity gfmd --cycle --format
    json``. Raises :class:`InputError` before any work for bad input (``to`` below ``from_``,
    ``grid`` < 4, ...), :class:`NotConverged` when a load misses its tolerance; Ctrl-C stops it
    within one relaxation step.
    """
    loads = _number(from_, "from_"), _number(to, "to"), _count(points, "points")
    m, knobs = _given_map(heights, size), _gfmd_knobs(grid, seed, tolerance, max_iterations, bins, method, rescale)
    return GfmdCycleResult(_gfmd_walk(scene, loads, m, knobs, progress, True))


def gfmd_sweep(
    scene: Scene,
    from_: float,
    to: float,
    *,
    points: int = 8,
    heights: Any = None,
    size: Optional[float] = None,
    grid: Optional[int] = None,
    seed: int = 1,
    tolerance: float = 1e-8,
    max_iterations: Optional[int] = None,
    bins: Optional[int] = None,
    method: str = "auto",
    rescale: bool = True,
    progress: Progress = None,
) -> GfmdSweepResult:
    """A one-way GFMD load sweep on one map (``asperity gfmd --from A --to B``): ``points``
    log-spaced loads from p* = ``from_`` to ``to``, each warm-started from the last relaxed
    state. ``to`` ≥ ``from_`` loads (library ``asperity::gfmd::sweep::run_sweep``, with the
    theory's sweep on the same map under ``theory``); ``to`` < ``from_`` unloads (the cycle's
    walk without the way up: rows with ``branch``, and ``pull_off_pressure`` and
    ``theory_cycle`` as in :func:`gfmd_cycle`).

    Returns a :class:`GfmdSweepResult` with the keys of ``asperity gfmd --from A --to B
    --format json`` (columns ``p``, ``a_r``, ``mean_gap_rel``, ``mean_contact_stress``, ...).
    Raises :class:`InputError` before any work for bad input, :class:`NotConverged` when a load
    misses its tolerance; Ctrl-C stops it within one relaxation step.
    """
    loads = _number(from_, "from_"), _number(to, "to"), _count(points, "points")
    m, knobs = _given_map(heights, size), _gfmd_knobs(grid, seed, tolerance, max_iterations, bins, method, rescale)
    return GfmdSweepResult(_gfmd_walk(scene, loads, m, knobs, progress, False))


def _gfmd_walk(
    scene: Scene, loads: "tuple[float, float, int]", m: "_native.GivenMap", knobs: "_native.GfmdKnobs", progress: Progress, cycle: bool
) -> Result:
    """The library's walk over loads of :func:`gfmd_cycle` and :func:`gfmd_sweep` on their
    checked arguments."""
    walk = _native.gfmd_cycle(_scene(scene), *loads, m, knobs, a.callback(progress), cycle)
    _warn_resolution(walk, 4)
    return walk


#: Metres per unit of the ``height_unit`` and ``size_unit`` arguments (the readers' units).
UNITS: Dict[str, float] = {"m": 1.0, "mm": 1e-3, "um": 1e-6, "µm": 1e-6, "nm": 1e-9, "pm": 1e-12}

#: The range of h_rms (m) a physical rough surface has, from an atomically flat one (0.01 nm)
#: to a coarse one (1 cm); outside it the heights' unit is most likely not the stated one.
PHYSICAL_RMS_HEIGHT_M = (1e-11, 1e-2)
#: The range of the rms gradient ḡ a physical rough surface has (slopes of 0.006° to 84°);
#: outside it the side's unit (or the heights') is most likely not the stated one.
PHYSICAL_RMS_GRADIENT = (1e-4, 10.0)


def _unit(x: Any, name: str) -> float:
    return UNITS[a.choice(x, name, ("m", "mm", "um", "µm", "nm", "pm"))]


def _warn_units(rms_height_m: Any, rms_gradient: Any, units: str, stacklevel: int = 3) -> None:
    """A :class:`UnitWarning` (one line) when h_rms or ḡ lies outside any physical range."""
    odd = []
    lo, hi = PHYSICAL_RMS_HEIGHT_M
    if isinstance(rms_height_m, float) and math.isfinite(rms_height_m) and not lo <= rms_height_m <= hi:
        odd.append(f"h_rms = {rms_height_m:.3g} m (physical: {lo:g} to {hi:g} m)")
    lo, hi = PHYSICAL_RMS_GRADIENT
    if isinstance(rms_gradient, float) and math.isfinite(rms_gradient) and rms_gradient > 0 and not lo <= rms_gradient <= hi:
        odd.append(f"rms gradient = {rms_gradient:.3g} (physical: {lo:g} to {hi:g})")
    if odd:
        warnings.warn(
            f"{' and '.join(odd)} with {units}: check height_unit and size_unit", UnitWarning, stacklevel=stacklevel
        )


def _rms(heights: np.ndarray, spacing: float) -> "tuple[float, float]":
    """h_rms and ḡ (forward differences inside the map) of a map in m with spacing in m."""
    h = heights - heights.mean()
    g2 = 0.0
    if heights.shape[1] > 1:
        g2 += float(np.mean(np.diff(heights, axis=1) ** 2)) / spacing**2
    if heights.shape[0] > 1:
        g2 += float(np.mean(np.diff(heights, axis=0) ** 2)) / spacing**2
    return float(np.sqrt(np.mean(h**2))), math.sqrt(g2)


def psd(
    heights: Any,
    size: Optional[float] = None,
    *,
    periodic: Optional[bool] = None,
    bins_per_decade: float = 10.0,
    height_unit: str = "m",
    size_unit: str = "m",
) -> PsdResult:
    """The PSD of a height map (``asperity psd``): library ``asperity::surface::psd::analyse``.

    ``heights``: a 2-D array (rows along y; 1-D: a line scan) in ``height_unit`` ("m", "mm",
    "um", "nm" or "pm"; default m) with ``size`` its x side in ``size_unit`` (default m;
    1e-12 m <= size <= 1000 m, as the CLI's ``--size``), or a Topography-like object
    (SurfaceTopography's: ``heights()``, ``physical_sizes``, ``is_periodic``). A masked array
    is refused (fill it first: ``np.ma.filled(a, a.mean())``). A plane is removed and a Hann
    window applied unless ``periodic`` (default: the topography's ``is_periodic``, else
    False). Returns a :class:`PsdResult`: ``q`` (1/m), ``psd`` (C(q) in m⁴, isotropic 2-D
    [S-2]), ``rms_height_m``, ``rms_gradient`` ḡ, ``rms_curvature`` (1/m), the self-affine fit
    (``hurst``, ``rolloff_wavelength_m``, ``short_wavelength_m`` with their ranges).

    Warns (:class:`UnitWarning`, one line) when h_rms or ḡ lies outside any physical range
    for the stated units (heights in nm passed as m give h_rms ~ 1e-9 of the truth and ḡ too).
    """
    hu, su = _unit(height_unit, "height_unit"), _unit(size_unit, "size_unit")
    arr, size_m, source, topo_periodic = as_map(heights, size, size_unit=su)
    per = topo_periodic if periodic is None else a.flag(periodic, "periodic")
    bpd = a.number(bins_per_decade, "bins_per_decade", "psd.bins_per_decade")
    arr = arr * hu if hu != 1.0 else arr
    r = PsdResult(_native.psd(arr, size_m, bool(per), bpd, source))
    _warn_units(r.rms_height_m, r.rms_gradient, f"heights in {height_unit}, size in {size_unit}")
    return r


def read_surface(
    path: Union[str, "os.PathLike[str]"],
    *,
    size: Optional[float] = None,
    height_unit: Optional[str] = None,
    size_unit: str = "m",
) -> Surface:
    """A height map from a file (.txt .asc .dat .xyz .npy .gsf; library
    ``asperity::surface::readers::read``): a :class:`Surface` (``map`` in m, rows along y;
    ``size_m``; Topography-like ``heights()``/``physical_sizes``/``is_periodic``). ``size``:
    the x side in ``size_unit`` (default m; overrides the file's), as the CLI's ``--size``;
    ``height_unit``: "m", "mm", "um", "nm" or "pm" where the file states none, as the CLI's
    ``--height-unit``. Warns (:class:`UnitWarning`) when the map's h_rms or ḡ lies outside any
    physical range for these units."""
    if not isinstance(path, (str, os.PathLike)):
        raise a.refuse("path", path, "a file name (str or os.PathLike)")
    su = _unit(size_unit, "size_unit")
    size_m = None if size is None else size_in_metres(size, su)
    unit = None if height_unit is None else a.choice(height_unit, "height_unit", ("m", "mm", "um", "µm", "nm", "pm"))
    try:
        d = _native.read_surface(os.fspath(path), size_m, unit)
    except InputError as e:
        if e.field != "system_size_m":
            raise
        # the library's map side is this function's `size`
        raise InputError(
            str(e).replace("system_size_m", "size", 1), field="size", value=e.value, allowed=e.allowed, key=e.key
        ) from None
    s = Surface(d["heights"], d["size_m"], d["source"])
    h, g = _rms(s.map, s.spacing_m)
    heights_in = height_unit or "the file's unit"
    side = f"size in {size_unit}" if size is not None else "the file's size"
    _warn_units(h, g, f"heights in {heights_in}, {side}")
    return s


def generate_surface(
    *,
    grid: int = 256,
    system_size_m: float = 1e-4,
    hurst: float = 0.8,
    rolloff_wavelength_m: Optional[float] = None,
    short_wavelength_m: Optional[float] = None,
    rms_gradient: Optional[float] = None,
    rms_height_m: Optional[float] = None,
    seed: int = 1,
    periodic: bool = True,
    output: Union[str, "os.PathLike[str]", None] = None,
) -> Surface:
    """A seeded self-affine height map (``asperity surface generate``): library
    ``asperity::surface::generate``, the generator GFMD uses (Fourier filtering with
    deterministic amplitudes and random phases, docs/physics.md §1).

    ``grid`` N (the map is N×N, 4…), ``system_size_m`` L, ``hurst`` H, ``rolloff_wavelength_m``
    λ_r (default L/2), ``short_wavelength_m`` λ_s (default 4L/N: four points per λ_s), and
    ``rms_gradient`` ḡ (default 1) or ``rms_height_m`` h_rms; the same ``seed`` gives the same
    map as the CLI's on every platform. ``periodic=False`` cuts the map out of a periodic one
    of twice the side, as a measured map would be. ``output``: also write it (.txt .asc .dat
    .xyz .npy .gsf, by the extension; :meth:`Surface.write` does the same later).

    Returns a :class:`Surface` that every function taking a map takes (:func:`psd`,
    :func:`gfmd`, :meth:`Scene.with_surface`); ``rms_height_m`` and ``rms_gradient`` are the
    map's own (periodic: ḡ is the requested one to round-off).
    """
    if rms_gradient is not None and rms_height_m is not None:
        raise InputError(
            "invalid rms_height_m: allowed rms_gradient or rms_height_m, not both",
            field="rms_height_m",
            value=a.shown(rms_height_m),
            allowed="rms_gradient or rms_height_m, not both",
        )
    d = _native.generate_surface(
        a.count(grid, "grid", "gfmd.grid"),
        a.number(system_size_m, "system_size_m", "surface.system_size_m"),
        a.number(hurst, "hurst", "surface.hurst"),
        _opt_number(rolloff_wavelength_m, "rolloff_wavelength_m", "surface.rolloff_wavelength_m"),
        _opt_number(short_wavelength_m, "short_wavelength_m", "surface.short_wavelength_m"),
        _opt_number(rms_gradient, "rms_gradient", "surface.rms_gradient"),
        _opt_number(rms_height_m, "rms_height_m", "surface.rms_height_m"),
        a.seed(seed),
        a.flag(periodic, "periodic"),
    )
    s = Surface(d["heights"], d["size_m"], "generated", periodic=bool(d["periodic"]))
    s.rms_height_m = float(d["rms_height_m"])
    s.rms_gradient = float(d["rms_gradient"])
    if output is not None:
        s.write(output)
    return s


def _csv(reference: Mapping[str, Any]) -> str:
    cols = list(reference)
    if not cols or not all(isinstance(c, str) for c in cols):
        raise a.refuse("reference", reference, "a mapping of column names (p, a_r, ...) to arrays")
    arrays = [np.asarray(a.numbers_list(reference[c], "reference", missing=True), dtype=float) for c in cols]
    n = len(arrays[0])
    if any(len(x) != n for x in arrays):
        lengths = ", ".join(f"{c}: {len(x)}" for c, x in zip(cols, arrays))
        raise InputError(
            f"invalid reference = columns of lengths {lengths}: allowed columns of one length",
            field="reference",
            value=f"columns of lengths {lengths}",
            allowed="columns of one length",
        )
    out = io.StringIO()
    out.write(",".join(cols) + "\n")
    for i in range(n):
        out.write(",".join("" if math.isnan(x[i]) else repr(float(x[i])) for x in arrays) + "\n")
    return out.getvalue()


def gauge(
    scene: Scene,
    fit: Union[str, Sequence[str]] = ("c1", "c2"),
    reference: Union[str, "os.PathLike[str]", Mapping[str, Any]] = "eq18",
    *,
    from_: Optional[float] = None,
    to: Optional[float] = None,
    points: Optional[int] = None,
    observables: Optional[Sequence[str]] = None,
    progress: Progress = None,
) -> GaugeResult:
    """Fits coefficients of the custom model [S-17] (``fit``: c1, c2, alpha, k_griffith, w0) to
    a reference (``asperity gauge``): library ``asperity::fit::fit`` (weighted least squares,
    Levenberg-Marquardt).

    ``reference``: ``"eq18"`` (the closed form [S-18] at ``points`` loads from ``from_`` to
    ``to``, on the scene made adhesionless and semi-infinite), a CSV file, or a mapping of
    columns (``p``, ``a_r``, ``a_r_err``, ``mean_contact_stress``, ``mean_contact_stress_err``,
    ``mean_gap_rel``, ``mean_gap_rel_err``; arrays of one length, NaN for a missing value).
    Returns a :class:`GaugeResult` with the keys of ``asperity gauge --format json`` (``params``
    with values and standard errors, ``correlation``, ``chi2``, ``model``, ``start``, ...).
    """
    names = ",".join(a.text_list(fit, "fit", "a coefficient name or a list of them (c1, c2, alpha, k_griffith, w0)"))
    obs = None if observables is None else a.text_list(observables, "observables", "a list of a_r, mean_contact_stress, mean_gap_rel, pr")
    f = _opt_number(from_, "from_", "load.pressure")
    t = _opt_number(to, "to", "load.pressure")
    n = _opt_count(points, "points", "sweep.points")
    cb = a.callback(progress)
    if isinstance(reference, Mapping):
        return GaugeResult(_native.gauge(_scene(scene), names, "data", _csv(reference), f, t, n, obs, cb))
    if not isinstance(reference, (str, os.PathLike)):
        raise a.refuse("reference", reference, '"eq18", a CSV file or a mapping of columns')
    return GaugeResult(_native.gauge(_scene(scene), names, os.fspath(reference), None, f, t, n, obs, cb))
