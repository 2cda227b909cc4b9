#!/usr/bin/env python3
"""Unloading routes tried against GFMD's unloading branch (docs/physics.md §6.6).

Reads, all under data/reference/:
  reference-set-256.csv     GFMD's loading and unloading a_r (system II, 3 maps, turning
                            load p* = 1e-2, then tension to pull-off);
  pull-off-256.csv          GFMD's pull-off per case;
  unloading-theory-256.csv  the theory on the same reduced maps
                            (`cargo run --example unloading_theory`): the adhesionless
                            a0(p*) table per thickness and the adhesive loading branch of
                            models 4 and 5 at GFMD's loads.

Routes (equations in physics.md §6.6):
  theory   the theory's own unloading branch: equal to its loading branch at these loads
           (no window), no contact at p* <= 0 on most cases;
  pinned   the area a_t held while p* >= p_pin = p_rep(a_t) - sigma_a(q_s) a_t, receding below
           along p* = p_rep(a) - sigma_a(q_s) a (sigma_a(q_s): [S-8] at the finest scale);
  jkr(b)   an ensemble of JKR-shaped patches anchored at the turning point:
             p*(a) = p_rep(a) - kappa a^b,   kappa = (p_rep(a_t) - p*_max) / a_t^b,
           a_t the theory's loading a_r at p*_max, p_rep the adhesionless load holding a
           (the theory's gamma_s = 0 branch inverted); the unloading branch runs from a_t down
           to the first minimum of p*(a), which is the pull-off. b = 3/4: a fixed number of
           patches, each a flat punch detaching at the Griffith load sqrt(8 pi r^3 E* w)
           (the pinned contact: n from the anchor); b = 1/2: one JKR contact's
           sqrt(a)-law as a function of area at a linear p_rep; b fitted: on the slabs'
           other thicknesses (leave-one-thickness-out); b = 3/4 anchored at GFMD's own
           turning a_r as a diagnostic (how much of the error is the theory's a_t);
  split    the turning tension split into a share carried in proportion to the area
           (reversible) and a pinned share phi carried as a^(3/4), phi = 1 - d ln T/d ln p*
           of the theory's loading tension T = p_rep(a_r(p*)) - p* between p_lo and p*_max.

Prints, per route and model: the mean |ln(a_r route / a_r GFMD)| over GFMD's
unloading rows (positive loads below the turning load, p* = 0 and tensile loads), the rows
where the route has detached while GFMD holds, the pull-off ratio, and the hysteresis
confusion counts (GFMD's own unloading/loading ratio > 1.2 against the route's unloading /
the theory's loading > 1.2), and the mean |ln| over the rows where the route holds
contact (the detached rows are counted apart). Plain Python (no NumPy); CPU cost ~10 s.

Usage: scripts/unloading-routes.py [--cases]   (--cases: one line per case as well)
"""
import csv
import math
import os
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "reference")
P_MAX = 1e-2
SLABS = ["0.1", "0.15", "0.2", "0.3"]
THICK = ["0.5", "1", "inf"]
GAMMAS = ["0.5", "1", "2"]
HYST = 1.2


def key(t, g):
    return (t, g.rstrip("0").rstrip(".") if "." in g else g)


def read_gfmd():
    out = {}
    with open(os.path.join(ROOT, "reference-set-256.csv")) as f:
        for r in csv.DictReader(f):
            if r["system"] != "system-2":
                continue
            k = key(r["thickness_qr"], r["gamma_factor"])
            d = out.setdefault(k, {"loading": {}, "unloading": {}})
            d[r["branch"]][float(r["p"])] = (float(r["a_r"]), float(r["a_r_err"]))
    with open(os.path.join(ROOT, "pull-off-256.csv")) as f:
        for r in csv.DictReader(f):
            if r["system"] == "system-2":
                k = key(r["thickness_qr"], r["gamma_factor"])
                out[k]["pull_off"] = float(r["pull_off_pressure"])
    return out


