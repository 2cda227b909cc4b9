"""Height maps: numpy arrays, files and anything with `.heights()` and `.physical_sizes` (a
SurfaceTopography Topography) give the same results."""

from __future__ import annotations

from pathlib import Path

import numpy as np

import asperity


class StandIn:
    """What SurfaceTopography's Topography offers: heights() indexed [x, y], physical_sizes."""

    def __init__(self, map_yx: np.ndarray, size: float) -> None:
        self._h = map_yx.T.copy()
        ny, nx = map_yx.shape
        self.physical_sizes = (size, size * ny / nx)

    def heights(self) -> np.ndarray:
        return self._h


def _map() -> tuple:
    g = asperity.gfmd(asperity.Scene.preset("system-1").replace(pressure=0.05), grid=32)
    return g.heights, g.system_size_m


def test_topography_like_objects_are_accepted():
    h, size = _map()
    obj = StandIn(h, size)
    assert asperity.psd(obj).to_dict()["table"] == asperity.psd(h, size).to_dict()["table"]
    s = asperity.Scene.preset("system-1").replace(pressure=0.05)
    a = asperity.gfmd(s, obj).to_dict()
    b = asperity.gfmd(s, h, size).to_dict()
    assert a["a_r"] == b["a_r"] and a["mean_gap_rel"] == b["mean_gap_rel"]
    assert asperity.evaluate(s.with_surface(obj, periodic=True)).a_r == asperity.evaluate(s.with_surface(h, size, periodic=True)).a_r


def test_read_surface_round_trip(tmp_path: Path):
    h, size = _map()
    p = tmp_path / "m.npy"
    np.save(p, h)
    s = asperity.read_surface(p, size=size)
    np.testing.assert_array_equal(s.map, h)
    assert s.physical_sizes == (size, size)
    assert s.heights().shape == (32, 32)
    # a Surface goes wherever heights go
    assert asperity.psd(s).rms_gradient == asperity.psd(h, size).rms_gradient


def test_measured_scene_runs_theory_and_gfmd_on_its_map():
    h, size = _map()
    s = asperity.Scene.preset("system-1").replace(pressure=0.05).with_surface(h, size, periodic=True)
    assert s.summary()["spectrum"] == "tabulated"
    r = asperity.evaluate(s)
    g = asperity.gfmd(s)
    assert 0.0 < r.a_r < 1.0 and 0.0 < g.a_r < 1.0
    np.testing.assert_array_equal(g.heights, h)
    p = asperity.psd(h, size, periodic=True)
    assert p.q.shape == p.psd.shape and np.all(p.psd > 0)
