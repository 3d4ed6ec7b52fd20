#!/usr/bin/env python3
"""Speed benchmarks of rollerrig's contact functions, measured side by side.

    python benchmarks/bench_contact.py            # full run (about 1-2 minutes)
    python benchmarks/bench_contact.py --quick    # smoke run with small sizes

Measures on this machine, in one run, with time.perf_counter and the best of
several repeats (see benchmarks/README.md):

1. one thread: Hertz, linear theory, Polach and FASTSIM (10x10, 20x20, 30x30
   rect grid, blended 30x30, strips 30x30), each batched (one call on many
   random realistic cases) and one call per case (a Python loop of scalar
   calls), and the C kernel alone (benchmarks/bench_kernel.c, compiled here
   into a temporary directory, timed with clock_gettime over the same cases,
   and built a second time with the extension's own compiler flags); the
   batch overhead per case is the batched per-case time minus the C kernel's;
   the measurements of a row take turns, so a slow spell of the machine hits
   them alike;
2. the speed-up of two threads over one (concurrent.futures.ThreadPoolExecutor,
   the binding releases the GIL) for a large FASTSIM 20x20 and Polach batch
   split in two halves;
3. the pure-Python twin (tests/twin.py's fastsim, the tests' slow reference)
   against the C batch on the same FASTSIM 30x30 cases;
4. a published reference figure for context (CONTACT, not measured here).

Writes its Markdown report as the "contact" section of benchmarks/RESULTS.md
(full run), benchmarks/out/RESULTS-quick.md (--quick) or --out PATH, leaving
the other sections of that file (bench_rig_contact.py's) as they are, and
prints it.
Timing is reported, never asserted: the exit status is 0 whether or not a
goal is met.
"""
import argparse
import concurrent.futures
import datetime
import gc
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

from rollerrig.contact import creep as contact

from _bench_common import (ROOT, CProgram, CpuMonitor, command_text, conditions_lines,
                           extension_flags, fmt, interleaved, load_average, log, machine_info,
                           kernel_report_head, report_path, timed, verdict, write_section)

# Goals (a figure is compared with its goal in the report; nothing is asserted).
GOAL_FASTSIM30_US = 10.0        # FASTSIM 30x30, batched, one thread: <= 10 us per case
GOAL_RATE = 2e6                 # Polach and Hertz, batched, one thread: >= 2e6 cases/s
GOAL_OVERHEAD_US = 0.2          # batch overhead: <= 0.2 us per case
GOAL_THREADS = 1.8              # 2 threads >= 1.8x one

# CONTACT (E. Vollebregt) through its Python interface: 0.33 ms per FASTSIM
# case at 31x31 elements -- a published figure, not measured here.
CONTACT_FASTSIM31_US = 330.0

MU = 0.3
G = 8.2e10
NU = 0.28
E_STEEL = 2.1e11

SIZES = {
    # cheap: batch size for Hertz / linear / Polach; fastsim_work: FASTSIM
    # elements (cases x nx x ny) per batched call; loop: cases in the
    # one-call-per-case loop; threads_*: cases split over the threads.
    "full": dict(cheap=1_000_000, fastsim_work=36_000_000, loop=2000, repeats=5,
                 fastsim_repeats=4, threads_fastsim=200_000, threads_polach=4_000_000,
                 thread_repeats=5, twin_cases=20, twin_repeats=5, twin_tile=500),
    "quick": dict(cheap=50_000, fastsim_work=1_500_000, loop=100, repeats=2,
                  fastsim_repeats=2, threads_fastsim=10_000, threads_polach=200_000,
                  thread_repeats=2, twin_cases=4, twin_repeats=1, twin_tile=50),
}

# name, method, nx, ny, grid (one-thread section, rows in this order)
FASTSIM_ROWS = [
    ("FASTSIM 10x10", "fastsim", 10, 10, "rect"),
    ("FASTSIM 20x20", "fastsim", 20, 20, "rect"),
    ("FASTSIM 30x30", "fastsim", 30, 30, "rect"),
    ("FASTSIM blended 30x30", "fastsim_blended", 30, 30, "rect"),
    ("FASTSIM 30x30 strips", "fastsim", 30, 30, "strips"),
    ("FaStrip 30x30", "fastrip", 30, 30, "rect"),
]


