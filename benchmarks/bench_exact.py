"""Time of the exact solver (method "exact") per Hertzian case against the
grid size, its FFT products, and two threads against one.

    python benchmarks/bench_exact.py [--cases 40] [--sizes 11,27,45,61,101] [--rounds 5]

The cases are the first ones of tests/data/contact_exact_cases.csv (random
a/b, load, friction, creepage up to 3x the characteristic one, spin in two
thirds of them).  CONTACT's own exact solver (SteadyGS, no FFT) measured on
this machine: 40 ms per case at 27 elements across, 328 ms at 45 (issue 13).
"""
import argparse
import csv
import os
import threading
import time

import numpy as np

import rollerrig as rr

HERE = os.path.dirname(os.path.abspath(__file__))
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


def products(d, nx, k=8):
    """Median FFT products (normal, tangential) and Newton steps of k cases."""
    out = []
    for i in range(k):
        s = rr.exact_field(d["xi"][i], d["eta"][i], d["phi"][i], a=d["a"][i], b=d["b"][i],
                           N=d["N"][i], mu=d["mu"][i], G=d["G"][i], nu=d["nu"][i], nx=nx,
                           ny=nx)
        out.append(s.products + (s.newton_steps,))
    return np.median(np.array(out), axis=0)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cases", type=int, default=40)
    ap.add_argument("--sizes", default="11,27,45,61,101")
    ap.add_argument("--rounds", type=int, default=5)
    args = ap.parse_args()
    d = cases(args.cases)
    print("| elements across | grid | ms per case (1 thread) | products normal / tangential "
          "| Newton steps | CONTACT ms | ratio |")
    print("|---|---|---|---|---|---|---|")
    for nx in (int(s) for s in args.sizes.split(",")):
        sub = {k: v[: max(4, args.cases * 27 * 27 // (nx * nx))] for k, v in d.items()}
        run(sub, nx)                                   # warm up
        ms = best_ms(sub, nx, args.rounds)
        pn, pt, nw = products(d, nx)
        ref = CONTACT_MS.get(nx)
        ratio = f"{ref / ms:.1f}x faster" if ref else ""
        print(f"| {nx} | {nx + 4}x{nx + 4} | {ms:.2f} | {pn:.0f} / {pt:.0f} | {nw:.0f} "
              f"| {ref or ''} | {ratio} |")
    # two threads, each its own batch (and workspace), against one thread
    # doing both: all 300 cases at 27 across, three rounds
    nx = 27
    d = cases(300)
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
    print(f"\ntwo threads against one (600 cases at 27 across), three rounds: "
          f"{'; '.join(ratios)}")


if __name__ == "__main__":
    main()
