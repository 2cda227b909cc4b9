#!/usr/bin/env python3
"""[S] Fig. 7 from Python: the relative contact area of system II at p* = 0.005 over the slab
thickness t·q_r, from Persson theory with models 3 and 4 (and model 4 without adhesion, the
reference curve), with GFMD points on small maps beside it.

    python examples/python/fig7.py [--quick] [--out fig7.png]

The theory is `asperity.sweep_thickness` (each thickness its own scene, exactly what
`asperity.evaluate` gives; a second, unloading branch dashed where it exists), the half-space
(t = ∞) a marker at the right; GFMD is `asperity.gfmd` on the preset's reduced grid (or the
small `--grid`) with γ_s and ρ rescaled to keep γ̃_glo and the Tabor parameter.
`--quick` (CI) uses few thicknesses and one 64² GFMD map.
"""

from __future__ import annotations

import argparse
import math
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import asperity  # noqa: E402


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="small settings (CI)")
    ap.add_argument("--out", default="fig7.png", help="figure file (png, svg, pdf)")
    ap.add_argument("--grid", type=int, default=None, help="GFMD grid side N (default 64 quick, 256 full)")
    args = ap.parse_args()
    t0 = time.perf_counter()

    base = asperity.Scene.preset("system-2").replace(pressure=0.005)
    ts = np.geomspace(0.05, 10.0, 5) if args.quick else np.geomspace(0.01, 100.0, 41)
    gfmd_ts = [1.0] if args.quick else [0.1, 0.3, 1.0, 3.0, math.inf]
    grid = args.grid or (64 if args.quick else 256)

    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    curves = [
        (base.replace(model=3), "model 3", "tab:blue", "-"),
        (base.replace(model=4), "model 4", "tab:red", "-"),
        (base.replace(model=4, surface_energy_j_m2=0.0), "model 4, no adhesion", "0.4", ":"),
    ]
    right = ts[-1] * 3.0  # where the half-space is drawn
    for scene, label, color, style in curves:
        sw = asperity.sweep_thickness(scene, ts)
        ax.plot(sw.values, sw.a_r, style, color=color, label=label)
        if np.any(np.isfinite(sw.a_r_unloading)):
            ax.plot(sw.values, sw.a_r_unloading, "--", color=color, lw=1, label=f"{label}, unloading branch")
        half = asperity.evaluate(scene.replace(thickness_qr=math.inf))
        ax.plot([right], [half.a_r], "o", mfc="none", color=color)
        for t, why in zip(sw.values, sw.reasons):
            if why:
                print(f"{label}: t*q_r = {t:.3g}: {why}")

    g_t, g_a = [], []
    for t in gfmd_ts:
        r = asperity.gfmd(base.replace(model=4, thickness_qr=t), grid=grid)
        g_t.append(right if math.isinf(t) else t)
        g_a.append(r.a_r)
        on_map = r.theory.a_r if r.theory is not None else math.nan
        print(f"GFMD {grid}x{grid}: t*q_r = {t}: a_r = {r.a_r:.5f} (theory on the map {on_map:.5f}), {r.elapsed_s:.2f} s")
    ax.plot(g_t, g_a, "s", color="k", label=f"GFMD ({grid}²)")

    ax.set_xscale("log")
    ax.set_xlabel("t·q_r  (open symbols at the right: semi-infinite)")
    ax.set_ylabel("relative contact area a_r")
    ax.set_title("System II at p* = 0.005 ([S] Fig. 7)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(args.out, dpi=120)
    print(f"wrote {args.out} in {time.perf_counter() - t0:.1f} s")


if __name__ == "__main__":
    main()
