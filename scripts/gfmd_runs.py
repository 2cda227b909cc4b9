"""What the aggregate scripts share: the GFMD runs' JSON files of a folder (as
reference-set.sh and bandwidth-set.sh name them), the mean and standard error over seeds, the
theory's row at a load, and a CSV written from dict rows.
"""
import csv
import glob
import json
import math
import os
import re

NAME = re.compile(r"(system-\d)-t([^-]+)-g([^-]+)-s(\d+)\.json$")
OBS = ["a_r", "mean_gap_rel", "mean_contact_stress", "contact_stress_variance"]


def mean_se(xs):
    """The mean and standard error s/sqrt(K) of the finite values of xs (None where too few)."""
    xs = [x for x in xs if x is not None and math.isfinite(x)]
    if not xs:
        return None, None
    m = sum(xs) / len(xs)
    if len(xs) < 2:
        return m, None
    var = sum((x - m) ** 2 for x in xs) / (len(xs) - 1)
    return m, math.sqrt(var / len(xs))


def fmt(x):
    return "" if x is None else f"{x:.10e}"


def theory_at(run, p, branch="loading"):
    """The theory's (a_r, mean_gap_rel) at load p on the run's map, on the branch given."""
    th = run.get("theory") or {}
    for r in th.get("rows", []):
        if r["p"] and abs(r["p"] / p - 1) < 1e-9:
            if branch == "unloading" and r.get("a_r_unloading") is not None:
                return r["a_r_unloading"], r.get("mean_gap_unloading_rel")
            return r.get("a_r"), r.get("mean_gap_rel")
    return None, None


def read_cases(runs_dir):
    """The runs of runs_dir by case (system, thickness, gamma factor), in order, each case's
    runs as (seed, run) by seed."""
    cases = {}
    for path in sorted(glob.glob(os.path.join(runs_dir, "*.json"))):
        m = NAME.search(os.path.basename(path))
        if not m:
            continue
        sys_, t, g, seed = m.groups()
        with open(path) as fh:
            cases.setdefault((sys_, t, g), []).append((int(seed), json.load(fh)))
    for runs in cases.values():
        runs.sort(key=lambda sr: sr[0])
    return dict(sorted(cases.items()))


def write_csv(path, rows, fields=None):
    """rows (dicts) under a header of fields, else of the first row's keys."""
    with open(path, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=fields or list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