def read_theory():
    dry, loading = {}, {}
    with open(os.path.join(ROOT, "unloading-theory-256.csv")) as f:
        for r in csv.DictReader(f):
            t, g = r["thickness_qr"], r["gamma_factor"]
            if r["kind"] == "dry":
                dry.setdefault(t, []).append((float(r["p"]), float(r["a_r"])))
            else:
                k = key(t, g) + (int(r["model"]),)
                loading.setdefault(k, {})[float(r["p"])] = r
    return dry, loading


def p_rep(table, a):
    """The adhesionless load holding area a: a0(p*) inverted, log-linear between nodes."""
    if a <= table[0][1]:
        return table[0][0] * a / table[0][1]
    for (p0, a0), (p1, a1) in zip(table, table[1:]):
        if a <= a1:
            f = (math.log(a) - math.log(a0)) / (math.log(a1) - math.log(a0))
            return math.exp(math.log(p0) + f * (math.log(p1) - math.log(p0)))
    return table[-1][0]


class Ensemble:
    """p*(a) = p_rep(a) - kappa a^b anchored at (a_t, p*_max); its unloading branch."""

    def __init__(self, table, a_t, b):
        self.table, self.b = table, b
        self.kappa = max(p_rep(table, a_t) - P_MAX, 0.0) / a_t**b
        # the curve on a log grid of a from a_t down, cut at its first minimum
        self.curve = []
        n = 4000
        for i in range(n + 1):
            a = a_t * 10 ** (-8.0 * i / n)
            p = p_rep(table, a) - self.kappa * a**b
            if self.curve and p > self.curve[-1][1]:
                break
            self.curve.append((a, p))
        self.pull_off = min(self.curve[-1][1], 0.0)

    def area(self, p):
        """The branch's a at load p (None past the pull-off)."""
        if p >= self.curve[0][1]:
            return self.curve[0][0]
        for (a0, p0), (a1, p1) in zip(self.curve, self.curve[1:]):
            if p1 <= p <= p0:
                f = (p - p0) / (p1 - p0) if p1 != p0 else 0.0
                return math.exp(math.log(a0) + f * (math.log(a1) - math.log(a0)))
        return None


class Griffith:
    """The pinned contact receding at the finest scale's Griffith stress sigma_a(q_s):
    a = a_t while p* >= p_pin = p_rep(a_t) - sigma a_t, below it p* = p_rep(a) - sigma a
    where that rises with a; where it falls the contact jumps off at p_pin."""

    def __init__(self, table, a_t, sigma):
        self.table, self.a_t, self.sigma = table, a_t, sigma
        self.p_pin = p_rep(table, a_t) - sigma * a_t
        self.curve = []
        n = 4000
        for i in range(n + 1):
            a = a_t * 10 ** (-8.0 * i / n)
            p = min(p_rep(table, a) - sigma * a, self.p_pin)
            if self.curve and p > self.curve[-1][1]:
                break
            self.curve.append((a, p))
        self.pull_off = min(self.curve[-1][1], 0.0)

    def area(self, p):
        if p >= self.p_pin:
            return self.a_t
        return Ensemble.area(self, p)


class Split(Ensemble):
    """The turning tension T_t = p_rep(a_t) - p*_max split into a reversible share carried in
    proportion to the area and a pinned share phi carried as a^(3/4):
    p*(a) = p_rep(a) - (1 - phi) T_t a/a_t - phi T_t (a/a_t)^(3/4)."""

    def __init__(self, table, a_t, phi, b=0.75):
        tension = max(p_rep(table, a_t) - P_MAX, 0.0)
        self.curve = []
        n = 4000
        for i in range(n + 1):
            a = a_t * 10 ** (-8.0 * i / n)
            p = p_rep(table, a) - tension * ((1 - phi) * a / a_t + phi * (a / a_t) ** b)
            if self.curve and p > self.curve[-1][1]:
                break
            self.curve.append((a, p))
        self.pull_off = min(self.curve[-1][1], 0.0)