# --------------------------------------------------------------------- cases

def creep_cases(rng, n):
    """Random realistic cases: a, b 2-10 mm, N 1-100 kN (log-uniform),
    creepages cx, cy up to 1e-2, spin up to 1 rad/m (a cphi up to 1e-2)."""
    return dict(
        cx=rng.uniform(-1e-2, 1e-2, n),
        cy=rng.uniform(-1e-2, 1e-2, n),
        cphi=rng.uniform(-1.0, 1.0, n),
        a=rng.uniform(2e-3, 10e-3, n),
        b=rng.uniform(2e-3, 10e-3, n),
        N=np.exp(rng.uniform(math.log(1e3), math.log(1e5), n)),
    )


def hertz_cases(rng, n):
    """Curvature sums A, B and loads N (1-100 kN) giving a = 2-10 mm and
    B/A between 1/3 and 3.  All lengths of a Hertz contact scale as
    (curvature)^(-1/3), so A, B follow from one untimed call at A = 1."""
    N = np.exp(rng.uniform(math.log(1e3), math.log(1e5), n))
    ratio = np.exp(rng.uniform(-math.log(3.0), math.log(3.0), n))
    a0 = contact.hertz(1.0, ratio, N, errors="raise").a
    A = (a0 / rng.uniform(2e-3, 10e-3, n)) ** 3
    return dict(A=A, B=ratio * A, N=N)


def slice_cases(cases, start, stop):
    return {k: v[start:stop] for k, v in cases.items()}


def grid_options(method, nx, ny, grid):
    """The grid options the method has (the registry refuses the others)."""
    return {k: v for k, v in dict(nx=nx, ny=ny, grid=grid).items()
            if k in contact.METHODS[method].options}


def call_creep(cases, method, nx=30, ny=30, grid="rect"):
    return contact.creep_forces(cases["cx"], cases["cy"], cases["cphi"], a=cases["a"],
                                b=cases["b"], N=cases["N"], mu=MU, G=G, nu=NU,
                                method=method, **grid_options(method, nx, ny, grid))


def call_hertz(cases):
    return contact.hertz(cases["A"], cases["B"], cases["N"], E=E_STEEL, nu=NU)


# -------------------------------------------------------------------- timing

def creep_loop(cases, k, method, nx, ny, grid):
    """A Python loop of k scalar creep_forces calls (inputs as Python floats)."""
    cols = [cases[name][:k].tolist() for name in ("cx", "cy", "cphi", "a", "b", "N")]
    rows = list(zip(*cols))
    f = contact.creep_forces
    opts = grid_options(method, nx, ny, grid)

    def run():
        for cx, cy, cphi, a, b, N in rows:
            f(cx, cy, cphi, a=a, b=b, N=N, mu=MU, G=G, nu=NU, method=method, **opts)
    return run


def hertz_loop(cases, k):
    rows = list(zip(*(cases[name][:k].tolist() for name in ("A", "B", "N"))))
    f = contact.hertz

    def run():
        for A, B, N in rows:
            f(A, B, N, E=E_STEEL, nu=NU)
    return run


# ------------------------------------------------------------- C kernel loop

class Kernel(CProgram):
    """benchmarks/bench_kernel.c compiled into a temporary directory, with
    the plain command of the README (`flags` None) or with other flags."""

    def __init__(self, tmpdir, flags=None, name="bench_kernel"):
        super().__init__(tmpdir, "bench_kernel.c", ["-O3", "-std=c99"], flags, name)

    def run(self, path, repeats=1, method=None, nx=0, ny=0, grid=None):
        """Time the kernel over the cases in `path` (write_cases); method None
        for Hertz.  Returns bench_kernel's JSON line as a dict."""
        args = ["hertz", path, str(repeats)] if method is None else \
            ["creep", path, str(repeats), method, str(nx), str(ny),
             str(contact.METHODS[method].options["grid"].choices.index(grid))
             if "grid" in contact.METHODS[method].options else "0"]
        proc = subprocess.run([self.exe] + args, capture_output=True, text=True)
        if proc.returncode != 0:
            raise RuntimeError(f"bench_kernel failed: {proc.stderr.strip()}")
        return json.loads(proc.stdout)


