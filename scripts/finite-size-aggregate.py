#!/usr/bin/env python3
"""Joins the finite-size study of scripts/small-load-set.sh into data/reference/finite-size.csv.

finite-size-aggregate.py L2_SET_CSV L2_CASES_CSV L4_SET_CSV L8_SET_CSV OUT_CSV [L16_SET_CSV]

L2_SET_CSV / L2_CASES_CSV: the L/lambda_r = 2 small-load set and its cases (gamma_glo), as
reference-aggregate.py writes them from runs-small-cycle-L2; L4_SET_CSV, L8_SET_CSV: the same
for the loading sweeps on L/lambda_r = 4 and 8 maps (runs-small-sweep-L4, -L8), and optionally 16
(runs-small-sweep-L16). One row per
(case, load) that L/lambda_r = 2 and at least one larger size hold: GFMD's a_r (mean, standard
error) at each size and log_error = |ln(a_r(2) / a_r(largest size))|.
"""
import csv
import math
import sys

from gfmd_runs import write_csv


def read(path):
    try:
        with open(path) as fh:
            return list(csv.DictReader(fh))
    except FileNotFoundError:
        return []


def key(r):
    return (r["system"], r["thickness_qr"], r["gamma_factor"], f"{float(r['p']):.6e}")


def main(l2, l2_cases, l4, l8, out, l16=None):
    glo = {(c["system"], c["thickness_qr"], c["gamma_factor"]): c["gamma_glo"] for c in read(l2_cases)}
    loading = lambda rows: {key(r): r for r in rows if r["branch"] == "loading" and float(r["p"]) > 0}
    sizes = {2: loading(read(l2)), 4: loading(read(l4)), 8: loading(read(l8)), 16: loading(read(l16)) if l16 else {}}
    rows = []
    for k, r2 in sorted(sizes[2].items(), key=lambda kv: (kv[0][:3], float(kv[0][3]))):
        larger = [s for s in (16, 8, 4) if k in sizes[s]]
        if not larger:
            continue
        big = sizes[larger[0]][k]
        row = {"system": k[0], "thickness_qr": k[1], "gamma_factor": k[2],
               "gamma_glo": glo.get(k[:3], ""), "p": r2["p"]}
        for s in (2, 4, 8, 16):
            r = sizes[s].get(k)
            row[f"a_r_L{s}"] = r["a_r"] if r else ""
            row[f"a_r_L{s}_err"] = r["a_r_err"] if r else ""
        a2, ab = float(r2["a_r"]), float(big["a_r"])
        row["log_error"] = f"{abs(math.log(a2 / ab)):.6e}" if a2 > 0 and ab > 0 else ""
        rows.append(row)
    fields = ["system", "thickness_qr", "gamma_factor", "gamma_glo", "p", "a_r_L2", "a_r_L2_err",
              "a_r_L4", "a_r_L4_err", "a_r_L8", "a_r_L8_err", "log_error", "a_r_L16", "a_r_L16_err"]
    write_csv(out, rows, fields)
    print(f"{len(rows)} rows -> {out}", file=sys.stderr)
    print("| t·q_r | γ_s × | p* | a_r at L/λ_r = 2 | 4 | 8 | 16 | \\|ln(a_r(2)/a_r(largest))\\| |")
    print("|---|---|---|---|---|---|---|---|")
    pm = lambda m, e: "–" if not m else (f"{float(m):.3g}" + (f" ± {float(e):.1g}" if e else ""))
    for r in rows:
        print(f"| {r['thickness_qr']} | {r['gamma_factor']} | {float(r['p']):.3g} | "
              f"{pm(r['a_r_L2'], r['a_r_L2_err'])} | {pm(r['a_r_L4'], r['a_r_L4_err'])} | "
              f"{pm(r['a_r_L8'], r['a_r_L8_err'])} | {pm(r['a_r_L16'], r['a_r_L16_err'])} | {r['log_error']} |")


if __name__ == "__main__":
    main(*sys.argv[1:7])
