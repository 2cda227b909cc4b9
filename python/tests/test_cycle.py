"""Load cycles from Python: the theory's path (`asperity.cycle`, `sweep(..., cycle=True)`) and
GFMD's (`asperity.gfmd_cycle`) through tension to pull-off.

References: the CLI's JSON for the same case (`sweep --cycle`, `gfmd --cycle`), key by key to
PYTHON_CLI_REL; the theory's branches at one load from `evaluate` (the single-load solver that
scans for every root) to TRACKED_VS_SCANNED_REL; physics: without adhesion GFMD's minimum is
unique, so unloading retraces loading to GFMD_RETRACE_A_R and no tension is held (pull-off 0);
with adhesion unloading keeps at least as much contact as loading (contact hysteresis) and the
contact holds tension to a pull-off p* < 0 inside its bracket. Small cases (64² GFMD, a few
loads) keep each test within seconds on two cores."""

from __future__ import annotations

import _thread
import math
import signal
import threading
import time
from typing import Any, Dict, List, cast

import numpy as np
import pytest

import asperity
from conftest import compare, tolerance

REL = tolerance("PYTHON_CLI_REL")
RETRACE = tolerance("GFMD_RETRACE_A_R")
BRANCH_REL = tolerance("TRACKED_VS_SCANNED_REL")
STALL_S = 5.0  # a cancel slower than this never arrived (test_cancel.py)

# system II, model 3, t·q_r = 0.1, γ_s = 0.1256 J/m²: a hysteresis window from below p* = 1e-4
# up to the jump-in at p* ≈ 2.3e-4, and a contact branch that still exists at p* = 0
WINDOW: Dict[str, Any] = dict(model=3, thickness_qr=0.1, surface_energy_j_m2=0.1256)
WINDOW_FLAGS = ["--model", "3", "--thickness", "0.1", "--gamma", "0.1256"]
# system II on a 64² grid with γ_s = 0.3 J/m² (rescaled to the grid): GFMD holds tension
ADHESIVE_FLAGS = ["--grid", "64", "--gamma", "0.3", "--from", "0.002", "--to", "0.02", "--points", "3"]


@pytest.fixture(scope="module")
def window_cycle() -> asperity.CycleResult:
    return asperity.cycle(asperity.Scene.preset("system-2").replace(**WINDOW), 1e-4, 1e-2, points=2)


@pytest.fixture(scope="module")
def adhesive_gfmd() -> asperity.GfmdCycleResult:
    scene = asperity.Scene.preset("system-2").replace(surface_energy_j_m2=0.3)
    return asperity.gfmd_cycle(scene, 0.002, 0.02, points=3, grid=64)


def test_theory_cycle_equals_sweep_cycle_of_the_cli(cli, window_cycle):
    ref = cli("sweep", "--preset", "system-2", *WINDOW_FLAGS, "--from", "1e-4", "--to", "1e-2", "--points", "2", "--cycle", "--format", "json")
    assert compare(window_cycle.to_dict(), ref["cycle"], REL) == []
    assert set(window_cycle.to_dict()) == set(ref["cycle"])


def test_sweep_with_cycle_equals_the_cli(cli):
    scene = asperity.Scene.preset("system-2")
    res = asperity.sweep(scene, np.geomspace(1e-3, 1e-2, 3), cycle=True)
    ref = cli("sweep", "--preset", "system-2", "--from", "1e-3", "--to", "1e-2", "--points", "3", "--cycle", "--format", "json")
    assert compare(res.to_dict(), ref, REL) == []
    assert res.cycle is not None and compare(res.cycle.to_dict(), ref["cycle"], REL) == []
    assert asperity.sweep(scene, [1e-3]).cycle is None


