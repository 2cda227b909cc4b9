#!/usr/bin/env python3
"""tamaas's Polonsky–Keer solver on a height map written by asperity, for BENCHMARKS.md.

Usage (tamaas from PyPI, `pip install tamaas numpy`; not a dependency of asperity):

    asperity gfmd --preset system-1 --gamma 0 --grid 1024 --pressure 0.01 \
        --save-surface s1024.txt --format json > asperity.json
    OMP_NUM_THREADS=1 python3 scripts/pk-vs-tamaas.py s1024.txt 0.01 1e-8 > tamaas.json

The map is read as written (heights in m, the spacing from its header line), the body is
made with E* = 1 (E = 1, ν = 0) so that the mean pressure is p* times the map's rms gradient,
and tamaas's `PolonskyKeerRey` solves it to its own error `tolerance`. Printed as one JSON
object: the solve's wall and CPU seconds, its iterations as tamaas reports them on stdout
(not parsed here), the number of nodes in contact and a_r, to set beside asperity's
`contact_nodes`, `a_r` and `solve_elapsed_s` on the same map.
"""
import json
import sys
import time

import numpy as np
import tamaas as tm


def main() -> None:
    path, p_star, tol = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
    with open(path) as f:
        head = f.readline()
    spacing = float(head.split("spacing")[1].split()[0])
    h = np.ascontiguousarray(np.loadtxt(path, comments="#"))
    ny, nx = h.shape
    # rms gradient from the spectrum (the periodic map's own definition)
    hk = np.fft.fft2(h)
    qx = 2 * np.pi * np.fft.fftfreq(nx, d=spacing)
    qy = 2 * np.pi * np.fft.fftfreq(ny, d=spacing)
    qq = qy[:, None] ** 2 + qx[None, :] ** 2
    g = float(np.sqrt(np.sum(np.abs(hk) ** 2 * qq) / (nx * ny) ** 2))
    model = tm.ModelFactory.createModel(tm.model_type.basic_2d, [ny * spacing, nx * spacing], [ny, nx])
    model.E, model.nu = 1.0, 0.0
    solver = tm.PolonskyKeerRey(model, h, tol)
    solver.max_iter = 1_000_000
    t0, c0 = time.perf_counter(), time.process_time()
    solver.solve(p_star * g)
    t1, c1 = time.perf_counter(), time.process_time()
    contact = np.asarray(model.traction).reshape(ny, nx) > 0
    print(json.dumps({
        "grid": [ny, nx],
        "rms_gradient": g,
        "tolerance": tol,
        "solve_wall_s": t1 - t0,
        "solve_cpu_s": c1 - c0,
        "contact_nodes": int(contact.sum()),
        "a_r": float(contact.mean()),
        "tamaas": tm.__version__,
    }))


if __name__ == "__main__":
    main()
