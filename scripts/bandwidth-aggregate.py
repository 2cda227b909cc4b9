#!/usr/bin/env python3
"""Aggregates the GFMD loading sweeps of scripts/bandwidth-set.sh into the bandwidth set.

bandwidth-aggregate.py SET_CSV RUNS_DIR [RUNS_DIR ...]

One row per (grid, system, thickness_qr, gamma_factor, p) held by every seed of that grid:
gamma_glo of the reduced system, the mean and standard error s/sqrt(K) over the K seeds of
a_r, mean_gap_rel, mean_contact_stress and contact_stress_variance, the theory (the preset's
model 4) on the same maps (mean), and the wall seconds of the case's runs (wall_s).
"""
import sys

from gfmd_runs import OBS, fmt, mean_se, read_cases, theory_at, write_csv


def main(set_csv, *runs_dirs):
    rows = []
    for runs_dir in runs_dirs:
        for (sys_, t, g), runs in read_cases(runs_dir).items():
            grid = runs[0][1]["grid"]
            glo = ((runs[0][1].get("reduction") or {}).get("reduced") or {}).get("gamma_glo")
            loads = [r["p"] for r in runs[0][1]["rows"]]
            for p in loads:
                per = [next((r for r in run["rows"] if abs(r["p"] / p - 1) < 1e-9), None)
                       for _, run in runs]
                if any(r is None or not r.get("converged", True) for r in per):
                    continue
                row = {"system": sys_, "grid": grid, "thickness_qr": t, "gamma_factor": g,
                       "gamma_glo": fmt(glo), "branch": "loading", "p": f"{p:.10e}",
                       "seeds": len(runs)}
                for o in OBS:
                    mu, se = mean_se([r[o] for r in per])
                    row[o], row[o + "_err"] = fmt(mu), fmt(se)
                ths = [theory_at(run, p) for _, run in runs]
                row["theory_a_r"] = fmt(mean_se([x[0] for x in ths])[0])
                row["theory_mean_gap_rel"] = fmt(mean_se([x[1] for x in ths])[0])
                row["wall_s"] = f"{sum(run['elapsed_s'] for _, run in runs):.1f}"
                rows.append(row)
    write_csv(set_csv, rows)
    print(f"{len(rows)} rows -> {set_csv}", file=sys.stderr)


if __name__ == "__main__":
    main(*sys.argv[1:])
