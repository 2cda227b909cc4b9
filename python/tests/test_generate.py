"""Surfaces made in Python (`generate_surface`, the CLI's `surface generate` generator),
written in every format and read back, SurfaceTopography-like objects, units on `psd` and
`read_surface` with their warning, `replace()` on a measured scene, GFMD's resolution warning,
and `Scene.preset` of an explorer export (its branch and its measured map)."""

from __future__ import annotations

import re
import warnings
from pathlib import Path
from typing import Any, Callable, Dict

import numpy as np
import pytest

import asperity

REPO = Path(__file__).resolve().parents[2]


class Topography:
    """A stand-in for SurfaceTopography's Topography: heights() indexed [x, y],
    physical_sizes, is_periodic (SurfaceTopography itself need not be installed)."""

    def __init__(self, map_yx: np.ndarray, size: float, periodic: bool) -> None:
        self._h = map_yx.T.copy()
        ny, nx = map_yx.shape
        self.physical_sizes = (size, size * ny / nx)
        self.is_periodic = periodic

    def heights(self) -> np.ndarray:
        return self._h


def test_generated_map_has_what_was_asked_and_equals_the_cli_map(tmp_path: Path, cli: Callable[..., Dict[str, Any]]) -> None:
    s = asperity.generate_surface(grid=32, system_size_m=1e-4, hurst=0.7, rms_gradient=0.5, seed=4)
    assert s.map.shape == (32, 32) and s.is_periodic and s.size_m == pytest.approx(1e-4)
    assert s.rms_gradient == pytest.approx(0.5, rel=1e-9)
    # the same generator as the CLI's: the same seed gives the same map, value for value
    out = tmp_path / "cli.npy"
    cli("surface", "generate", "--output", str(out), "--grid", "32", "--size", "1e-4", "--hurst", "0.7",
        "--rms-gradient", "0.5", "--seed", "4", "--format", "json")
    np.testing.assert_allclose(np.load(out), s.map, rtol=0, atol=1e-15 * float(np.abs(s.map).max()))
    # h_rms instead of the gradient, and a map that is not periodic
    h = asperity.generate_surface(grid=32, rms_height_m=2e-7, periodic=False, seed=4)
    assert not h.is_periodic and h.map.shape == (32, 32)
    assert abs(float(h.map.mean())) < 1e-12 * 2e-7 * 1024


@pytest.mark.parametrize("ext", ["txt", "asc", "dat", "xyz", "npy", "gsf"])
def test_every_format_is_written_and_read_back(tmp_path: Path, ext: str) -> None:
    s = asperity.generate_surface(grid=16, system_size_m=2e-5, rms_height_m=1e-7, seed=2)
    p = tmp_path / f"map.{ext}"
    if ext == "npy":
        with pytest.raises(asperity.InputError, match="size"):
            s.write(p)
            asperity.read_surface(p)
    s.write(p)
    # .npy states no side: it is given
    back = asperity.read_surface(p, size=2e-5 if ext == "npy" else None)
    rel = 1e-6 if ext == "gsf" else 1e-12  # gsf stores f32
    np.testing.assert_allclose(back.map, s.map, rtol=0, atol=rel * float(np.abs(s.map).max()))
    assert back.size_m == pytest.approx(2e-5, rel=1e-6)
    # output= writes at once
    q = tmp_path / f"again.{ext}"
    asperity.generate_surface(grid=16, system_size_m=2e-5, rms_height_m=1e-7, seed=2, output=q)
    assert q.stat().st_size > 0


def test_generated_spectrum_fits_its_hurst_exponent() -> None:
    s = asperity.generate_surface(grid=256, system_size_m=1e-4, hurst=0.8, rolloff_wavelength_m=5e-5, short_wavelength_m=2e-6, seed=1)
    fit = asperity.psd(s)  # periodic from the map: no window
    assert fit.to_dict()["hurst"] == pytest.approx(0.8, abs=0.05)


def test_topography_like_objects_go_where_maps_go() -> None:
    s = asperity.generate_surface(grid=32, system_size_m=1e-5, seed=3)
    t = Topography(s.map, s.size_m, periodic=True)
    # its is_periodic is honoured: the same as the map with periodic=True, not the windowed PSD
    assert asperity.psd(t).to_dict()["table"] == asperity.psd(s.map, s.size_m, periodic=True).to_dict()["table"]
    assert asperity.psd(t).to_dict()["table"] != asperity.psd(s.map, s.size_m).to_dict()["table"]
    scene = asperity.Scene.preset("system-1").replace(pressure=0.05)
    a = asperity.evaluate(scene.with_surface(t)).a_r
    b = asperity.evaluate(scene.with_surface(s.map, s.size_m, periodic=True)).a_r
    assert a == b
    g = asperity.gfmd(scene, t, max_iterations=20000)
    np.testing.assert_array_equal(g.heights, s.map)


