"""Time of the exact solver (method "exact") per Hertzian case against the
grid size, its FFT products, and two threads against one.

    python benchmarks/bench_exact.py [--cases 40] [--sizes 11,21,27,45,61,81,101]
                                     [--rounds 5] [--threads-cases 300] [--vs OTHER_TREE]

The cases are the first ones of tests/data/contact_exact_cases.csv (random
a/b, load, friction, creepage up to 3x the characteristic one, spin in two
thirds of them).  CONTACT's own exact solver (SteadyGS, no FFT) measured on
this machine: 40 ms per case at 27 elements across, 328 ms at 45 (issue 13).

Each time is the fastest of --rounds runs of the batch (on a shared machine
the slower runs time the neighbours).  The report says how busy the machine
was: the load average, the CPU time other processes used during each
section (from /proc/stat; 0 = quiet, 1 = another process kept a core busy)
and a fixed pure-Python workload timed before and after each section.

Also a creep curve (60 creepages at one a/b and load, so the normal problem
is solved once and reused) and two threads against one.

--vs OTHER_TREE times another build of the package side by side at 27 and
45 across, on the random cases and on the creep curve (a source tree with
its extension built in place, e.g. the commit before a change): the two
take turns in child interpreters, round by round, so that a slow spell of
the machine hits both alike.
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import threading
import time

import numpy as np

import rollerrig as rr

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from _bench_common import CpuMonitor, conditions_lines, load_average  # noqa: E402

CONTACT_MS = {27: 40.0, 45: 328.0}


def cases(n):
    path = os.path.join(HERE, "..", "tests", "data", "contact_exact_cases.csv")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))[:n]
    return {k: np.array([float(r[k]) for r in rows])
            for k in ("xi", "eta", "phi", "a", "b", "N", "mu", "G", "nu")}


def run(d, nx):
    return rr.creep_forces(d["xi"], d["eta"], d["phi"], a=d["a"], b=d["b"], N=d["N"],
                           mu=d["mu"], G=d["G"], nu=d["nu"], method="exact", nx=nx, ny=nx)


def best_ms(d, nx, rounds):
    """ms per case, the fastest of `rounds` runs of the batch (on a shared
    machine the slower runs measure the neighbours, not the solver)."""
    best = float("inf")
    for _ in range(rounds):
        t = time.perf_counter()
        run(d, nx)
        best = min(best, time.perf_counter() - t)
    return best / len(d["xi"]) * 1e3


def products(d, nx, k):
    """Median FFT products (normal, tangential) and Newton steps of the first k cases."""
    out = []
    for i in range(k):
        s = rr.exact_field(d["xi"][i], d["eta"][i], d["phi"][i], a=d["a"][i], b=d["b"][i],
                           N=d["N"][i], mu=d["mu"][i], G=d["G"][i], nu=d["nu"][i], nx=nx,
                           ny=nx)
        out.append(s.products + (s.newton_steps,))
    return np.median(np.array(out), axis=0)


def curve(d):
    """A creep curve: 60 creepages along the first case's direction (its
    spin scaled alike), 0.05 to 3 times its characteristic creepage, at its
    a/b, load and friction: the normal problem is the same for all of them
    and is solved once (the workspace keeps it)."""
    m = np.linspace(0.05, 3.0, 60)
    scale = m / np.hypot(d["xi"][0], d["eta"][0]) * (d["mu"][0] * d["N"][0]) / (
        d["G"][0] * d["a"][0] * d["b"][0] * 4.0)
    c = {k: np.full(60, d[k][0]) for k in ("a", "b", "N", "mu", "G", "nu")}
    c.update(xi=d["xi"][0] * scale, eta=d["eta"][0] * scale, phi=d["phi"][0] * scale)
    return c


def subset(d, nx, ncases):
    """As many cases at nx as ncases take at 27 across (at least 4)."""
    return {k: v[: max(4, ncases * 27 * 27 // (nx * nx))] for k, v in d.items()}


_CHILD = r"""
import json, sys
sys.path.insert(0, sys.argv[1])
import bench_exact as b
nx, n = int(sys.argv[2]), int(sys.argv[3])
d = b.curve(b.cases(1)) if sys.argv[4] == "curve" else b.subset(b.cases(n), nx, n)
b.run(d, nx)
print(json.dumps([b.best_ms(d, nx, 3), b.rr.__file__]))
"""


def child_ms(tree, nx, ncases, what="cases"):
    """ms per case of the package in `tree` (None: the one this interpreter
    imports), in a child interpreter, the fastest of 3 runs; and the
    package's path.  The child runs in the tree (or in this package's
    parent): its working directory comes first on its path."""
    env = dict(os.environ)
    if tree:
        env["PYTHONPATH"] = os.path.abspath(tree) + os.pathsep + env.get("PYTHONPATH", "")
    cwd = os.path.abspath(tree) if tree else os.path.dirname(os.path.dirname(rr.__file__))
    out = subprocess.run([sys.executable, "-c", _CHILD, HERE, str(nx), str(ncases), what],
                         env=env, cwd=cwd, capture_output=True, text=True, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def side_by_side(tree, ncases, rounds):
    rows, paths = [], set()
    for what in ("cases", "curve"):
        for nx in (27, 45):
            mine, other = float("inf"), float("inf")
            for _ in range(rounds):
                ms, path = child_ms(None, nx, ncases, what)
                mine = min(mine, ms)
                ms, opath = child_ms(tree, nx, ncases, what)
                other = min(other, ms)
                paths.add((path, opath))
            rows.append(f"| {'random cases' if what == 'cases' else 'creep curve'} | {nx} "
                        f"| {mine:.3f} | {other:.3f} | {mine / other:.3f} |")
    (path, opath), = paths
    return [f"\nthis build ({os.path.dirname(path)}) against {os.path.dirname(opath)} (the two "
            f"taking turns, fastest of {rounds} rounds of 3 runs each):", "",
            "| cases | elements across | this build ms | other ms | ratio |",
            "|---|---|---|---|---|"] + rows


def speed_table(sizes, ncases, rounds):
    d = cases(ncases)
    lines = ["| elements across | grid | ms per case (1 thread) | FFT products normal / "
             "tangential (median) | Newton steps | CONTACT ms | ratio |",
             "|---|---|---|---|---|---|---|"]
    for nx in sizes:
        sub = subset(d, nx, ncases)
        run(sub, nx)                                   # warm up
        ms = best_ms(sub, nx, rounds)
        pn, pt, nw = products(d, nx, len(d["xi"]))
        ref = CONTACT_MS.get(nx)
        ratio = f"{ref / ms:.1f}x faster" if ref else ""
        lines.append(f"| {nx} | {nx + 4}x{nx + 4} | {ms:.2f} | {pn:.0f} / {pt:.0f} | {nw:.0f} "
                     f"| {ref or ''} | {ratio} |")
    return lines


def curve_lines(rounds):
    c = curve(cases(1))
    out = []
    for nx in (27, 45):
        run(c, nx)
        ms = best_ms(c, nx, rounds)
        out.append(f"{nx} across {ms:.2f} ms ({CONTACT_MS[nx] / ms:.0f}x CONTACT's random-case "
                   "time)")
    return ["\na creep curve (60 creepages at one a/b and load: the normal problem solved "
            "once), per case: " + "; ".join(out)]


def threads_line(nthreads_cases):
    """Two threads, each its own batch (and workspace), against one thread
    doing both: nthreads_cases cases at 27 across, three rounds."""
    nx = 27
    d = cases(nthreads_cases)
    run(d, nx)
    ratios = []
    for _ in range(3):
        t = time.perf_counter()
        run(d, nx)
        run(d, nx)
        one = time.perf_counter() - t
        ts = [threading.Thread(target=run, args=(d, nx)) for _ in range(2)]
        t = time.perf_counter()
        for th in ts:
            th.start()
        for th in ts:
            th.join()
        two = time.perf_counter() - t
        ratios.append(f"{one / two:.2f}x ({one * 1e3:.0f} ms against {two * 1e3:.0f} ms)")
    return [f"\ntwo threads against one ({2 * len(d['xi'])} cases at 27 across), three "
            f"rounds: {'; '.join(ratios)}"]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cases", type=int, default=40)
    ap.add_argument("--sizes", default="11,21,27,45,61,81,101")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--threads-cases", type=int, default=300)
    ap.add_argument("--vs", metavar="OTHER_TREE",
                    help="time this source tree's build of the package side by side")
    args = ap.parse_args()
    load0 = load_average()
    mon = CpuMonitor()
    lines = mon.section("sizes", speed_table, [int(s) for s in args.sizes.split(",")],
                        args.cases, args.rounds)
    lines += mon.section("curve", curve_lines, args.rounds)
    lines += mon.section("threads", threads_line, args.threads_cases)
    if args.vs:
        lines += mon.section("side by side", side_by_side, args.vs, args.cases, args.rounds)
    lines += [""] + conditions_lines(load0, load_average(), mon)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