def test_theory_cycle_follows_its_branches_into_tension(window_cycle):
    c = window_cycle
    assert list(c.branch) == ["loading", "loading", "unloading", "unloading"]
    assert list(c.on_unloading_branch) == [False, False, True, True]
    # the branches at p* = 1e-4 against the single-load solver (every root scanned)
    r = asperity.evaluate(asperity.Scene.preset("system-2").replace(**WINDOW, pressure=float(c.p[0])))
    assert r.a_r == pytest.approx(c.a_r[0], rel=BRANCH_REL)
    assert r.unloading_a_r == pytest.approx(c.a_r[2], rel=BRANCH_REL)
    # inside the window unloading keeps more contact than loading at the same load
    assert c.p[2] == c.p[0] and c.a_r[2] > c.a_r[0]
    # on into tension: p* = 0 held on the contact branch, no mean gap there, lost beyond
    assert c.p[3] == 0.0 and c.a_r[3] > 0.0 and math.isnan(c.mean_gap_rel[3])
    assert c.pull_off_pressure is not None and c.pull_off_bracket is not None and c.tension_bound is not None
    lost, held = c.pull_off_bracket
    assert lost < held == c.pull_off_pressure <= 0.0
    assert -c.tension_bound <= lost
    assert c.jump_in_pressure is not None and 1e-4 < c.jump_in_pressure < 1e-2
    assert "tension" in c.note


def test_theory_cycle_without_adhesion_retraces_and_holds_no_tension():
    c = asperity.cycle(asperity.Scene.preset("system-2").replace(surface_energy_j_m2=0.0), 1e-3, 1e-2, points=3)
    up, down = c.a_r[c.loading], c.a_r[~c.loading]
    assert len(up) == 3 and len(down) == 2
    np.testing.assert_array_equal(down, up[:2][::-1])
    assert c.pull_off_pressure == 0.0 and c.tension_bound is None
    assert "without adhesion" in c.note


def test_gfmd_cycle_equals_the_cli(cli, adhesive_gfmd):
    ref = cli("gfmd", "--preset", "system-2", *ADHESIVE_FLAGS, "--cycle", "--format", "json")
    assert compare(adhesive_gfmd.to_dict(), ref, REL) == []
    assert set(adhesive_gfmd.to_dict()) == set(ref)


def test_gfmd_cycle_with_adhesion_keeps_more_contact_and_pulls_off(adhesive_gfmd):
    g = adhesive_gfmd
    loading = g.loading
    assert loading.sum() == 3
    shared = 0
    for p, a in zip(g.p[~loading], g.a_r[~loading]):
        up = g.a_r[loading][g.p[loading] == p]
        if up.size:
            shared += 1
            assert a >= up[0], (p, a, up[0])
    assert shared == 2
    # this case shows the hysteresis: more contact on unloading at the smallest load
    assert g.a_r[~loading][1] > g.a_r[loading][0]
    assert g.pull_off_pressure is not None and g.pull_off_pressure < 0.0
    assert g.pull_off_bracket is not None
    lost, held = g.pull_off_bracket
    assert lost < held == g.pull_off_pressure
    assert held - lost <= 0.03 * abs(held) + 1e-15  # bisected to 3 % of the pull-off
    assert g.p.min() == g.pull_off_pressure and (g.a_r > 0.0).all()
    assert (g.branch[np.argmin(g.p):] == "unloading").all()
    # the theory on the same map alongside, over the same positive loads
    t = g.theory_cycle
    assert t is not None and t.pull_off_pressure is not None and t.pull_off_pressure <= 0.0
    np.testing.assert_array_equal(t.p[t.p > 0], g.p[g.p > 0])


def test_gfmd_cycle_without_adhesion_retraces_loading(cli):
    scene = asperity.Scene.preset("system-2").replace(surface_energy_j_m2=0.0)
    g = asperity.gfmd_cycle(scene, 0.005, 0.05, points=3, grid=64)
    ref = cli("gfmd", "--preset", "system-2", "--grid", "64", "--gamma", "0", "--from", "0.005", "--to", "0.05", "--points", "3", "--cycle", "--format", "json")
    assert compare(g.to_dict(), ref, REL) == []
    up = dict(zip(g.p[g.loading], g.a_r[g.loading]))
    down = list(zip(g.p[~g.loading], g.a_r[~g.loading]))
    assert len(up) == 3 and len(down) == 2, "no tensile rows without adhesion"
    for p, a in down:
        assert abs(a - up[p]) <= RETRACE, (p, a, up[p])
    assert g.pull_off_pressure == 0.0 and g.pull_off_bracket is None
    assert "no adhesion" in g.note


