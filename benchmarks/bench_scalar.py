"""The cost of one scalar call above the kernel: rr.creep_forces and rr.hertz
on plain Python numbers.

A scalar call's overhead is its time minus the kernel's time for the same
case; the kernel's time is the per-case time of one batched call on 10^5
copies of the case (the batch path's own overhead is below 0.02 us a case:
the contact section of RESULTS.md).  Goal (issue 12): overhead <= 5 us.

With `--vs PYTHON` the same measurement runs under a second interpreter
too (for instance one whose rollerrig is the code before a change), the two
taking turns in each round, so both columns come from one run.  Every
measurement runs in a child process of its own interpreter.

    python benchmarks/bench_scalar.py [--vs /path/to/other/python] [--quick] [--out FILE]
"""
import argparse
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))

#: (label, function, keyword arguments): one realistic case each
CASES = (
    ("hertz", "hertz", dict(A=40.0, B=25.0, N=500.0)),
    ("linear theory", "creep_forces", dict(method="linear")),
    ("Polach", "creep_forces", dict(method="polach")),
    ("FASTSIM 20x20", "creep_forces", dict(method="fastsim", nx=20, ny=20)),
    ("FASTSIM 30x30 (default)", "creep_forces", {}),
)
CONTACT = dict(a=0.003, b=0.0025, N=520.0, mu=0.4)


def measure(calls, batch):
    """In the child: per case, the best scalar-call time and the batched
    per-case time [us], as JSON on stdout."""
    import gc
    import numpy as np
    import rollerrig as rr

    def best(fn, n, repeats=5):
        t = float("inf")
        for _ in range(repeats):
            t0 = time.perf_counter()
            fn(n)
            t = min(t, (time.perf_counter() - t0) / n)
        return t * 1e6

    out = {}
    gc.disable()
    for label, func, kw in CASES:
        f = getattr(rr, func)
        if func == "hertz":
            def one(n, f=f, kw=kw):
                for _ in range(n):
                    f(**kw)
            arrays = {k: np.full(batch, v) for k, v in kw.items()}

            def many(n, f=f, arrays=arrays):
                f(**arrays)
        else:
            def one(n, f=f, kw=kw):
                for _ in range(n):
                    f(0.001, 0.0, 0.0, **CONTACT, **kw)
            cx = np.full(batch, 0.001)

            def many(n, f=f, cx=cx, kw=kw):
                f(cx, 0.0, 0.0, **CONTACT, **kw)
        one(10)
        scalar = best(one, calls)
        kernel = best(lambda n: many(n), 1, repeats=3) / batch
        out[label] = dict(scalar=scalar, kernel=kernel)
    print(json.dumps(dict(version=getattr(rr, "__version__", "?"),
                          where=os.path.dirname(rr.__file__), times=out)))


def child(python, calls, batch):
    proc = subprocess.run([python, os.path.abspath(__file__), "--measure", str(calls),
                           str(batch)], capture_output=True, text=True, cwd="/",
                          check=True)
    return json.loads(proc.stdout)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--vs", help="a second interpreter, measured taking turns")
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--out")
    parser.add_argument("--measure", nargs=2, type=int, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.measure:
        return measure(*args.measure)

    sys.path.insert(0, HERE)
    import _bench_common as bc
    calls, batch, rounds = (200, 10_000, 2) if args.quick else (3000, 100_000, 5)
    pythons = [sys.executable] + ([args.vs] if args.vs else [])
    best = [None] * len(pythons)
    where = [None] * len(pythons)
    t0 = time.perf_counter()
    load0 = bc.load_average()
    for _ in range(rounds):
        for k, py in enumerate(pythons):
            r = child(py, calls, batch)
            where[k] = r["where"]
            if best[k] is None:
                best[k] = r["times"]
            else:
                for label, t in r["times"].items():
                    for key in t:
                        best[k][label][key] = min(best[k][label][key], t[key])
    elapsed = time.perf_counter() - t0
    names = ["this"] + (["vs"] if args.vs else [])
    L = ["# Scalar calls: overhead above the kernel", ""]
    if args.quick:
        L += ["**Quick smoke run (--quick): figures indicative only.**", ""]
    L += [f"- date: {time.strftime('%Y-%m-%dT%H:%M:%S%z')}",
          f"- command: `{bc.command_text(argv)}` (total {elapsed:.0f} s)",
          bc.machine_line(bc.machine_info(bc.compiler_version())),
          f"- load average at start {load0}, at end {bc.load_average()}",
          f"- packages: " + "; ".join(f"{n}: rollerrig from `{w}`" for n, w in zip(names, where)),
          f"- each figure: best of {rounds} rounds (the interpreters taking turns), each the "
          f"best of 5 loops of {calls} scalar calls; kernel = per-case time of one batched "
          f"call on {batch} copies of the case",
          ""]
    head = "| call | " + " | ".join(
        f"{n} scalar us | {n} kernel us | {n} overhead us" for n in names)
    if args.vs:
        head += " | overhead this / vs"
    head += " | goal overhead <= 5 us |"
    L += [head, "| --- " * (head.count("|") - 1) + "|"]
    for label, _, _ in CASES:
        cells = []
        over = []
        for k in range(len(pythons)):
            t = best[k][label]
            over.append(t["scalar"] - t["kernel"])
            cells += [bc.fmt(t["scalar"]), bc.fmt(t["kernel"]), bc.fmt(over[-1])]
        row = f"| {label} | " + " | ".join(cells)
        if args.vs:
            row += f" | {over[0] / over[1]:.3f}"
        row += f" | {bc.verdict(over[0] <= 5.0)} |"
        L.append(row)
    return bc.publish(args, "scalar", L)


if __name__ == "__main__":
    sys.exit(main())