def stickiness(table, rows, p_lo):
    """phi = 1 - d ln T / d ln p* of the theory's loading tension T = p_rep(a_r(p*)) - p*
    between p_lo and p*_max, in [0, 1]: 0 where T grows as p* (adhesion only steepens a
    linear a_r(p*)), 1 where T stays finite as p* falls (a sticky contact)."""

    def tension(p):
        row = rows[min(rows, key=lambda q: abs(q - p))]
        return p_rep(table, float(row["a_r"])) - p

    x = 1 - math.log(tension(P_MAX) / tension(p_lo)) / math.log(P_MAX / p_lo)
    return min(max(x, 0.0), 1.0)


def unloading_rows(gfmd, k):
    """GFMD's unloading rows below the turning load: (p, a_r, err)."""
    return sorted(
        ((p, a, e) for p, (a, e) in gfmd[k]["unloading"].items() if p < P_MAX * 0.999),
        reverse=True,
    )


def judge(gfmd, dry, loading, cases, route, model, verbose=False):
    """Errors of `route(t, g, a_t, table)` -> Ensemble-like on `cases`."""
    errs, detached, po, conf = [], 0, [], {"tp": 0, "fn": 0, "fp": 0, "tn": 0}
    for t, g in cases:
        k = key(t, g)
        th = loading[k + (model,)]
        a_t = float(th[min(th, key=lambda p: abs(p - P_MAX))]["a_r"])
        ens = route(t, g, a_t, dry[t])
        line = []
        for p, a_g, _ in unloading_rows(gfmd, k):
            a = ens.area(p)
            if a is None:
                detached += 1
                line.append(f"{p:.1e}:det/{a_g:.3f}")
                continue
            errs.append(abs(math.log(a / a_g)))
            line.append(f"{p:.1e}:{a:.3f}/{a_g:.3f}")
            if p > 0:
                a_load = float(th[min(th, key=lambda q: abs(q - p))]["a_r"])
                gl = gfmd[k]["loading"][min(gfmd[k]["loading"], key=lambda q: abs(q - p))][0]
                hg, hr = a_g / gl > HYST, a / a_load > HYST
                conf[("t" if hg == hr else "f") + ("p" if hr else "n")] += 1
        r = ens.pull_off / gfmd[k]["pull_off"] if gfmd[k]["pull_off"] < 0 else float("nan")
        po.append(r)
        if verbose:
            print(f"    {t:>5} x{g:<3} po {ens.pull_off:.2e}/{gfmd[k]['pull_off']:.2e} " + " ".join(line))
    mean = sum(errs) / len(errs) if errs else float("nan")
    po_ok = [abs(math.log(x)) for x in po if x > 0]
    po_mean = sum(po_ok) / len(po_ok) if po_ok else float("nan")
    return mean, len(errs), detached, po_mean, sum(1 for x in po if x == 0), conf


class TheoryOwn:
    """The theory's own unloading: its loading branch at p* > 0 (no window), none below."""

    def __init__(self, loading_rows):
        self.rows = loading_rows
        self.pull_off = 0.0

    def area(self, p):
        if p <= 0:
            return None
        return float(self.rows[min(self.rows, key=lambda q: abs(q - p))]["a_r"])


def fit_beta(gfmd, dry, loading, cases, model):
    """b minimising the mean |ln| error on `cases` (golden section on [0.05, 0.99])."""

    def cost(b):
        m, n, det, *_ = judge(gfmd, dry, loading, cases, lambda t, g, a, tab: Ensemble(tab, a, b), model)
        return (m * n + det * math.log(10)) / max(n + det, 1)

    lo, hi = 0.05, 0.99
    for _ in range(30):
        m1, m2 = lo + 0.382 * (hi - lo), hi - 0.382 * (hi - lo)
        if cost(m1) < cost(m2):
            hi = m2
        else:
            lo = m1
    return 0.5 * (lo + hi)


