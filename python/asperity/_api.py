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
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Union

import numpy as np

from . import _native
from ._errors import InputError
from ._results import CycleResult, GfmdCycleResult, GfmdResult, GfmdSweepResult, PsdResult, Report, Result, SweepResult
from ._scene import Scene, Surface, as_map

__all__ = [
    "evaluate",
    "sweep",
    "sweep_thickness",
    "sweep_gamma",
    "cycle",
    "gfmd",
    "gfmd_cycle",
    "psd",
    "read_surface",
    "gauge",
]

Progress = Optional[Callable[[Dict[str, Any]], Any]]


def _scene(scene: Any) -> "_native.SceneCore":
    if not isinstance(scene, Scene):
        raise TypeError(f"expected an asperity.Scene, got {type(scene).__name__}")
    return scene._core


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
    return Report(
        _native.evaluate(
            _scene(scene), sigma_points, sigma_max, rtol, adhesion_steps, adhesion_points, adhesion_tol, progress
        )
    )


def _values(values: Any, field: str) -> List[float]:
    try:
        arr = np.asarray(values, dtype=float).ravel()
    except (TypeError, ValueError):
        raise InputError(
            f"invalid {field} = {values!r}: allowed a list of numbers",
            field=field,
            value=repr(values),
            allowed="a list of numbers",
        ) from None
    return [float(x) for x in arr]


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
    knob = _OVER.get(over)
    if knob is None:
        raise InputError(
            f"invalid over = {over!r}: allowed pressure, thickness or gamma",
            field="over",
            value=repr(over),
            allowed="pressure, thickness (thickness_qr) or gamma (surface_energy_j_m2)",
        )
    if (pressures is None) == (values is None):
        raise TypeError("sweep() takes the values to sweep once: as `pressures` (positional) or as `values`")
    field = {"pressure": "pressures", "thickness": "thickness_qr", "gamma": "surface_energy_j_m2"}[knob]
    given = pressures if values is None else values
    return SweepResult(_native.sweep(_scene(scene), _values(given, field), knob, progress, bool(cycle)))


def sweep_thickness(scene: Scene, thickness_qr: Any, *, progress: Progress = None) -> SweepResult:
    """:func:`sweep` over t·q_r (finite values, ascending) at the scene's p* ([S] Fig. 7)."""
    return sweep(scene, over="thickness", values=thickness_qr, progress=progress)


def sweep_gamma(scene: Scene, surface_energy_j_m2: Any, *, progress: Progress = None) -> SweepResult:
    """:func:`sweep` over γ_s in J/m² (ascending, from 0 allowed) at the scene's p*."""
    return sweep(scene, over="gamma", values=surface_energy_j_m2, progress=progress)


def _number(x: Any, field: str) -> float:
    if isinstance(x, bool) or not isinstance(x, (int, float, np.integer, np.floating)):
        raise InputError(
            f"invalid {field} = {x!r}: allowed a number",
            field=field,
            value=repr(x),
            allowed="a number",
        )
    return float(x)


