"""The bad-call corpus: every function × every keyword × values of the wrong type, NaN and
infinities, negatives and non-whole numbers for counts, huge and tiny numbers, and each
range's own edges just outside (read from the library's range table). Every call must be
refused before any work with an `InputError` whose `field` is the argument (or a `TypeError`
naming it) — never an `OverflowError`, an `IndexError`, or a message without the argument.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any, Callable, Dict, List, Tuple, cast

import numpy as np
import pytest

import asperity
from asperity import _native

REPO = Path(__file__).resolve().parents[2]
S1 = asperity.Scene.preset("system-1")
MAP = np.outer(np.sin(np.linspace(0, 6, 16)), np.cos(np.linspace(0, 5, 16))) * 1e-6

# values no scalar argument takes
WRONG_TYPE: List[Any] = ["x", object(), [1.0, 2.0], {"a": 1}, 1 + 2j, b"1"]
NOT_FINITE: List[Any] = [math.nan, math.inf, -math.inf, 10**400, -(10**400)]
NOT_WHOLE: List[Any] = [1.5, -1, 2**64, 10**30, -(2**63), True]


def outside(key: str, name: str) -> List[float]:
    """Numbers just outside the library's range of `key`."""
    r = _native.allowed(key, name)
    assert r is not None, key
    out: List[float] = []
    lo, hi = r["lo"], r["hi"]
    if lo is not None:
        out.append(lo if not r["lo_inclusive"] else (lo / 2 if lo > 0 else lo - 1))
        if lo > 0:
            out.append(-lo)
    if hi is not None:
        out.append(hi if not r["hi_inclusive"] else (hi * 2 if hi > 0 else hi + 1))
    return out


def number(key: str, name: str) -> List[Any]:
    return WRONG_TYPE + NOT_FINITE + [True] + outside(key, name)


def count(key: str, name: str) -> List[Any]:
    return WRONG_TYPE + [math.nan, math.inf] + NOT_WHOLE + outside(key, name)


SEED = WRONG_TYPE + [math.nan, 1.5, -1, 2**64, 10**30, True]
FLAG = ["x", 1, 0, 1.5, object(), [True]]
CHOICE = ["x", 1, None, object(), "", ["m"]]
LIST = ["x", [], [[1.0, 2.0]], [math.nan], [math.inf], object(), {"a": 1.0}, np.ma.array([1.0, 2.0], mask=[False, True])]
CALLBACK = [1, "x", [print]]
TEXTS = [1, object(), [1, 2], [], b"c1"]

# (function, positional arguments, base keywords, keyword under test, bad values)
Case = Tuple[str, Callable[..., Any], Tuple[Any, ...], Dict[str, Any], str, List[Any]]