def report(name, res):
    mean, n, det, po, po_none, c = res
    print(
        f"  {name:<30} mean|ln| {mean:5.2f} over {n:3d} rows, detached {det:2d}; "
        f"pull-off mean|ln| {po:5.2f}; hysteresis tp {c['tp']:2d} fn {c['fn']:2d} fp {c['fp']:2d} tn {c['tn']:2d}"
    )


GROUPS = (
    ("slabs t*q_r <= 0.3", SLABS),
    ("t*q_r 0.5 and 1", ["0.5", "1"]),
    ("half-space", ["inf"]),
)


def main():
    verbose = "--cases" in sys.argv
    gfmd = read_gfmd()
    dry, loading = read_theory()
    slab_cases = [(t, g) for t in SLABS for g in GAMMAS]
    for model in (4, 5):
        print(f"model {model} (a_t and the theory's loading branch)")
        betas = {t_out: fit_beta(gfmd, dry, loading, [c for c in slab_cases if c[0] != t_out], model) for t_out in SLABS}
        b_all = fit_beta(gfmd, dry, loading, slab_cases, model)
        print(f"  b fitted on the slabs: {b_all:.3f}; each slab thickness left out: "
              + ", ".join(f"{t}: {b:.3f}" for t, b in betas.items()))
        for label, thick in GROUPS:
            print(f" {label}")
            cases = [(t, g) for t in thick for g in GAMMAS]
            own = lambda t, g, a, tab, m=model: TheoryOwn(loading[key(t, g) + (m,)])
            report("theory (no window)", judge(gfmd, dry, loading, cases, own, model))
            sig = lambda t, g, m=model: float(loading[key(t, g) + (m,)][P_MAX]["sigma_a"])
            route = lambda t, g, a, tab: Griffith(tab, a, sig(t, g))
            report("pinned, Griffith sigma_a(q_s)", judge(gfmd, dry, loading, cases, route, model))
            for b in (0.5, 0.75):
                route = lambda t, g, a, tab, b=b: Ensemble(tab, a, b)
                report(f"jkr b = {b}", judge(gfmd, dry, loading, cases, route, model))
            # diagnostic: the same route anchored at GFMD's own turning a_r (not the theory's)
            a_g = lambda t, g: gfmd[key(t, g)]["loading"][max(gfmd[key(t, g)]["loading"])][0]
            route = lambda t, g, a, tab: Ensemble(tab, a_g(t, g), 0.75)
            report("jkr b = 0.75 at GFMD's a_t", judge(gfmd, dry, loading, cases, route, model))
            # the pinned share from the theory's loading tension between p_lo and p*_max
            for p_lo in (1e-4, 1e-3):
                phi = lambda t, g, p_lo=p_lo, m=model: stickiness(dry[t], loading[key(t, g) + (m,)], p_lo)
                route = lambda t, g, a, tab, phi=phi: Split(tab, a, phi(t, g))
                report(f"split, phi from {p_lo:.0e}", judge(gfmd, dry, loading, cases, route, model))
            # b fitted without the case's own thickness (slabs), or on all slabs (others)
            route = lambda t, g, a, tab: Ensemble(tab, a, betas.get(t, b_all))
            report("jkr b fitted (held out)", judge(gfmd, dry, loading, cases, route, model))
        if verbose:
            print(f" per case, jkr b = 0.75, model {model}: pull-off route/GFMD, p*: a_r route/GFMD unloading")
            cases = [(t, g) for _, thick in GROUPS for t in thick for g in GAMMAS]
            judge(gfmd, dry, loading, cases, lambda t, g, a, tab: Ensemble(tab, a, 0.75), model, True)


if __name__ == "__main__":
    main()
