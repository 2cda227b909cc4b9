"""The theory through Python against closed forms and its own invariants."""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest

import asperity
from conftest import REPO, SYSTEM_2, tolerance


@pytest.mark.parametrize("p", [1e-4, 0.01, 0.1, 0.5])
def test_model1_half_space_is_erf_sqrt2_p(p):
    """With W = f = 1 the stress variance at q_s is (E*ḡ/2)², so a_r = erf(√2 p*) [S-22]."""
    scene = asperity.Scene.preset("system-1").replace(model=1, surface_energy_j_m2=0.0, thickness_qr=math.inf, pressure=p)
    r = asperity.evaluate(scene)
    assert abs(r.a_r / math.erf(math.sqrt(2.0) * p) - 1.0) < tolerance("MODEL1_ERF_REL")


def test_report_fields_and_arrays():
    r = asperity.evaluate(asperity.Scene.preset("system-2"))
    assert isinstance(r.pr.sigma, np.ndarray) and isinstance(r.pr.density, np.ndarray)
    assert r.pr.sigma.shape == r.pr.density.shape == (201,)
    # ∫Pr dσ* = a_r (trapezoid on the report's own grid)
    area = float(np.sum(0.5 * (r.pr.density[1:] + r.pr.density[:-1]) * np.diff(r.pr.sigma)))
    assert abs(area / r.a_r - 1.0) < tolerance("ADHESIVE_PR_INTEGRAL_REL")
    lo, hi = r.gap_bracket
    assert lo <= r.mean_gap_rel <= hi
    assert r.elapsed_s >= r.elapsed_solve_s >= 0.0
    assert json.loads(json.dumps(r.to_dict())) == r.to_dict()
    assert r.branches and r.branches[0].a_r >= 0.0


def test_replace_returns_a_validated_copy():
    s = asperity.Scene.preset("system-2")
    t = s.replace(thickness_qr=0.3, pressure=1e-3)
    assert (t.thickness_qr, t.pressure) == (0.3, 1e-3)
    assert s.thickness_qr == math.inf and s.pressure == 0.005
    assert s.replace(thickness_qr="inf").thickness_qr == math.inf
    assert s.replace() == s
    c = s.replace(c1=0.5)
    assert c.model == "custom" and c.fields()["c1"] == 0.5


def test_keyword_scene_equals_the_preset():
    kw = asperity.Scene(**SYSTEM_2)
    a = asperity.evaluate(kw).to_dict()
    b = asperity.evaluate(asperity.Scene.preset("system-2")).to_dict()
    for k in ("a_r", "mean_contact_stress", "contact_stress_variance", "mean_gap_rel"):
        assert a[k] == b[k]


def test_sweep_arrays_and_branches():
    s = asperity.Scene.preset("system-1").replace(surface_energy_j_m2=0.0)
    sw = asperity.sweep(s, np.geomspace(1e-3, 0.1, 5))
    assert len(sw) == 5 and sw.a_r.shape == (5,)
    assert np.all(np.diff(sw.a_r) > 0) and np.all(np.diff(sw.mean_gap_rel) < 0)
    np.testing.assert_allclose(sw.values, np.geomspace(1e-3, 0.1, 5), rtol=1e-12)
    assert sw.reasons == [None] * 5
    # an uneven list: one sweep per value, each row the same as the single-value sweep's
    odd = asperity.sweep(s, [1e-3, 2e-3, 0.1])
    one = asperity.sweep(s, [2e-3])
    assert odd.a_r[1] == one.a_r[0]
    # the adhesive slab: both branches as columns
    a = asperity.sweep(asperity.Scene.preset("system-2").replace(thickness_qr=0.1), np.geomspace(1e-4, 1e-2, 5))
    assert a.a_r_unloading.shape == (5,) and a.branches.shape == (5,)


