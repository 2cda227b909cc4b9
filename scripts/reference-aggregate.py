#!/usr/bin/env python3
"""Aggregates the GFMD cycle runs of scripts/reference-set.sh into the reference set.

reference-aggregate.py RUNS_DIR SET_CSV PULL_OFF_CSV [PER_SEED_CSV]

SET_CSV: one row per (system, thickness_qr, gamma_factor, branch, p) held by every seed:
the mean and standard error s/sqrt(K) over the K seeds of a_r, mean_gap_rel,
mean_contact_stress and contact_stress_variance, and the theory on the same maps (mean).
PULL_OFF_CSV: per (system, thickness_qr, gamma_factor) the pull-off p* and jump-in p*
(mean, standard error, seeds) and the CPU seconds of the runs.
PER_SEED_CSV: every row of every run (seed, step, branch, p and the observables), and each
run's pull-off as a row with branch `pull_off`.
"""
import sys

from gfmd_runs import OBS, fmt, mean_se, read_cases, theory_at, write_csv


def main(runs_dir, set_csv, pull_csv, seed_csv=None):
    cases = read_cases(runs_dir)
    set_rows, pull_rows, seed_rows = [], [], []
    for (sys_, t, g), runs in cases.items():
        k = len(runs)
        for seed, run in runs:
            for i, r in enumerate(run["rows"]):
                row = {"system": sys_, "thickness_qr": t, "gamma_factor": g, "seed": seed,
                       "step": i, "branch": r.get("branch", "loading"), "p": f"{r['p']:.10e}"}
                row.update({o: fmt(r[o]) for o in OBS})
                seed_rows.append(row)
            if run.get("pull_off_pressure") is not None:
                row = {"system": sys_, "thickness_qr": t, "gamma_factor": g, "seed": seed,
                       "step": len(run["rows"]), "branch": "pull_off",
                       "p": f"{run['pull_off_pressure']:.10e}"}
                row.update({o: "" for o in OBS})
                seed_rows.append(row)
        keyed = []
        for _, run in runs:
            d = {}
            for i, r in enumerate(run["rows"]):
                d.setdefault((r.get("branch", "loading"), r["p"]), r)
            keyed.append(d)
        common = [key for key in keyed[0] if all(key in d for d in keyed[1:])]
        order = {key: i for i, key in enumerate(keyed[0])}
        for branch, p in sorted(common, key=lambda key: order[key]):
            row = {"system": sys_, "thickness_qr": t, "gamma_factor": g, "branch": branch,
                   "p": f"{p:.10e}", "seeds": k}
            for o in OBS:
                mu, se = mean_se([d[(branch, p)][o] for d in keyed])
                row[o], row[o + "_err"] = fmt(mu), fmt(se)
            ths = [theory_at(run, p, branch) for _, run in runs] if p > 0 else []
            row["theory_a_r"] = fmt(mean_se([x[0] for x in ths])[0]) if ths else ""
            row["theory_mean_gap_rel"] = fmt(mean_se([x[1] for x in ths])[0]) if ths else ""
            set_rows.append(row)
        po = mean_se([run.get("pull_off_pressure") for _, run in runs])
        ji = mean_se([run.get("jump_in_pressure") for _, run in runs])
        red = runs[0][1].get("reduction") or {}
        pull_rows.append({
            "system": sys_, "thickness_qr": t, "gamma_factor": g, "seeds": k,
            "grid": runs[0][1]["grid"],
            "gamma_glo": fmt((red.get("reduced") or {}).get("gamma_glo")),
            "pull_off_pressure": fmt(po[0]), "pull_off_pressure_err": fmt(po[1]),
            "jump_in_pressure": fmt(ji[0]), "jump_in_pressure_err": fmt(ji[1]),
            "jump_in_seeds": sum(1 for _, r in runs if r.get("jump_in_pressure") is not None),
            "wall_s": f"{sum(r['elapsed_s'] for _, r in runs):.1f}",
        })
    for path, rows in ((set_csv, set_rows), (pull_csv, pull_rows), (seed_csv, seed_rows)):
        if not rows or not path:
            continue
        write_csv(path, rows)
    print(f"{len(cases)} cases, {len(set_rows)} rows -> {set_csv}; pull-off -> {pull_csv}", file=sys.stderr)


if __name__ == "__main__":
    main(*sys.argv[1:5])
