"""Accuracy of rig_contact(patch="nonhertz") against the library's exact
solver (rig_exact) on CONTACT's 72 roller cases (tests/data/roller_nonhertz_
cases.csv: both pairs, left wheel, -5.5 to +5.5 mm, three creepages), beside
today's single Hertz ellipse (FASTSIM 20 x 20, and the exact table).

Rows 0.1 mm either side of each case's shift (the case half-way between two
rows: the worst place for the rows' blend).  |F - F_ref| / (mu N_ref) of the
wheel's total force (normal force included), and the normal solution.

    python benchmarks/bench_nonhertz_accuracy.py [--half 1e-4] [--n-ref 40]
"""
import argparse
import sys
import time
from pathlib import Path

import numpy as np

import rollerrig as rr

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from reference_cases import read_columns  # noqa: E402

C = read_columns("roller_nonhertz_cases.csv")


def geometry(pair):
    if pair == "miniprof":
        return rr.RigGeometry.measured_pair()
    return rr.RigGeometry.standard(roller_radius=0.8001)


def run(half=1e-4, n_ref=40, richardson=True, workers=2):
    out = {}
    for pair in ("miniprof", "s1002_uic60"):
        g = geometry(pair)
        ct = rr.contact_table(g, -0.0065, 0.0065, 261)
        m = np.flatnonzero(C["pair"] == pair)
        ys = np.unique(C["y_ws"][m])
        rows = np.unique(np.round(np.concatenate([ys - half, ys + half]), 9))
        t0 = time.perf_counter()
        E = 2 * C["G"][m[0]] * (1 + C["nu"][m[0]])
        tab = rr.nonhertz_table(g, None, None, y=rows, Fz=float(C["FZ"][m[0]]),
                                mu_ref=float(C["mu"][m[0]]), E=E, sides=("left",),
                                richardson=richardson, workers=workers)
        tb = time.perf_counter() - t0
        tab = rr.NonHertzTable(tab.left, tab.left, tab.Fz)   # the right side unused here
        res = []
        for i in m:
            kw = dict(y=C["y_ws"][i], spin=C["spin"][i], roller_spin=C["roller_spin"][i],
                      mu=C["mu"][i], E=E, nu=C["nu"][i])
            ref = rr.rig_exact(g, C["y_ws"][i], Fz=C["FZ"][i], mu=C["mu"][i],
                               spin=C["spin"][i], roller_spin=C["roller_spin"][i], E=E,
                               nu=C["nu"][i], table=ct, n=n_ref)
            nh = rr.rig_contact(ct, Fz_left=C["FZ"][i], Fz_right=C["FZ"][i], patch="nonhertz",
                                nonhertz=tab, **kw).left
            hz = rr.rig_contact(ct, Fz_left=C["FZ"][i], Fz_right=C["FZ"][i], **kw).left
            ht = rr.rig_contact(ct, Fz_left=C["FZ"][i], Fz_right=C["FZ"][i],
                                method="exact_table", **kw).left
            muN = C["mu"][i] * ref.N
            s = ref.solution
            centre = ref.patch.point + (s.pn * s.x).sum() / s.pn.sum() * ref.patch.t1 \
                + (s.pn * s.y).sum() / s.pn.sum() * ref.patch.t2
            res.append(dict(
                y=C["y_ws"][i], nh=np.linalg.norm(nh.force - ref.force) / muN,
                hertz=np.linalg.norm(hz.force - ref.force) / muN,
                hertz_table=np.linalg.norm(ht.force - ref.force) / muN,
                dN=abs(nh.N / ref.N - 1), dA=abs(nh.area / s.contact_area - 1),
                dp=abs(nh.pmax / s.pmax - 1), dc=np.linalg.norm(nh.centre - centre),
                dA_h=abs(np.pi * hz.a * hz.b / s.contact_area - 1),
                dp_h=abs(hz.p0 / s.pmax - 1)))
        out[pair] = dict(build_s=tb, rows=rows.size, cases=res)
    return out


def stats(v):
    v = np.asarray(v)
    return f"{np.percentile(v, 95):.4f} / {v.max():.4f}"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--half", type=float, default=1e-4)
    ap.add_argument("--n-ref", type=int, default=40)
    ap.add_argument("--no-richardson", action="store_true")
    a = ap.parse_args()
    out = run(a.half, a.n_ref, not a.no_richardson)
    allc = [c for p in out.values() for c in p["cases"]]
    print(f"reference rig_exact n = {a.n_ref}; rows +-{a.half * 1e3:g} mm around each case; "
          f"Richardson {not a.no_richardson}")
    print("| set | nonhertz p95 / max | Hertz FASTSIM | Hertz exact_table | dN | dA | dp | "
          "centre [mm] | rows, build [s] |")
    for name, cs, extra in [(p, out[p]["cases"], f"{out[p]['rows']}, {out[p]['build_s']:.1f}")
                            for p in out] + [("all 72", allc, "")]:
        col = lambda k: [c[k] for c in cs]
        print(f"| {name} | {stats(col('nh'))} | {stats(col('hertz'))} | "
              f"{stats(col('hertz_table'))} | {np.percentile(col('dN'), 95):.4f} | "
              f"{np.percentile(col('dA'), 95):.3f} | {np.percentile(col('dp'), 95):.3f} | "
              f"{np.percentile(col('dc'), 95) * 1e3:.3f} | {extra} |")
    worst = max(allc, key=lambda c: c["nh"])
    print("worst nonhertz case:", worst)


if __name__ == "__main__":
    main()
