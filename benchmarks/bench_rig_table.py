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
import time

import numpy as np

import rollerrig as rr

METHODS = [("fastsim", "FASTSIM 20x20 (default)"), ("exact_table", "exact-theory table"),
           ("polach", "Polach")]
G, NU = 8.2e10, 0.28


def random_inputs(n, seed):
    """tests/test_exact_table.py's random cases."""
    rng = np.random.default_rng(seed)
    aob = np.exp(rng.uniform(np.log(0.1), np.log(10.0), n))
    c = rng.uniform(3e-3, 9e-3, n)
    N = rng.uniform(5e3, 1e5, n)
    mu = rng.uniform(0.1, 0.5, n)
    s = mu * N / (G * c * c)
    mag = s * np.exp(rng.uniform(np.log(1e-4), np.log(1e3), (3, n)))
    mag *= rng.choice([-1.0, 0.0, 1.0, 1.0], (3, n))
    return dict(cx=mag[0] / 4.0, cy=mag[1] / 4.0, cphi=mag[2] / (4.0 * c), a=c * np.sqrt(aob),
                b=c / np.sqrt(aob), N=N, mu=mu, G=G, nu=NU)


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
    cases = random_inputs(args.batch, 1)
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