def test_knob_sweeps():
    s = asperity.Scene.preset("system-2").replace(surface_energy_j_m2=0.0)
    t = asperity.sweep_thickness(s, [0.1, 1.0, 10.0])
    assert np.all(np.diff(t.a_r) < 0)  # thinner slabs give way: more contact
    g = asperity.sweep_gamma(asperity.Scene.preset("system-2"), np.linspace(0.0, 0.1, 3))
    assert g.gamma.tolist() == [0.0, 0.05, 0.1]
    assert asperity.sweep(s, [0.1, 1.0], over="thickness").to_dict()["over"] == "thickness"


def test_gauge_eq18():
    g = asperity.gauge(asperity.Scene.preset("system-1"), ["c1", "c2"], "eq18", from_=1e-3, to=0.3, points=6)
    d = g.to_dict()
    assert d["reference"] == "eq18" and len(d["params"]) == 2
    assert d["chi2"] >= 0.0


def test_results_do_not_depend_on_threads():
    code = (
        "import asperity, json; s = asperity.Scene.preset('system-2').replace(thickness_qr=0.5);"
        "r = asperity.evaluate(s).to_dict(); print(json.dumps({k: r[k] for k in "
        "('a_r', 'mean_contact_stress', 'mean_gap_rel', 'pr')}))"
    )
    outs = []
    for n in ("1", "2"):
        env = dict(os.environ, RAYON_NUM_THREADS=n)
        outs.append(subprocess.run([sys.executable, "-c", code], env=env, check=True, capture_output=True, text=True).stdout)
    assert outs[0] == outs[1]


def test_gauge_on_columns_equals_gauge_on_the_same_csv(tmp_path):
    ps = np.geomspace(1e-3, 0.3, 6)
    a_r = np.array([asperity.evaluate(asperity.Scene.preset("system-1").replace(surface_energy_j_m2=0.0, pressure=float(p))).a_r for p in ps])
    cols = {"p": ps, "a_r": a_r * 1.05}
    path = tmp_path / "ref.csv"
    path.write_text("p,a_r\n" + "".join(f"{float(p)!r},{float(a)!r}\n" for p, a in zip(ps, cols["a_r"])))
    s = asperity.Scene.preset("system-1").replace(surface_energy_j_m2=0.0)
    a = asperity.gauge(s, "c1", cols).to_dict()
    b = asperity.gauge(s, ["c1"], path).to_dict()
    assert a["params"][0]["value"] == b["params"][0]["value"]
    assert b["reference"] == "ref.csv"


def test_sweep_takes_its_values_once():
    s = asperity.Scene.preset("system-1")
    with pytest.raises(TypeError):
        asperity.sweep(s)
    with pytest.raises(TypeError):
        asperity.sweep(s, [0.01], values=[0.02])
    assert asperity.sweep(s, values=[0.01]).p.tolist() == [0.01]


def test_model5_is_model3_without_adhesion_and_follows_gamma_glo():
    """Model 5 (docs/physics.md §3.6): model 3's coefficients at γ_s = 0 (so the same a_r), and
    with adhesion W(0) rising with γ̃_glo·√μ_T in model 4's form (at the scene's bandwidth), through the scene."""
    dry = asperity.Scene.preset("system-1").replace(surface_energy_j_m2=0.0, thickness_qr=math.inf, pressure=0.01)
    assert asperity.evaluate(dry.replace(model=5)).a_r == asperity.evaluate(dry.replace(model=3)).a_r

    def w0(scene):
        f = scene.fields()
        return 1.0 - f["c1"] - f["c2"]

    half = asperity.Scene.preset("system-2").replace(model=5, thickness_qr=math.inf)
    assert half.model == "5"
    # the full bandwidth λ_r/λ_s = 128 (3 octaves above the set's 16): floor 0.125 + 3 x 0.0411
    assert abs(w0(half) - (0.125 + 3 * 0.0411)) < 1e-3  # γ̃_glo = 0.10, μ_T = 1.00: the floor
    # thinner slabs store less elastic energy in full contact: more γ̃_glo, more W(0)
    assert 0.25 < w0(half.replace(thickness_qr=0.3)) < w0(half.replace(thickness_qr=0.15)) < 1.0