def _count(x: Any, field: str) -> int:
    if isinstance(x, bool) or not isinstance(x, (int, np.integer)) or x < 1:
        raise InputError(
            f"invalid {field} = {x!r}: allowed a whole number >= 1",
            field=field,
            value=repr(x),
            allowed="a whole number >= 1",
        )
    return int(x)


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
    return CycleResult(_native.cycle(_scene(scene), f, t, n, progress))


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
    arr: Optional[np.ndarray] = None
    size_m: Optional[float] = None
    if heights is not None:
        arr, size_m, _ = as_map(heights, size)
    elif size is not None:
        raise InputError(
            "invalid size: allowed None without heights",
            field="size",
            value=repr(size),
            allowed="None without heights",
        )
    return GfmdResult(
        _native.gfmd(
            _scene(scene), arr, size_m, grid, seed, tolerance, max_iterations, bins, method, rescale, progress
        )
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
    return GfmdCycleResult(
        _gfmd_walk(scene, from_, to, points, heights, size, grid, seed, tolerance, max_iterations, bins, method, rescale, progress, True)
    )


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
    return GfmdSweepResult(
        _gfmd_walk(scene, from_, to, points, heights, size, grid, seed, tolerance, max_iterations, bins, method, rescale, progress, False)
    )


def _gfmd_walk(
    scene: Scene,
    from_: float,
    to: float,
    points: int,
    heights: Any,
    size: Optional[float],
    grid: Optional[int],
    seed: int,
    tolerance: float,
    max_iterations: Optional[int],
    bins: Optional[int],
    method: str,
    rescale: bool,
    progress: Progress,
    cycle: bool,
) -> Dict[str, Any]:
    """The arguments of :func:`gfmd_cycle` and :func:`gfmd_sweep` checked and passed to the
    library's walk over loads."""
    f, t, n = _number(from_, "from_"), _number(to, "to"), _count(points, "points")
    arr: Optional[np.ndarray] = None
    size_m: Optional[float] = None
    if heights is not None:
        arr, size_m, _ = as_map(heights, size)
    elif size is not None:
        raise InputError(
            "invalid size: allowed None without heights",
            field="size",
            value=repr(size),
            allowed="None without heights",
        )
    return _native.gfmd_cycle(
        _scene(scene), f, t, n, arr, size_m, grid, seed, tolerance, max_iterations, bins, method, rescale, progress, cycle
    )


def psd(heights: Any, size: Optional[float] = None, *, periodic: bool = False, bins_per_decade: float = 10.0) -> PsdResult:
    """The PSD of a height map (``asperity psd``): library ``asperity::surface::psd::analyse``.

    ``heights``: a 2-D array (m, rows along y; 1-D: a line scan) with ``size`` its x side in m,
    or a Topography-like object. A plane is removed and a Hann window applied unless
    ``periodic``. Returns a :class:`PsdResult`: ``q`` (1/m), ``psd`` (C(q) in m⁴, isotropic 2-D
    [S-2]), ``rms_height_m``, ``rms_gradient`` ḡ, ``rms_curvature`` (1/m), the self-affine fit
    (``hurst``, ``rolloff_wavelength_m``, ``short_wavelength_m`` with their ranges).
    """
    arr, size_m, source = as_map(heights, size)
    return PsdResult(_native.psd(arr, size_m, periodic, bins_per_decade, source))


def read_surface(
    path: Union[str, "os.PathLike[str]"], *, size: Optional[float] = None, height_unit: Optional[str] = None
) -> Surface:
    """A height map from a file (.txt .asc .dat .xyz .npy .gsf; library
    ``asperity::surface::readers::read``): a :class:`Surface` (``map`` in m, rows along y;
    ``size_m``; Topography-like ``heights()``/``physical_sizes``). ``size``: the x side in m
    (overrides the file's); ``height_unit``: "m", "mm", "um", "nm" or "pm" where the file
    states none."""
    d = _native.read_surface(os.fspath(path), size, height_unit)
    return Surface(d["heights"], d["size_m"], d["source"])


def _csv(reference: Mapping[str, Any]) -> str:
    cols = list(reference)
    arrays = [np.asarray(reference[c], dtype=float).ravel() for c in cols]
    n = len(arrays[0]) if arrays else 0
    out = io.StringIO()
    out.write(",".join(cols) + "\n")
    for i in range(n):
        out.write(",".join("" if math.isnan(a[i]) else repr(float(a[i])) for a in arrays) + "\n")
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
) -> Result:
    """Fits coefficients of the custom model [S-17] (``fit``: c1, c2, alpha, k_griffith, w0) to
    a reference (``asperity gauge``): library ``asperity::fit::fit`` (weighted least squares,
    Levenberg-Marquardt).

    ``reference``: ``"eq18"`` (the closed form [S-18] at ``points`` loads from ``from_`` to
    ``to``, on the scene made adhesionless and semi-infinite), a CSV file, or a mapping of
    columns (``p``, ``a_r``, ``a_r_err``, ``mean_contact_stress``, ``mean_contact_stress_err``,
    ``mean_gap_rel``, ``mean_gap_rel_err``; arrays). Returns a :class:`Result` with the keys of
    ``asperity gauge --format json`` (``params`` with values and standard errors,
    ``correlation``, ``chi2``, ``model``, ``start``, ...).
    """
    names = fit if isinstance(fit, str) else ",".join(fit)
    obs = None if observables is None else list(observables)
    if isinstance(reference, Mapping):
        return Result(
            _native.gauge(_scene(scene), names, "data", _csv(reference), from_, to, points, obs, progress)
        )
    return Result(
        _native.gauge(
            _scene(scene), names, os.fspath(reference), None, from_, to, points, obs, progress
        )
    )