def cases() -> List[Case]:
    out: List[Case] = []

    def add(label: str, f: Callable[..., Any], args: Tuple[Any, ...], base: Dict[str, Any], kw: str, bad: List[Any]) -> None:
        for v in bad:
            out.append((label, f, args, base, kw, [v]))

    ev = asperity.evaluate
    add("evaluate", ev, (S1,), {}, "sigma_points", count("accuracy.sigma_points", "sigma_points"))
    for k in ("sigma_max", "rtol", "adhesion_steps", "adhesion_points", "adhesion_tol"):
        add("evaluate", ev, (S1,), {}, k, number(f"accuracy.{k}", k))
    add("evaluate", ev, (S1,), {}, "progress", CALLBACK)

    sw = asperity.sweep
    add("sweep", sw, (S1,), {}, "values", LIST)
    add("sweep", sw, (S1, [0.01, 0.02]), {}, "over", CHOICE)
    add("sweep", sw, (S1, [0.01, 0.02]), {}, "cycle", FLAG)
    add("sweep", sw, (S1, [0.01, 0.02]), {}, "progress", CALLBACK)
    add("sweep_thickness", asperity.sweep_thickness, (S1,), {}, "thickness_qr", LIST)
    add("sweep_gamma", asperity.sweep_gamma, (S1,), {}, "surface_energy_j_m2", LIST)

    cy = asperity.cycle
    for k in ("from_", "to"):
        add("cycle", cy, (S1,), {"from_": 1e-3, "to": 1e-2}, k, WRONG_TYPE + NOT_FINITE + [True])
    add("cycle", cy, (S1, 1e-3, 1e-2), {}, "points", count("sweep.points", "points"))
    add("cycle", cy, (S1, 1e-3, 1e-2), {}, "progress", CALLBACK)

    small = {"grid": 16, "max_iterations": 50}
    for label, f, args in (
        ("gfmd", asperity.gfmd, (S1,)),
        ("gfmd_cycle", asperity.gfmd_cycle, (S1, 1e-3, 1e-2)),
        ("gfmd_sweep", asperity.gfmd_sweep, (S1, 1e-3, 1e-2)),
    ):
        add(label, f, args, small, "grid", count("gfmd.grid", "grid"))
        add(label, f, args, small, "seed", SEED)
        add(label, f, args, small, "tolerance", number("gfmd.tolerance", "tolerance"))
        add(label, f, args, {"grid": 16}, "max_iterations", count("gfmd.max_iterations", "max_iterations"))
        add(label, f, args, small, "bins", count("gfmd.bins", "bins"))
        add(label, f, args, small, "method", CHOICE)
        add(label, f, args, small, "rescale", FLAG)
        add(label, f, args, small, "progress", CALLBACK)
        add(label, f, args, {"max_iterations": 50}, "size", WRONG_TYPE + NOT_FINITE + outside("surface.system_size_m", "size"))
    for label, f in (("gfmd_cycle", asperity.gfmd_cycle), ("gfmd_sweep", asperity.gfmd_sweep)):
        add(label, f, (S1, 1e-3, 1e-2), small, "points", count("sweep.points", "points"))
        for k in ("from_", "to"):
            add(label, f, (S1,), {**small, "from_": 1e-3, "to": 1e-2}, k, WRONG_TYPE + NOT_FINITE + [True])

    ps = asperity.psd
    add("psd", ps, (MAP,), {}, "size", number("surface.system_size_m", "size") + [1e-320, 1e308])
    add("psd", ps, (MAP, 1e-4), {}, "bins_per_decade", number("psd.bins_per_decade", "bins_per_decade"))
    add("psd", ps, (MAP, 1e-4), {}, "periodic", FLAG)
    add("psd", ps, (MAP, 1e-4), {}, "height_unit", CHOICE)
    add("psd", ps, (MAP, 1e-4), {}, "size_unit", CHOICE)
    add("psd", ps, (), {"size": 1e-4}, "heights", ["x", object(), np.zeros((2, 2, 2)), MAP.astype(complex), np.ma.array(MAP, mask=MAP > 0), np.full((4, 4), np.nan), [[0.0, math.inf], [1.0, 2.0]]])

    sample = str(REPO / "data" / "samples" / "map.txt")
    rs = asperity.read_surface
    add("read_surface", rs, (sample,), {}, "size", number("surface.system_size_m", "size"))
    add("read_surface", rs, (sample,), {}, "height_unit", [c for c in CHOICE if c is not None])
    add("read_surface", rs, (sample,), {}, "size_unit", CHOICE)
    add("read_surface", rs, (), {}, "path", [1, None, object()])

    gs = asperity.generate_surface
    base = {"grid": 16}
    add("generate_surface", gs, (), {}, "grid", count("gfmd.grid", "grid"))
    for k, key in (
        ("system_size_m", "surface.system_size_m"),
        ("hurst", "surface.hurst"),
        ("rolloff_wavelength_m", "surface.rolloff_wavelength_m"),
        ("short_wavelength_m", "surface.short_wavelength_m"),
        ("rms_gradient", "surface.rms_gradient"),
        ("rms_height_m", "surface.rms_height_m"),
    ):
        add("generate_surface", gs, (), base, k, number(key, k))
    add("generate_surface", gs, (), base, "seed", SEED)
    add("generate_surface", gs, (), base, "periodic", FLAG)
    add("generate_surface", gs, (), base, "output", [1, object(), [b"x"], "/tmp/map.png", str(REPO)])

    ga = asperity.gauge
    add("gauge", ga, (S1,), {"points": 3}, "fit", TEXTS)
    add("gauge", ga, (S1,), {"points": 3}, "observables", TEXTS)
    for k in ("from_", "to"):
        add("gauge", ga, (S1,), {"points": 3}, k, number("load.pressure", k))
    add("gauge", ga, (S1,), {}, "points", count("sweep.points", "points"))
    add("gauge", ga, (S1,), {"points": 3}, "progress", CALLBACK)
    add(
        "gauge",
        ga,
        (S1,),
        {},
        "reference",
        [1, object(), {"p": [1e-3, 1e-2], "a_r": [0.1]}, {"p": "x", "a_r": [0.1]}, {1: [1.0]}, {}],
    )

    rp = S1.replace
    for k, key in (
        ("pressure", "load.pressure"),
        ("surface_energy_j_m2", "adhesion.surface_energy_j_m2"),
        ("range_m", "adhesion.range_m"),
        ("contact_modulus_pa", "material.contact_modulus_pa"),
        ("hurst", "surface.hurst"),
        ("rms_gradient", "surface.rms_gradient"),
        ("system_size_m", "surface.system_size_m"),
    ):
        add("Scene.replace", rp, (), {}, k, WRONG_TYPE + NOT_FINITE + [True] + outside(key, k))
    add("Scene.preset", asperity.Scene.preset, (), {}, "name_or_path", [1, None, object()])
    ws = S1.with_surface
    add("Scene.with_surface", ws, (MAP, 1e-4), {}, "periodic", FLAG)
    for k in ("qmin", "qmax"):
        add("Scene.with_surface", ws, (MAP, 1e-4), {}, k, WRONG_TYPE + NOT_FINITE + [True])
    return out