def test_trust_says_no_error_known_far_from_the_reference_set():
    """The trust read-out quotes an error only where GFMD was measured near the scene's load."""
    s = asperity.Scene.preset("system-2").replace(model=5)
    near = asperity.evaluate(s.replace(pressure=1e-3)).trust
    assert near["known"] is True
    assert near["a_r_band_ratio"] >= math.exp(near["a_r_log_error"])
    assert near["measured_model"] == 5
    far = asperity.evaluate(s.replace(pressure=1e-8)).trust
    assert far["known"] is False
    assert far["a_r_band_ratio"] is None and far["a_r_log_error"] is None
    assert "no error known" in far["summary"]


def _jump_scene() -> "asperity.Scene":
    """The tour's "Jump into contact" scene (tours/wang-muser.toml): system II, model 3,
    γ_s = 0.1256 J/m², p* = 1e-4; its hysteresis window in t·q_r lies at 0.099–0.101."""
    return asperity.Scene.preset("system-2").replace(model=3, surface_energy_j_m2=0.1256, pressure=1e-4)


@pytest.mark.parametrize("points", [8, 16])
def test_sweep_thickness_finds_the_window_between_its_values(points):
    """The window is far narrower than the sweep's step: the library's probe finds it in the
    jump of a_r between two rows, as the explorer's chart and `asperity sweep --over thickness`
    do (the edges bracket two stable branches: src/report/sweep_tests.rs)."""
    t = np.geomspace(0.05, 1.0, points)
    sw = asperity.sweep_thickness(_jump_scene(), t)
    assert len(sw) == points
    edges = {e["kind"]: e["value"] for e in sw.to_dict()["window_edges"]}
    assert set(edges) == {"jump_in", "pull_off"}, sw.to_dict()["window_edges"]
    assert 0.09 < edges["jump_in"] < edges["pull_off"] < 0.11, edges


def test_one_name_per_quantity():
    """Each quantity has one preferred name; an alias (asperity::report::names) carries the
    same number, and `pressure` is not a sweep's keyword (the error names `pressures`)."""
    r = asperity.evaluate(_jump_scene().replace(thickness_qr=0.1))
    assert r.a_r_unloading is not None and r.a_r_unloading == r.unloading_a_r
    assert r.variance == r.contact_stress_variance
    for b in r.to_dict()["branches"]:
        assert b["mean_gap_reversible_rel"] == b["mean_gap_upper_rel"]
    sw = asperity.sweep(asperity.Scene.preset("system-1"), [0.01, 0.1])
    assert "a_r_unloading" in sw.to_dict()["rows"][0] and "unloading_a_r" not in sw.to_dict()["rows"][0]
    with pytest.raises(asperity.InputError, match="pressures") as e:
        asperity.sweep(asperity.Scene.preset("system-1"), pressure=[0.01, 0.1])
    assert e.value.field == "pressure"


def test_attributes_are_built_once_and_read_only():
    r = asperity.evaluate(asperity.Scene.preset("system-1"))
    assert r.pr.sigma is r.pr.sigma
    assert r.pr is r.pr
    with pytest.raises(ValueError):
        r.pr.sigma[0] = 1.0
    sw = asperity.sweep(asperity.Scene.preset("system-1"), np.geomspace(1e-3, 1e-2, 3))
    assert sw.a_r is sw.a_r and sw.values is sw.values
    assert np.array(sw.a_r).flags.writeable


def test_results_name_their_fields_types():
    """A type checker reads the fields' types from the result classes (`r.a_r` is a float;
    `Report`'s, built in Rust, from the stub: test_stubs.py)."""
    import typing

    assert typing.get_type_hints(asperity.GfmdResult)["iterations"] is int
    assert typing.get_type_hints(asperity.SweepResult)["a_r"] is np.ndarray