def test_gfmd_cycle_reports_progress_and_a_raising_callback_stops_it():
    seen: List[Dict[str, Any]] = []

    def progress(info: Dict[str, Any]) -> None:
        seen.append(dict(info))
        if len(seen) >= 3:
            raise KeyboardInterrupt

    scene = asperity.Scene.preset("system-2").replace(thickness_qr=0.5)
    with pytest.raises(KeyboardInterrupt):
        asperity.gfmd_cycle(scene, 0.005, 0.05, points=4, grid=512, progress=progress)
    assert seen[0]["stage"] == "relax" and seen[-1]["done"] >= seen[0]["done"]


def test_ctrl_c_stops_a_gfmd_cycle():
    scene = asperity.Scene.preset("system-2").replace(thickness_qr=0.5)
    fired: List[float] = []

    def ctrl_c() -> None:
        fired.append(time.perf_counter())
        _thread.interrupt_main()

    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.5, ctrl_c)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            asperity.gfmd_cycle(scene, 0.005, 0.05, points=4, grid=512)
        latency = time.perf_counter() - fired[0]
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)
    print(f"gfmd_cycle: Ctrl-C to KeyboardInterrupt in {latency:.3f} s")
    assert latency < STALL_S, latency


def test_gfmd_sweep_equals_the_cli_both_ways(cli):
    # rising: the loading sweep of `gfmd --from A --to B`; falling: its unloading walk
    scene = asperity.Scene.preset("system-2").replace(surface_energy_j_m2=0.3)
    for a, b in [(0.002, 0.02), (0.02, 0.002)]:
        g = asperity.gfmd_sweep(scene, a, b, points=3, grid=32)
        ref = cli("gfmd", "--preset", "system-2", "--grid", "32", "--gamma", "0.3", "--from", str(a), "--to", str(b), "--points", "3", "--format", "json")
        assert compare(g.to_dict(), ref, REL) == [], (a, b)
        assert set(g.to_dict()) == set(ref)
        assert isinstance(g, asperity.GfmdSweepResult) and len(g) == 3
        # more load, more contact along the walk; the rows in the order visited
        order = np.argsort(g.p)
        assert np.all(np.diff(g.a_r[order]) > 0), g.a_r
        assert (g.p[0] < g.p[-1]) == (a < b)


def test_gfmd_sweep_loading_agrees_with_the_cycle_loading_branch(adhesive_gfmd):
    # the same map and loads: the rising sweep is the cycle's way up, warm start for warm start
    scene = asperity.Scene.preset("system-2").replace(surface_energy_j_m2=0.3)
    g = asperity.gfmd_sweep(scene, 0.002, 0.02, points=3, grid=64)
    up = adhesive_gfmd.loading
    assert np.allclose(g.p, adhesive_gfmd.p[up], rtol=1e-15)
    assert np.allclose(g.a_r, adhesive_gfmd.a_r[up], rtol=0, atol=RETRACE)


def test_gfmd_walks_carry_the_map_they_ran_on(adhesive_gfmd):
    # the same seed and grid generate the same map as a single `gfmd` run; it stays out of the
    # JSON dict, as `gfmd`'s does
    scene = asperity.Scene.preset("system-2").replace(surface_energy_j_m2=0.3)
    one = asperity.gfmd(scene.replace(pressure=0.002), grid=64)
    sweep = asperity.gfmd_sweep(scene, 0.02, 0.002, points=2, grid=64)
    for walk in (adhesive_gfmd, sweep):
        assert isinstance(walk.heights, np.ndarray) and walk.heights.shape == (64, 64)
        assert np.array_equal(walk.heights, one.heights)
        assert "heights" not in walk.to_dict()


S = asperity.Scene.preset("system-2")