CASES = cases()


def test_the_corpus_is_large() -> None:
    assert len(CASES) >= 500, len(CASES)
    assert len({(c[0], c[4]) for c in CASES}) >= 80


@pytest.mark.parametrize("case", CASES, ids=[f"{c[0]}-{c[4]}-{i}" for i, c in enumerate(CASES)])
def test_bad_argument_is_refused_naming_it(case: Case) -> None:
    label, f, args, base, kw, (value,) = case
    kwargs = {**base, kw: value}
    with pytest.raises((asperity.InputError, TypeError)) as info:
        f(*args, **kwargs)
    e = info.value
    assert not isinstance(e, (OverflowError, IndexError)), f"{label}({kw}={value!r}): {type(e).__name__}: {e}"
    message = str(e)
    assert kw in message, f"{label}({kw}={value!r}): the message does not name {kw}: {message}"
    assert "\n" not in message and len(message) <= 400, message
    if isinstance(e, asperity.InputError):
        assert e.field == kw, f"{label}({kw}={value!r}): field {e.field!r}: {message}"


def test_the_issue_examples() -> None:
    with pytest.raises(asperity.InputError, match="seed"):
        asperity.gfmd(S1, seed=-1)
    with pytest.raises(asperity.InputError, match="sigma_points"):
        asperity.evaluate(S1, sigma_points=-1)
    with pytest.raises(asperity.InputError, match="grid"):
        asperity.gfmd(S1, grid=cast(Any, 1.5))
    with pytest.raises(asperity.InputError, match="reference"):
        asperity.gauge(S1, reference={"p": [1e-3, 1e-2], "a_r": [0.1]})
    for size in (1e-320, 1e308):
        with pytest.raises(asperity.InputError, match="size") as info:
            asperity.psd(MAP, size)
        assert "1e-12 <= size <= 1000" in str(info.value)
    with pytest.raises(asperity.InputError, match="masked"):
        asperity.psd(np.ma.array(MAP, mask=MAP > 0), 1e-4)


def test_good_values_at_the_range_edges_pass() -> None:
    # a whole float is a count; a numpy integer is a seed; the bounds themselves are allowed
    r = asperity.evaluate(S1, sigma_points=cast(Any, 51.0))
    assert len(r.pr.sigma) == 51
    r_size = _native.allowed("surface.system_size_m", "size")
    assert r_size is not None
    lo = r_size["lo"]
    surface = asperity.generate_surface(grid=cast(Any, np.int64(16)), seed=cast(Any, np.uint64(2**64 - 1)))
    assert surface.map.shape == (16, 16)
    assert asperity.psd(MAP, 1e-4 * 1e6, size_unit="um").system_size_m == pytest.approx(1e-4)
    assert lo == 1e-12
