"""The paper's scenario on the exact-theory table against FASTSIM (issue 14).

    python benchmarks/bench_rig_table.py [--repeats 5] [--batch 200000]

For each method: per creepage target the creepage held, the adhesion (the
mean force over the normal load once settled) and the peak force over mu N
(RigResult.summary), and the real-time factor of rig.run over the paper's
schedule at the 4 ms step (table built outside the timing; the best of
--repeats, the methods taking turns).  Then the batch API's speed of
exact_table and Polach (rr.creep_forces on --batch random cases drawn as
tests/test_exact_table.py draws them: every a/b of the table, creepages from
none to far past saturation; best of --repeats, the two taking turns), and
the load average before and after, the machine's other work.
"""
import argparse
import os
import sys
import time

import rollerrig as rr

METHODS = [("fastsim", "FASTSIM 20x20 (default)"), ("exact_table", "exact-theory table"),
           ("polach", "Polach")]
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests"))
from test_exact_table import G, NU, random_inputs  # noqa: E402  (the test's random cases)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=5)
    ap.add_argument("--batch", type=int, default=200000)
    args = ap.parse_args()
    load0 = os.getloadavg()
    runs = {m: rr.simulate(method=m) for m, _ in METHODS}
    best = {m: float("inf") for m, _ in METHODS}
    for _ in range(args.repeats):
        for m, _ in METHODS:
            best[m] = min(best[m], rr.simulate(method=m).wall["run"])
    cases = dict(random_inputs(args.batch, 1), G=G, nu=NU)
    batch = {"exact_table": float("inf"), "polach": float("inf")}
    for m in batch:
        rr.creep_forces(**cases, method=m)          # warm-up
    for _ in range(args.repeats):
        for m in batch:
            t0 = time.perf_counter()
            rr.creep_forces(**cases, method=m)
            batch[m] = min(batch[m], time.perf_counter() - t0)
    load1 = os.getloadavg()
    print("| method | target | held | adhesion | peak F / (mu N) |")
    print("|---|---|---|---|---|")
    for m, name in METHODS:
        for row in runs[m].summary():
            print(f"| {name} | {row['target']:.3f} | {row['reached']:.5f} | "
                  f"{row['adhesion']:.5f} | {row['peak_force_over_muN']:.4f} |")
    print()
    ref = runs["fastsim"].summary()
    for m, name in METHODS[1:]:
        d = [abs(a["adhesion"] - b["adhesion"]) for a, b in zip(runs[m].summary(), ref)]
        print(f"- {name} against FASTSIM: held adhesion differs by at most {max(d):.2e}")
    print()
    print("| method | run time of the 20 s scenario [ms] | real-time factor |")
    print("|---|---|---|")
    for m, name in METHODS:
        dur = runs[m].duration
        print(f"| {name} | {best[m] * 1e3:.1f} | {dur / best[m]:.0f} |")
    print()
    for m, t in batch.items():
        print(f"- batch API, {m}: {t / args.batch * 1e6:.3f} us a case "
              f"({args.batch / t:.2e} cases/s; {args.batch} random cases)")
    print(f"- load average (1, 5, 15 min) before {load0[0]:.2f}, {load0[1]:.2f}, {load0[2]:.2f}; "
          f"after {load1[0]:.2f}, {load1[1]:.2f}, {load1[2]:.2f} ({os.cpu_count()} processors)")


if __name__ == "__main__":
    main()
