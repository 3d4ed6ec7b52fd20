"""Time per case of the non-Hertzian wheel-on-roller patch and of rig_exact on
CONTACT's 72 roller-rig cases (tests/data/roller_nonhertz_cases.csv), before
and after the C core took them over (issue 24: csrc/geometry/rr_gap.h,
rr_wheel_exact.h):

    python benchmarks/bench_nonhertz.py [--repeat R]

- h alone: undeformed_distance on CONTACT's inputs (its pose, reference and
  0.4 mm grid);
- h and the solve: that plus one exact_solve (tests/test_nonhertz.py's
  "CONTACT's inputs");
- the full chain: rig_exact from rollerrig's geometry with the vertical
  load (its first, coarse pass, the load's iteration and the rebuild), on
  the 0.4 mm grid and on the default grid (n = 40);
- "before" is the Python construction as it was (tests/_nonhertz_python.py,
  which the tests hold the C one to), "after" the package's;
- where the full chain's time goes (after): the Python before the core
  (the zero-gap pose and contact point, the wheelset's motion from
  rig_contact), the patches built (their count times one build's time:
  undeformed_distance at the final patch's options less its pose search)
  and the solves (their count times one exact_solve of the final patch, a
  fresh workspace: an upper bound, the core keeps a grid's spectra from
  solve to solve);
- CONTACT: the file's t_calc, cntc_calculate's wall time per case (its
  header: a 2-core shared machine), for context; it includes CONTACT's own
  search for the vertical load.
Times are medians of R repeats (default 1) per case, then the median and
the largest over the cases; the machine is shared, so they move by 10-30 %
from run to run.

    python benchmarks/bench_nonhertz.py --chain [--repeat R] [--every K] [--grid G] [--worst W]

times the full chain alone, with whichever rollerrig the interpreter
imports, and the C call's part of it (rr_wheel_exact through the
binding): run it with another checkout's environment for its "before"
(main's build, then this one's, one after the other), one row per grid
with the solves per case (--worst W: the W slowest cases of each grid
after its row, with their solves, patches and grid sizes: what sets the
p95).  The cases run in turn, R sweeps of them, as a
table's rows or the rig's steps would: a case's grids often have the last
one's sizes, whose kernel spectra the core keeps.  The instruction count
of the C core (the measure on a shared machine):

    valgrind --tool=callgrind --toggle-collect=py_wheel_exact \
        python benchmarks/bench_nonhertz.py --chain --every 6 --grid 0.4

(every sixth case: the 12 of RESULTS.md's profiles, 13 calls with the
warm-up, the first case twice; six cases apart, their grids' sizes seldom
repeat: the cost of a case alone); without --every, all 72 in turn (the
cost of a sweep).
"""
import argparse
import csv
import os
import sys
import time

import numpy as np

import rollerrig as rr
from rollerrig.geometry.patch import _pose_and_point
from rollerrig.rig.exact import _motion

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests"))
import _nonhertz_python as before  # noqa: E402  (the construction the core replaced)


def cases():
    path = os.path.join(HERE, "..", "tests", "data", "roller_nonhertz_cases.csv")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    return [{k: (float(v) if k not in ("key", "pair", "side", "wheel_profile",
                                       "roller_profile") else v) for k, v in r.items()}
            for r in rows]


def timed(f, c, repeat):
    t = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = f(c)
        t.append(time.perf_counter() - t0)
    return float(np.median(t)), out


class _CoreTimer:
    """rollerrig.rig.exact's _core with wheel_exact timed: the C call alone
    (rr_wheel_exact and the binding's arrays), apart from rig_exact's Python."""

    def __init__(self, core):
        self._core, self.spent = core, 0.0

    def __getattr__(self, name):
        return getattr(self._core, name)

    def wheel_exact(self, *args):
        t0 = time.perf_counter()
        try:
            return self._core.wheel_exact(*args)
        finally:
            self.spent += time.perf_counter() - t0