# call, the error's field, a piece of the message (the allowed range)
BAD = [
    (lambda pr: asperity.cycle(S, -1.0, 1e-2, progress=pr), "from_", "invalid from_ = -1: allowed 1e-12 <= p* <= 1e3"),
    (lambda pr: asperity.cycle(S, 1e-2, 1e-3, progress=pr), "to", "a p* above the first load"),
    (lambda pr: asperity.cycle(S, 1e-3, 1e-2, points=0, progress=pr), "points", "invalid points = 0"),
    (lambda pr: asperity.cycle(S, cast(Any, "a"), 1e-2, progress=pr), "from_", "allowed a finite number"),
    (lambda pr: asperity.sweep(S, [1e-3, 2e-3, 1e-2], cycle=True, progress=pr), "pressures", "log-spaced loads with cycle=True"),
    (lambda pr: asperity.sweep(S, over="thickness", values=[0.1, 1.0], cycle=True, progress=pr), "cycle", 'only with over="pressure"'),
    (lambda pr: asperity.gfmd_cycle(S, 0.02, 0.01, grid=32, progress=pr), "to", "a turning load p* >= the first load 0.02"),
    (lambda pr: asperity.gfmd_cycle(S, 0.0, 0.01, grid=32, progress=pr), "from_", "allowed 1e-12 <= p* <= 1e3"),
    (lambda pr: asperity.gfmd_cycle(S, 0.002, 0.01, grid=2, progress=pr), "grid", "4 <= grid <= 8192"),
    (lambda pr: asperity.gfmd_cycle(S, 0.002, 0.01, method="cg", progress=pr), "method", "auto, pk or fire"),
    (lambda pr: asperity.gfmd_cycle(S.replace(thickness_qr=0.5), 0.002, 0.01, method="pk", progress=pr), "method", "pk on a slab"),
    (lambda pr: asperity.gfmd(S.replace(thickness_qr=0.5), method="pk", progress=pr), "method", "pk on a slab"),
    (lambda pr: asperity.gfmd_cycle(S, 0.002, 0.01, tolerance=2.0, progress=pr), "tolerance", "allowed"),
    (lambda pr: asperity.gfmd_cycle(S, 0.002, 0.01, size=1e-6, progress=pr), "size", "None without heights"),
    (lambda pr: asperity.gfmd_sweep(S, 0.002, 0.01, points=0, grid=32, progress=pr), "points", "invalid points = 0"),
    (lambda pr: asperity.gfmd_sweep(S, 0.002, 1e9, grid=32, progress=pr), "to", "allowed 1e-12 <= p* <= 1e3"),
]


@pytest.mark.parametrize("call,field,allowed", BAD)
def test_bad_input_is_refused_before_any_work(call, field, allowed):
    seen: List[Dict[str, Any]] = []
    with pytest.raises(asperity.InputError) as e:
        call(seen.append)
    msg = str(e.value)
    assert isinstance(e.value, ValueError)
    assert e.value.field == field, (e.value.field, msg)
    assert allowed in msg and "\n" not in msg, msg
    assert e.value.value is not None and e.value.allowed is not None
    assert seen == [], "no work before the error"


def test_the_cycle_names_are_public():
    # Python names are a public interface: pinned here, extended only
    import inspect

    assert {"cycle", "gfmd_cycle", "gfmd_sweep", "CycleResult", "GfmdCycleResult", "GfmdSweepResult"} <= set(asperity.__all__)
    assert list(inspect.signature(asperity.gfmd_sweep).parameters) == list(inspect.signature(asperity.gfmd_cycle).parameters)
    assert list(inspect.signature(asperity.cycle).parameters) == ["scene", "from_", "to", "points", "progress"]
    assert list(inspect.signature(asperity.gfmd_cycle).parameters) == [
        "scene", "from_", "to", "points", "heights", "size", "grid", "seed", "tolerance",
        "max_iterations", "bins", "method", "rescale", "progress",
    ]
    assert "cycle" in inspect.signature(asperity.sweep).parameters
