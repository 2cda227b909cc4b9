#!/usr/bin/env python3
"""A measured surface from Python: read a height map, its PSD with the self-affine fit, Persson
theory on that PSD over the load, and GFMD on the map itself beside it.

    python examples/python/measured_surface.py [--surface FILE --size L_m] [--quick] [--out measured.png]

Without --surface a periodic self-affine map (H = 0.8, λ_r = L/2) is synthesised with numpy,
written to measured.npy and read back, so the script runs anywhere. Any file
`asperity.read_surface` reads works (.txt .asc .dat .xyz .npy .gsf); a SurfaceTopography
Topography goes wherever the map does. `--quick` (CI) uses a 64² map and three loads.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import asperity  # noqa: E402


def synthetic_map(n: int, size_m: float, seed: int = 7) -> np.ndarray:
    """A periodic self-affine map: C(q) flat below q_r = 4π/L, ∝ q^(−2−2H) up to q_s = πn/(2L),
    random phases, scaled to an rms gradient of 1."""
    rng = np.random.default_rng(seed)
    q1 = 2 * np.pi * np.fft.fftfreq(n, d=size_m / n)
    qx, qy = np.meshgrid(q1, q1)
    q = np.hypot(qx, qy)
    q_r, q_s, hurst = 2 * 2 * np.pi / size_m, q1.max() / 2, 0.8
    c = np.where(q < q_r, q_r, q) ** (-2 - 2 * hurst)
    c[(q == 0) | (q > q_s)] = 0.0
    h = np.fft.ifft2(np.sqrt(c) * np.exp(2j * np.pi * rng.random((n, n)))).real
    gx = np.fft.ifft2(1j * qx * np.fft.fft2(h)).real
    gy = np.fft.ifft2(1j * qy * np.fft.fft2(h)).real
    return h / np.sqrt(np.mean(gx**2 + gy**2))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--surface", help="height map file (default: a synthesised one)")
    ap.add_argument("--size", type=float, default=None, help="x side of the map in m")
    ap.add_argument("--periodic", action="store_true", help="the map is periodic (no plane fit, no window)")
    ap.add_argument("--quick", action="store_true", help="small settings (CI)")
    ap.add_argument("--out", default="measured.png")
    args = ap.parse_args()
    t0 = time.perf_counter()

    if args.surface:
        surf = asperity.read_surface(args.surface, size=args.size)
        periodic = args.periodic
    else:
        n, size = (64, 1e-4) if args.quick else (256, 1e-4)
        path = Path(args.out).with_suffix(".npy")
        np.save(path, synthetic_map(n, size))
        surf = asperity.read_surface(path, size=size)
        periodic = True
    print(surf)

    spec = asperity.psd(surf, periodic=periodic)
    print(
        f"h_rms = {spec.rms_height_m:.4g} m, g = {spec.rms_gradient:.4g}, "
        f"H = {spec.hurst}, lambda_r = {spec.rolloff_wavelength_m}, lambda_s = {spec.short_wavelength_m}"
    )

    # the theory on the map's PSD (model 3, adhesionless, semi-infinite) over the load
    scene = asperity.Scene.preset("system-1").replace(surface_energy_j_m2=0.0, model=3)
    scene = scene.with_surface(surf, periodic=periodic)
    ps = np.geomspace(1e-3, 0.3, 8 if args.quick else 30)
    sw = asperity.sweep(scene, ps)

    # GFMD on the map itself at a few loads (p* by the map's own rms gradient)
    g_p = [0.01, 0.05, 0.2] if args.quick else [0.003, 0.01, 0.03, 0.1, 0.3]
    g_a = [asperity.gfmd(scene.replace(pressure=p)).a_r for p in g_p]

    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4.2))
    a.loglog(spec.q, spec.psd, ".", label="radial average")
    a.set_xlabel("q (1/m)")
    a.set_ylabel("C(q) (m⁴)")
    a.set_title("PSD of the map")
    b.loglog(sw.values, sw.a_r, "-", label="Persson theory (model 3) on the PSD")
    b.loglog(g_p, g_a, "s", color="k", label="GFMD on the map")
    b.set_xlabel("p* = p/(E* g)")
    b.set_ylabel("a_r")
    b.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    print(f"wrote {args.out} in {time.perf_counter() - t0:.1f} s")


if __name__ == "__main__":
    main()
