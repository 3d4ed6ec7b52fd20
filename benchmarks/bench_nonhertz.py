"""Time per case of the non-Hertzian wheel-on-roller patch (rollerrig.geometry.patch)
on CONTACT's 72 roller-rig cases (tests/data/roller_nonhertz_cases.csv):

    python benchmarks/bench_nonhertz.py

- h alone: undeformed_distance on CONTACT's inputs (its pose, reference and
  0.4 mm grid);
- h and the solve: that plus one exact_solve (tests/test_nonhertz.py's
  "CONTACT's inputs");
- the full chain: rig_exact from rollerrig's geometry with the vertical
  load (its first, coarse pass, the load's iteration and the rebuild), on
  the 0.4 mm grid and on the default grid (n = 40);
- CONTACT: the file's t_calc, cntc_calculate's wall time per case (its header:
  a 2-core shared machine), for context; it includes CONTACT's own search
  for the vertical load.
"""
import csv
import os
import time

import numpy as np

import rollerrig as rr

HERE = os.path.dirname(os.path.abspath(__file__))


def cases():
    path = os.path.join(HERE, "..", "tests", "data", "roller_nonhertz_cases.csv")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return [{k: (float(v) if k not in ("key", "pair", "side", "wheel_profile",
                                       "roller_profile") else v) for k, v in r.items()}
            for r in rows]


def main():
    geo = {"miniprof": rr.RigGeometry.measured_pair(),
           "s1002_uic60": rr.RigGeometry.standard(roller_radius=0.8001)}
    tables = {k: rr.contact_table(g, -0.0065, 0.0065, 261) for k, g in geo.items()}
    cs = cases()

    def patch(c):
        return rr.undeformed_distance(geo[c["pair"]], c["y_ws"], approach=c["approach"],
                                      reference=(c["s_roller"], c["delta"]), dx=c["dx"],
                                      dy=c["ds"], z=c["wheel_radius"] - c["z_ws"],
                                      roll=c["roll"])

    def solve(c):
        p = patch(c)
        return rr.exact_solve(p.h, dx=p.dx, dy=p.dy, x0=p.x0, y0=p.y0, N=c["FN"], mu=c["mu"],
                              G=c["G"], nu=c["nu"], cx=c["cx"], cy=c["cy"], cphi=c["cphi"])

    def chain(c, **kw):
        return rr.rig_exact(geo[c["pair"]], c["y_ws"], Fz=c["FZ"], mu=c["mu"], spin=c["spin"],
                            roller_spin=c["roller_spin"], E=2 * c["G"] * (1 + c["nu"]),
                            nu=c["nu"], table=tables[c["pair"]], **kw)

    rows = []
    for name, f in (("h alone (CONTACT's inputs, 0.4 mm)", patch),
                    ("h and one solve (CONTACT's inputs, 0.4 mm)", solve),
                    ("full chain, Fz (0.4 mm)", lambda c: chain(c, dx=c["dx"], dy=c["ds"])),
                    ("full chain, Fz (n = 40)", chain)):
        f(cs[0])                                        # warm up
        t = []
        for c in cs:
            t0 = time.perf_counter()
            f(c)
            t.append(time.perf_counter() - t0)
        rows.append((name, 1e3 * np.median(t), 1e3 * np.max(t)))
    tc = np.array([c["t_calc"] for c in cs])
    rows.append(("CONTACT cntc_calculate (the file's t_calc)", 1e3 * np.median(tc),
                 1e3 * np.max(tc)))
    print("| what | ms per case, median | max |")
    print("|---|---|---|")
    for name, med, mx in rows:
        print(f"| {name} | {med:.1f} | {mx:.1f} |")


if __name__ == "__main__":
    main()
