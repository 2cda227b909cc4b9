#!/usr/bin/env python3
"""The theory's error against the small-load set, per model and load range.

small-load-table.py SET_CSV MODELS_CSV

SET_CSV: data/reference/small-load-256.csv (GFMD, mean over seeds); MODELS_CSV:
data/reference/theory-models-small-256.csv (models 1-5 on the same maps). Prints, per model and
per load range, over the loading points (and, separately, the unloading points of the adhesive
cases), the mean and worst |ln(theory / GFMD)| of a_r and of the mean gap, as a markdown table.
"""
import csv
import math
import sys

RANGES = [("1e-5 ≤ p* < 1e-4", 1e-5, 1e-4), ("1e-4 ≤ p* < 1e-3", 1e-4, 1e-3), ("1e-3 ≤ p* ≤ 1e-2", 1e-3, 1.01e-2)]


def main(set_csv, models_csv):
    key = lambda r: (r["thickness_qr"], r["gamma_factor"], r["branch"], f"{float(r['p']):.6e}")
    gfmd = {key(r): r for r in csv.DictReader(open(set_csv)) if r["system"] == "system-2"}
    rows = list(csv.DictReader(open(models_csv)))
    print("| model | branch | loads | points | a_r mean / worst | ū mean / worst |")
    print("|---|---|---|---|---|---|")
    for model in "12345":
        for branch in ("loading", "unloading"):
            for name, lo, hi in RANGES:
                ea, eu = [], []
                for r in rows:
                    if r["model"] != model or r["branch"] != branch:
                        continue
                    if branch == "unloading" and r["gamma_factor"] == "0":
                        continue
                    p = float(r["p"])
                    if not (lo * (1 - 1e-9) <= p < hi * (1 - 1e-9)):
                        continue
                    g = gfmd.get(key(r))
                    if not g:
                        continue
                    a, ga = float(r["theory_a_r"]), float(g["a_r"])
                    if a > 0 and ga > 0:
                        ea.append(abs(math.log(a / ga)))
                    u, gu = float(r["theory_mean_gap_rel"] or "nan"), float(g["mean_gap_rel"] or "nan")
                    if u > 0 and gu > 0:
                        eu.append(abs(math.log(u / gu)))
                if not ea:
                    continue
                f = lambda e: f"{sum(e) / len(e):.3f} / {max(e):.3f} ({math.exp(max(e)):.2f}×)" if e else "–"
                print(f"| {model} | {branch} | {name} | {len(ea)} | {f(ea)} | {f(eu)} |")


if __name__ == "__main__":
    main(*sys.argv[1:3])