def write_cases(tmpdir, cases, hertz):
    """The case file of bench_kernel.c: the binding's argument order, constants
    as length-1 columns (broadcast, as the binding does)."""
    if hertz:
        cols = [cases["A"], cases["B"], cases["N"], E_STEEL, NU, E_STEEL, NU]
    else:
        cols = [cases["cx"], cases["cy"], cases["cphi"], cases["a"], cases["b"], cases["N"],
                MU, G, NU, 0.0, 1.0, 0.0]     # mu, G, nu, speed, friction A, B (Coulomb)
    n = cols[0].size
    path = os.path.join(tmpdir, "cases.bin")
    with open(path, "wb") as fh:
        np.array([n, len(cols)], dtype=np.int64).tofile(fh)
        for col in cols:
            col = np.ascontiguousarray(np.atleast_1d(np.asarray(col, dtype=np.float64)))
            np.array([col.size], dtype=np.int64).tofile(fh)
            col.tofile(fh)
    return path


def checksum(arrays, status):
    ok = status >= 0
    return float(sum(np.sum(a[ok]) for a in arrays))


# ------------------------------------------------------------------ sections

def one_thread(rng, sz, kernel, kernel_ext):
    rows = []
    cheap = creep_cases(rng, sz["cheap"])
    hcases = hertz_cases(rng, sz["cheap"])
    specs = [("Hertz", "hertz", 0, 0, "")] \
        + [("Linear theory", "linear", 30, 30, "rect"), ("Polach", "polach", 30, 30, "rect"),
           ("Exact-theory table", "exact_table", 30, 30, "rect")] \
        + FASTSIM_ROWS
    for name, method, nx, ny, grid in specs:
        fast = method.startswith("fastsim") or method == "fastrip"    # grid methods
        if fast:
            n = max(1000, int(sz["fastsim_work"] // (nx * ny)))
            cases = creep_cases(rng, n)
            repeats = sz["fastsim_repeats"]
        else:
            n = sz["cheap"]
            cases = hcases if method == "hertz" else cheap
            repeats = sz["repeats"]
        loop_n = min(sz["loop"], n)
        log(f"  {name}: {n} cases batched, {loop_n} in a loop ...")
        if method == "hertz":
            call_hertz(slice_cases(cases, 0, 100))              # warm-up
            res = call_hertz(cases)
            outs, status = (res.a, res.b, res.p0, res.delta), res.status
            batch = timed(lambda: call_hertz(cases))
            loop = hertz_loop(cases, loop_n)
            kmethod = None
        else:
            call_creep(slice_cases(cases, 0, 100), method, nx, ny, grid)
            res = call_creep(cases, method, nx, ny, grid)
            outs, status = (res.fx, res.fy, res.mz), res.status
            batch = timed(lambda: call_creep(cases, method, nx, ny, grid))
            loop = creep_loop(cases, loop_n, method, nx, ny, grid)
            kmethod = method
        fns = [batch, timed(loop)]
        kernels = [(key, kern) for key, kern in (("kernel_us", kernel),
                                                  ("kernel_ext_us", kernel_ext)) if kern.ok]
        last = {}
        if kernels:
            path = write_cases(kernel.tmpdir, cases, method == "hertz")
            for key, kern in kernels:
                def run_kernel(key=key, kern=kern):
                    last[key] = kern.run(path, 1, kmethod, nx, ny, grid)
                    return last[key]["best_s"]
                fns.append(run_kernel)
        times = interleaved(fns, repeats)
        row = dict(name=name, method=method, nx=nx, ny=ny, grid=grid, n=n, loop_n=loop_n,
                   repeats=repeats, batch_us=times[0] / n * 1e6,
                   loop_us=times[1] / loop_n * 1e6, not_ok=int(np.count_nonzero(status)),
                   kernel_us=None, kernel_ext_us=None, agree=None)
        ref = checksum(outs, status)
        for (key, _), t in zip(kernels, times[2:]):
            row[key] = t / n * 1e6
            k = last[key]
            agree = abs(k["checksum"] - ref) <= 1e-9 * max(1.0, abs(ref)) \
                and k["bad"] == int(np.count_nonzero(status < 0))
            row["agree"] = agree if row["agree"] is None else row["agree"] and agree
        rows.append(row)
    return rows


def threads(rng, sz):
    results = []
    for name, method, nx, n in (("FASTSIM 20x20", "fastsim", 20, sz["threads_fastsim"]),
                                ("Polach", "polach", 30, sz["threads_polach"])):
        log(f"  {name}: {n} cases in two halves, 1 and 2 threads ...")
        cases = creep_cases(rng, n)
        halves = [slice_cases(cases, 0, n // 2), slice_cases(cases, n // 2, n)]

        def work(part, method=method, nx=nx):
            return call_creep(part, method, nx, nx, "rect")

        with concurrent.futures.ThreadPoolExecutor(1) as pool1, \
                concurrent.futures.ThreadPoolExecutor(2) as pool2:
            for pool in (pool1, pool2):                         # warm-up: start the workers
                list(pool.map(work, [slice_cases(h, 0, 100) for h in halves]))
            best = {1: math.inf, 2: math.inf}
            cpu = {1: 0.0, 2: 0.0}
            gc.disable()
            try:
                for _ in range(sz["thread_repeats"]):        # interleaved: same conditions
                    for workers, pool in ((1, pool1), (2, pool2)):
                        c0 = time.process_time()
                        t0 = time.perf_counter()
                        list(pool.map(work, halves))
                        t = time.perf_counter() - t0
                        if t < best[workers]:
                            best[workers] = t
                            cpu[workers] = (time.process_time() - c0) / t
            finally:
                gc.enable()
        results.append(dict(name=name, n=n, t1=best[1], t2=best[2],
                            speedup=best[1] / best[2], cpu2=cpu[2],
                            repeats=sz["thread_repeats"]))
    return results


def twin_section(rng, sz):
    """The pure-Python twin (tests/twin.py, the tests' slow reference) against
    the C batch on the same FASTSIM 30x30 cases, rect grid."""
    sys.path.insert(0, os.path.join(ROOT, "tests"))
    import twin

    k = sz["twin_cases"]
    cases = creep_cases(rng, k)
    per_case = [dict(cx=float(cases["cx"][i]), cy=float(cases["cy"][i]),
                     cphi=float(cases["cphi"][i]), a=float(cases["a"][i]),
                     b=float(cases["b"][i]), N=float(cases["N"][i]), mu=MU, G=G, nu=NU,
                     nx=30, ny=30, bound="parabolic", grid="rect", variant="fastsim")
                for i in range(k)]
    log(f"  twin: {k} cases, grid='rect' ...")
    twin_out = [twin.fastsim(**kw) for kw in per_case]         # also the warm-up
    c_out = call_creep(cases, "fastsim", 30, 30, "rect")
    tiled = {name: np.tile(v, sz["twin_tile"]) for name, v in cases.items()}

    def c_small():                    # one call on the few cases: best of 20
        return min(timed(lambda: call_creep(cases, "fastsim", 30, 30, "rect"))()
                   for _ in range(20))
    t_twin, t_c, t_c_small = interleaved(
        [timed(lambda: [twin.fastsim(**kw) for kw in per_case]),
         timed(lambda: call_creep(tiled, "fastsim", 30, 30, "rect")), c_small],
        sz["twin_repeats"])
    scale = MU * cases["N"]
    diff = max(math.hypot(tw[0] - fx, tw[1] - fy) / s
               for tw, fx, fy, s in zip(twin_out, c_out.fx, c_out.fy, scale))
    return dict(cases=k, twin_us=t_twin / k * 1e6, c_us=t_c / (k * sz["twin_tile"]) * 1e6,
                c_small_us=t_c_small / k * 1e6, tile=sz["twin_tile"],
                repeats=sz["twin_repeats"], max_diff=diff)


# -------------------------------------------------------------------- report

def twin_table(L, tw):
    L.append(f"tests/twin.py's fastsim against creep_forces(method=\"fastsim\") at 30x30, "
             f"parabolic bound, rect grid, on the same {tw['cases']} cases. C batched: one "
             f"call on the {tw['cases']} cases tiled {tw['tile']} times.")
    L.append("")
    L.append("| implementation | us/case | ratio twin / C |")
    L.append("| --- | ---: | ---: |")
    L.append(f"| twin (Python loop, best of {tw['repeats']}) | {fmt(tw['twin_us'])} | |")
    L.append(f"| C batched ({tw['cases']} x {tw['tile']} cases) | {fmt(tw['c_us'])} | "
             f"{tw['twin_us'] / tw['c_us']:.0f}x |")
    L.append(f"| C, one call on the {tw['cases']} cases only | {fmt(tw['c_small_us'])} | "
             f"{tw['twin_us'] / tw['c_small_us']:.0f}x |")
    L.append("")
    L.append(f"Largest difference twin - C on these cases: |dF| = {fmt(tw['max_diff'])} "
             "mu N (tests/test_twin.py holds it within 1e-12 mu N).")
    L.append("")


def report(args, info, load0, load1, date, rows, thr, tw, kernel, kernel_ext, mon, elapsed):
    by = {r["name"]: r for r in rows}
    L = kernel_report_head("rollerrig speed benchmarks", args, info, date, elapsed, kernel,
                           kernel_ext)
    L += conditions_lines(load0, load1, mon)
    L.append("- every figure is the best of several repeats (time.perf_counter; the C kernel "
             "with clock_gettime), all measured side by side in this one run; one thread "
             "unless stated.")
    L.append("")

    # goals first, so that they are seen
    goals = []
    f30 = by.get("FASTSIM 30x30")
    goals.append(("FASTSIM 30x30 (rect), batched", f"{fmt(f30['batch_us'])} us/case",
                  f"<= {GOAL_FASTSIM30_US:g} us/case", f30["batch_us"] <= GOAL_FASTSIM30_US))
    for name in ("Polach", "Hertz"):
        rate = 1e6 / by[name]["batch_us"]
        goals.append((f"{name}, batched", f"{fmt(rate)} cases/s", f">= {GOAL_RATE:.0e} cases/s",
                      rate >= GOAL_RATE))
    for name in ("Linear theory", "Polach", "Hertz"):
        r = by[name]
        if r["kernel_us"] is None:
            goals.append((f"batch overhead, {name}", "not measured (no C kernel)",
                          f"<= {GOAL_OVERHEAD_US} us/case", None))
        else:
            ov = r["batch_us"] - r["kernel_us"]
            goals.append((f"batch overhead, {name}", f"{fmt(ov)} us/case",
                          f"<= {GOAL_OVERHEAD_US} us/case", ov <= GOAL_OVERHEAD_US))
    for t in thr:
        goals.append((f"2 threads over 1, {t['name']}", f"{t['speedup']:.2f}x",
                      f">= {GOAL_THREADS}x", t["speedup"] >= GOAL_THREADS))
    L.append("## Goals")
    L.append("")
    L.append("| goal | measured | target | result |")
    L.append("| --- | --- | --- | --- |")
    for g in goals:
        L.append(f"| {g[0]} | {g[1]} | {g[2]} | {verdict(g[3])} |")
    L.append("")
    if f30["kernel_us"] is not None and f30["kernel_ext_us"] is not None:
        L.append(f"FASTSIM 30x30, the C kernel alone: {fmt(f30['kernel_us'])} us/case built with "
                 f"the plain command, {fmt(f30['kernel_ext_us'])} us/case with the extension's "
                 "flags (see the batch overhead below).")
        L.append("")

    L.append("## One thread: batched, one call per case, C kernel")
    L.append("")
    L.append("Batched: one call on n random cases (a, b 2-10 mm, N 1-100 kN, mu 0.3, "
             "|cx|, |cy| <= 1e-2, |cphi| <= 1 rad/m; Hertz: A, B giving a = 2-10 mm, "
             "B/A 1/3-3). One call per case: a Python loop of scalar calls on the first "
             "cases. C kernel: benchmarks/bench_kernel.c looping over the same n cases as "
             "the binding's inner loop does, built with the plain command; batch overhead = "
             "batched - C kernel, per case (the goal's definition). The C kernel built with "
             "the extension's own flags (Python's CFLAGS, which include -fwrapv, and -fPIC) "
             "separates the cost of the Python call from that of different code generation: "
             "Python overhead = batched - that kernel. "
             "FASTSIM: parabolic bound, Coulomb friction.")
    L.append("")
    L.append("| method | grid | n batched | batched us/case | cases/s batched | "
             "one call per case us | C kernel us/case | batch overhead us/case | "
             "C kernel, extension's flags us/case | Python overhead us/case | "
             "status != 0 | C = Python |")
    L.append("| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |")
    for r in rows:
        grid = "-" if not r["method"].startswith("fastsim") else f"{r['nx']}x{r['ny']} {r['grid']}"
        ov = None if r["kernel_us"] is None else r["batch_us"] - r["kernel_us"]
        ov_ext = None if r["kernel_ext_us"] is None else r["batch_us"] - r["kernel_ext_us"]
        agree = "n/a" if r["agree"] is None else ("yes" if r["agree"] else "**no**")
        L.append(f"| {r['name']} | {grid} | {r['n']} | {fmt(r['batch_us'])} | "
                 f"{fmt(1e6 / r['batch_us'])} | {fmt(r['loop_us'])} (n={r['loop_n']}) | "
                 f"{fmt(r['kernel_us'])} | {fmt(ov)} | {fmt(r['kernel_ext_us'])} | "
                 f"{fmt(ov_ext)} | {r['not_ok']} | {agree} |")
    L.append("")
    L.append("The batch overhead goal is about the cheap methods (Hertz, linear, Polach), "
             "where the Python call's fixed and per-element costs would show; for FASTSIM the "
             "difference between the two kernel builds is code generation, not Python.")
    L.append("")
    L.append(f"Repeats: {rows[0]['repeats']} (Hertz, linear, Polach), "
             f"{rows[-1]['repeats']} (FASTSIM). \"C = Python\": the kernel's checksum of the "
             "outputs equals the binding's (same cases, same results).")
    if not kernel.ok:
        L.append("")
        L.append(f"C kernel not built: {kernel.error.splitlines()[0] if kernel.error else ''}")
    L.append("")

    L.append("## Two threads over one")
    L.append("")
    L.append("One batch split in two halves, both submitted to a "
             "concurrent.futures.ThreadPoolExecutor with 1 worker, then with 2 workers "
             "(runs interleaved). CPU/wall: process CPU time over wall time of the best "
             "2-thread run (2.0 = both cores busy all along).")
    L.append("")
    L.append("| batch | n | 1 thread s | 2 threads s | speed-up | CPU/wall (2 threads) |")
    L.append("| --- | ---: | ---: | ---: | ---: | ---: |")
    for t in thr:
        L.append(f"| {t['name']} | {t['n']} | {fmt(t['t1'])} | {fmt(t['t2'])} | "
                 f"{t['speedup']:.2f}x | {t['cpu2']:.2f} |")
    L.append("")

    L.append("## Pure-Python twin")
    L.append("")
    twin_table(L, tw)

    L.append("## Reference (not measured here)")
    L.append("")
    L.append("| code | grid | us per FASTSIM case | source |")
    L.append("| --- | --- | ---: | --- |")
    L.append(f"| CONTACT through its Python interface | 31x31 | {CONTACT_FASTSIM31_US:.0f} | "
             "published figure |")
    L.append(f"| rollerrig, batched (this run) | 30x30 rect | {fmt(f30['batch_us'])} | measured |")
    L.append(f"| rollerrig, one call per case (this run) | 30x30 rect | {fmt(f30['loop_us'])} | "
             "measured |")
    L.append("")
    L.append(f"Ratio published CONTACT / rollerrig batched: "
             f"{CONTACT_FASTSIM31_US / f30['batch_us']:.0f}x (different machine and a "
             "31x31 grid: context only).")
    L.append("")
    return "\n".join(L)


def accuracy_section():
    """Accuracy of every method on CONTACT's 3220 exact cases (not a speed
    figure, but kept beside them as the issue asks): tests/reference_cases.py."""
    sys.path.insert(0, os.path.join(ROOT, "tests"))
    from reference_cases import score_methods

    lines = ["", "## Accuracy on the 3220 exact cases", "",
             "|dF| / (mu N), dF the vector (dFx, dFy) against CONTACT's exact theory "
             "(contact_test_table_mx11.csv: 11x11 grid, itself a few % off the "
             "continuum). FASTSIM variants at 30x30, parabolic bound; "
             "modified_fastsim with its defaults k0 = 0.54, alpha_inf = 0.02, "
             "beta = 0.62 (a contaminated-rail model, so far from the clean exact "
             "theory by design).", "",
             "| method | grid | median | p95 | max |", "| --- | --- | ---: | ---: | ---: |"]
    for grid in ("rect", "strips"):
        methods = ("linear", "fastsim", "fastsim_blended", "modified_fastsim", "polach") \
            if grid == "rect" else ("fastsim", "fastsim_blended")
        for method, sc in score_methods(methods, grid=grid).items():
            g = grid if "fastsim" in method else "-"
            lines.append(f"| {method} | {g} | {sc['median']:.4f} | {sc['p95']:.4f} | "
                         f"{sc['max']:.4f} |")
    lines += ["", "Target for Kalker's FASTSIM at about 30x30 (an independent "
              "implementation): median 0.028, p95 0.11, max 0.18, each within 0.01 "
              "(tests/test_creep_reference.py).", ""]
    return "\n".join(lines)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="small sizes: a smoke run")
    parser.add_argument("--out", help="report path (default benchmarks/RESULTS.md, or "
                        "benchmarks/out/RESULTS-quick.md with --quick)")
    parser.add_argument("--seed", type=int, default=20240601)
    args = parser.parse_args(argv)
    args.command = command_text(argv)
    out = report_path(args)
    sz = SIZES["quick" if args.quick else "full"]
    rng = np.random.default_rng(args.seed)
    date = datetime.datetime.now().astimezone().isoformat(timespec="seconds")
    load0 = load_average()
    t_start = time.perf_counter()

    with tempfile.TemporaryDirectory(prefix="rollerrig-bench-") as tmp:
        log("compiling the C kernel benchmark ...")
        mon = CpuMonitor()
        kernel = Kernel(tmp)
        kernel_ext = Kernel(tmp, extension_flags(), "bench_kernel_ext")
        if not kernel.ok:
            log(f"  C kernel not built ({kernel.error}); batch overhead not measured")
        info = machine_info(kernel.cc_version)
        log("one thread ...")
        rows = mon.section("one thread", one_thread, rng, sz, kernel, kernel_ext)
        log("threads ...")
        thr = mon.section("threads", threads, rng, sz)
        log("pure-Python twin ...")
        tw = mon.section("twin", twin_section, rng, sz)

    load1 = load_average()
    text = report(args, info, load0, load1, date, rows, thr, tw, kernel, kernel_ext, mon,
                  time.perf_counter() - t_start)
    text += accuracy_section()
    write_section(out, "contact", text)
    print(text)
    log(f"written {os.path.relpath(out, os.getcwd())}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