def test_units_on_psd_and_read_surface(tmp_path: Path) -> None:
    s = asperity.generate_surface(grid=32, system_size_m=1e-5, rms_height_m=5e-8, seed=5)
    ref = asperity.psd(s.map, s.size_m).to_dict()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        nm = asperity.psd(s.map * 1e9, s.size_m * 1e6, height_unit="nm", size_unit="um").to_dict()
    assert nm["rms_height_m"] == pytest.approx(ref["rms_height_m"], rel=1e-12)
    assert nm["rms_gradient"] == pytest.approx(ref["rms_gradient"], rel=1e-12)
    # the mistake the units catch: nanometre heights passed as metres
    with pytest.warns(asperity.UnitWarning, match=r"h_rms = .* m .*height_unit") as rec:
        asperity.psd(s.map * 1e9, s.size_m)
    assert len(rec) == 1 and "\n" not in str(rec[0].message)
    # a side in micrometres passed as metres: the gradient is 1e-6 of the truth
    with pytest.warns(asperity.UnitWarning, match="rms gradient"):
        asperity.psd(s.map, s.size_m * 1e6)
    # read_surface: a text matrix without a unit, read in nm with a side in um
    p = tmp_path / "nm.txt"
    np.savetxt(p, s.map * 1e9)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        back = asperity.read_surface(p, size=10.0, size_unit="um", height_unit="nm")
    np.testing.assert_allclose(back.map, s.map, rtol=1e-12, atol=1e-20)
    assert back.size_m == pytest.approx(1e-5)
    with pytest.warns(asperity.UnitWarning):
        asperity.read_surface(p, size=1e-5)


def test_replace_refuses_to_drop_a_measured_psd() -> None:
    s = asperity.generate_surface(grid=32, system_size_m=1e-5, seed=3)
    scene = asperity.Scene.preset("system-1").with_surface(s, periodic=True)
    with pytest.raises(asperity.InputError, match="hurst = 0.7: allowed .*measured PSD.*keep") as info:
        scene.replace(hurst=0.7)
    assert info.value.field == "hurst"
    # what does not touch the surface keeps the measured PSD
    kept = scene.replace(pressure=0.02)
    assert kept.summary()["spectrum"] == "tabulated"


def test_adhesive_gfmd_on_a_coarse_grid_warns_about_resolution() -> None:
    # the sample preset's 64² grid: Δa = 1.6 µm against ρ = 2 nm, (γ/E*)Δa/ρ² ≈ 700 ≫ 0.25
    scene = asperity.Scene.preset(REPO / "data" / "samples" / "sample.toml").replace(pressure=0.05)
    with pytest.warns(asperity.ResolutionWarning, match=r"\(gamma/E\*\)\*da/rho\^2 = [0-9.]+ > 0.25") as rec:
        r = asperity.gfmd(scene)
    assert r.to_dict()["adhesion_resolution"] > 0.25
    assert len(rec) == 1 and "\n" not in str(rec[0].message)
    # the same number GFMD reports, from the scene's own numbers: (γ_s'/E*)·Δa/ρ'² on the grid it ran
    d = r.to_dict()
    want = d["gamma"] / scene.contact_modulus_pa * d["spacing_m"] / d["range_m"] ** 2
    assert d["adhesion_resolution"] == pytest.approx(want, rel=1e-9)
    # adhesionless: no warning
    with warnings.catch_warnings():
        warnings.simplefilter("error", asperity.ResolutionWarning)
        asperity.gfmd(scene.replace(surface_energy_j_m2=0.0))


def _export(tmp_path: Path, extra: str) -> Path:
    text = (REPO / "presets" / "system-2.toml").read_text()
    text = re.sub(r"(?m)^pressure = .*$", "pressure = 1e-4", text)
    text = re.sub(r"(?m)^thickness_qr = .*$", "thickness_qr = 0.1" + extra, text)
    text = re.sub(r"(?m)^surface_energy_j_m2 = .*$", "surface_energy_j_m2 = 0.1256", text)
    text = re.sub(r"(?m)^variant = .*$", "variant = 3", text)
    p = tmp_path / "export.toml"
    p.write_text(text)
    return p


def test_preset_of_an_export_reads_its_branch(tmp_path: Path, cli: Callable[..., Dict[str, Any]]) -> None:
    loading = asperity.evaluate(asperity.Scene.preset(_export(tmp_path, "")))
    p = _export(tmp_path, '\nbranch = "unloading"')
    r = asperity.evaluate(asperity.Scene.preset(p))
    d = r.to_dict()
    assert d["branch"] == "unloading" and loading.to_dict()["branch"] == "loading"
    # the unloading root the loading evaluation lists, and what `run --preset` reports
    listed = [b for b in loading.to_dict()["branches"] if b["branch"] == "unloading"]
    assert listed and d["a_r"] == pytest.approx(listed[0]["a_r"], rel=1e-6)
    assert d["a_r"] > 5 * loading.a_r
    assert d["a_r"] == pytest.approx(cli("run", "--preset", str(p), "--format", "json")["a_r"], rel=1e-9)


def test_preset_of_an_export_reads_its_measured_map(tmp_path: Path, cli: Callable[..., Dict[str, Any]]) -> None:
    text = (REPO / "data" / "samples" / "sample.toml").read_text()
    sample = REPO / "data" / "samples" / "map.txt"
    text += f'\n[measured]\nmap = "{sample}"\nsize_m = 5e-5\nperiodic = true\n'
    p = tmp_path / "measured.toml"
    p.write_text(text)
    scene = asperity.Scene.preset(p)
    assert scene.summary()["spectrum"] == "tabulated"
    want = asperity.Scene.preset(REPO / "data" / "samples" / "sample.toml").with_surface(
        asperity.read_surface(sample, size=5e-5), periodic=True
    )
    assert asperity.evaluate(scene).a_r == asperity.evaluate(want).a_r
    assert asperity.evaluate(scene).a_r == pytest.approx(cli("run", "--preset", str(p), "--format", "json")["a_r"], rel=1e-9)
