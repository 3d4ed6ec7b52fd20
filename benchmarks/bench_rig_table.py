"""The paper's scenario on the exact-theory table against FASTSIM (issue 14).

    python benchmarks/bench_rig_table.py [--repeats 5]

For each method: per creepage target the creepage held, the adhesion (the
mean force over the normal load once settled) and the peak force over mu N
(RigResult.summary), and the real-time factor of rig.run over the paper's
schedule at the 4 ms step (table built outside the timing; the best of
--repeats, the methods taking turns).
"""
import argparse

import rollerrig as rr

METHODS = [("fastsim", "FASTSIM 20x20 (default)"), ("exact_table", "exact-theory table"),
           ("polach", "Polach")]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeats", type=int, default=5)
    args = ap.parse_args()
    runs = {m: rr.simulate(method=m) for m, _ in METHODS}
    best = {m: float("inf") for m, _ in METHODS}
    for _ in range(args.repeats):
        for m, _ in METHODS:
            best[m] = min(best[m], rr.simulate(method=m).wall["run"])
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


if __name__ == "__main__":
    main()