def chain_only(geo, tables, cs, repeat, grids="both", worst=0):
    """The full chain of the rollerrig imported, on both grids: ms per case
    (median, p95, max over the cases of each case's median of R sweeps over
    the cases in turn: each case after the one before, whose grids often
    have its sizes and so its kernel spectra),
    the C call's share of it (rr_wheel_exact through the binding, the same
    statistics), and the solves per case (median, max); with worst, the
    slowest cases after each grid's row (what sets its p95)."""
    import rollerrig.rig.exact as exact
    print(f"rollerrig from {os.path.dirname(rr.__file__)}")
    print("| full chain | ms per case, median | p95 | max | the C call: median | p95 | max "
          "| solves per case, median | max |")
    print("|---|---|---|---|---|---|---|---|---|")
    timer = _CoreTimer(exact._core)
    exact._core = timer
    try:
        for name, grid in (("0.4 mm", True), ("n = 40", False)):
            if grids != "both" and grid != (grids == "0.4"):
                continue

            def chain(c):
                kw = dict(dx=c["dx"], dy=c["ds"]) if grid else {}
                return rr.rig_exact(geo[c["pair"]], c["y_ws"], Fz=c["FZ"], mu=c["mu"],
                                    spin=c["spin"], roller_spin=c["roller_spin"],
                                    E=2 * c["G"] * (1 + c["nu"]), nu=c["nu"],
                                    table=tables[c["pair"]], **kw)
            chain(cs[0])                                     # warm up
            # the cases in turn, as a sweep's (a table's rows, the rig's
            # steps): each after the one before, R sweeps
            whole = np.empty((repeat, len(cs)))
            core = np.empty((repeat, len(cs)))
            p = np.empty(len(cs), dtype=int)
            shape = {}
            for r in range(repeat):
                for i, c in enumerate(cs):
                    timer.spent = 0.0
                    t0 = time.perf_counter()
                    out = chain(c)
                    whole[r, i] = time.perf_counter() - t0
                    core[r, i] = timer.spent
                    p[i] = out.passes
                    shape[i] = (out.builds, out.patch.h.shape)
            t, tc = 1e3 * np.median(whole, axis=0), 1e3 * np.median(core, axis=0)
            print(f"| {name} | {np.median(t):.2f} | {np.percentile(t, 95):.2f} | {t.max():.2f} "
                  f"| {np.median(tc):.2f} | {np.percentile(tc, 95):.2f} | {tc.max():.2f} "
                  f"| {np.median(p):g} | {p.max()} |")
            for i in np.argsort(t)[::-1][:worst]:
                c = cs[i]
                print(f"    {c['key']}: {t[i]:.2f} ms (C {tc[i]:.2f}), {p[i]} solves, "
                      f"{shape[i][0]} patches, grid {shape[i][1][1]} x {shape[i][1][0]}")
    finally:
        exact._core = timer._core


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--chain", action="store_true",
                    help="the full chain alone, of the rollerrig imported")
    ap.add_argument("--every", type=int, default=1,
                    help="every k-th of the 72 cases (6: the 12 of the callgrind profile)")
    ap.add_argument("--grid", choices=("both", "0.4", "n40"), default="both",
                    help="--chain: the grids run")
    ap.add_argument("--worst", type=int, default=0,
                    help="--chain: list the K slowest cases of each grid")
    args = ap.parse_args()
    repeat = args.repeat
    geo = {"miniprof": rr.RigGeometry.measured_pair(),
           "s1002_uic60": rr.RigGeometry.standard(roller_radius=0.8001)}
    tables = {k: rr.contact_table(g, -0.0065, 0.0065, 261) for k, g in geo.items()}
    cs = cases()[::args.every]
    if args.chain:
        chain_only(geo, tables, cs, repeat, args.grid, args.worst)
        return

    def mk(m):
        def patch(c):
            return m.undeformed_distance(geo[c["pair"]], c["y_ws"], approach=c["approach"],
                                         reference=(c["s_roller"], c["delta"]), dx=c["dx"],
                                         dy=c["ds"], z=c["wheel_radius"] - c["z_ws"],
                                         roll=c["roll"])

        def solve(c):
            p = patch(c)
            return rr.exact_solve(p.h, dx=p.dx, dy=p.dy, x0=p.x0, y0=p.y0, N=c["FN"],
                                  mu=c["mu"], G=c["G"], nu=c["nu"], cx=c["cx"], cy=c["cy"],
                                  cphi=c["cphi"])

        def chain(c, **kw):
            return m.rig_exact(geo[c["pair"]], c["y_ws"], Fz=c["FZ"], mu=c["mu"],
                               spin=c["spin"], roller_spin=c["roller_spin"],
                               E=2 * c["G"] * (1 + c["nu"]), nu=c["nu"],
                               table=tables[c["pair"]], **kw)
        return patch, solve, chain

    rows, after_chains = [], {}
    impls = (("before", mk(before)), ("after", mk(rr)))
    for name, which in (("h alone (CONTACT's inputs, 0.4 mm)", 0),
                        ("h and one solve (CONTACT's inputs, 0.4 mm)", 1),
                        ("full chain, Fz (0.4 mm)", 2), ("full chain, Fz (n = 40)", 3)):
        row = [name]
        for label, (patch, solve, chain) in impls:
            f = {0: patch, 1: solve,
                 2: lambda c, chain=chain: chain(c, dx=c["dx"], dy=c["ds"]),
                 3: chain}[which]
            f(cs[0])                                     # warm up
            res = [timed(f, c, repeat) for c in cs]
            t = np.array([r[0] for r in res])
            row += [1e3 * np.median(t), 1e3 * t.max()]
            if which >= 2:
                row.append(np.median([r[1].passes for r in res]))
                if label == "after":
                    after_chains[name] = (t, [r[1] for r in res])
            else:
                row.append(float("nan"))
        rows.append(row)
    tc = np.array([c["t_calc"] for c in cs])
    print("| what | before: ms per case, median | max | solves | after: median | max "
          "| solves |")
    print("|---|---|---|---|---|---|---|")
    for name, bm, bx, bs, am, ax, as_ in rows:
        s = (lambda v: "" if np.isnan(v) else f"{v:g}")
        print(f"| {name} | {bm:.1f} | {bx:.1f} | {s(bs)} | {am:.1f} | {ax:.1f} | {s(as_)} |")
    print(f"| CONTACT cntc_calculate (the file's t_calc) | | | | {1e3 * np.median(tc):.1f} | "
          f"{1e3 * tc.max():.1f} | |")

    # where the full chain's time goes (after)
    print()
    print("| after, full chain | per case, median: total ms | pose and motion (Python) | "
          "builds x one build | solves x one solve (fresh) |")
    print("|---|---|---|---|---|")
    for name, (t, res) in after_chains.items():
        pre, build, solve = [], [], []
        for c, e in zip(cs, res):
            g, p = geo[c["pair"]], e.patch
            t0 = time.perf_counter()
            _pose_and_point("bench", g, c["y_ws"], "left")
            _motion(g, c["y_ws"], c["spin"], c["roller_spin"], 0.0, 0.0, 1e-3,
                    tables[c["pair"]])
            t1 = time.perf_counter()
            rr.undeformed_distance(g, c["y_ws"], approach=p.approach, cover=p.cover,
                                   dx=p.dx, dy=p.dy, z=p.z, roll=p.roll)
            t2 = time.perf_counter()
            _pose_and_point("bench", g, c["y_ws"], "left")
            t3 = time.perf_counter()
            rr.exact_solve(p.h, dx=p.dx, dy=p.dy, x0=p.x0, y0=p.y0, N=e.N, mu=c["mu"],
                           G=c["G"], nu=c["nu"], cx=e.cx, cy=e.cy, cphi=e.cphi)
            t4 = time.perf_counter()
            pre.append(t1 - t0)
            build.append(e.builds * ((t2 - t1) - (t3 - t2)))
            solve.append(e.passes * (t4 - t3))
        med = (lambda v: 1e3 * float(np.median(v)))
        builds = np.median([e.builds for e in res])
        passes = np.median([e.passes for e in res])
        print(f"| {name} | {med(t):.1f} | {med(pre):.2f} | {builds:g} x = {med(build):.2f} | "
              f"{passes:g} x = {med(solve):.1f} |")


if __name__ == "__main__":
    main()
