"""Every fast creep-force method against the library's own exact theory.

    python benchmarks/score_vs_exact.py [--n 3000] [--seed 20261202] [--nx 27]

The cases and the reference: rollerrig.analysis.reference.own_exact_cases (seeded
random_cases, drawn as CONTACT's 300 cases were; method "exact"
extrapolated to the continuum from nx and 2 nx elements across).  Each method
is scored as rollerrig.analysis.reference.score does (|(dFx, dFy)|/(mu N), |dMz|/(mu N
c)), split by spin and a/b class; the table is printed in Markdown.
"""
import argparse
import time


from rollerrig.analysis import reference as ref

FAST = [("linear", {}), ("fastsim", dict(nx=30, ny=30)),
        ("fastsim_blended", dict(nx=30, ny=30)),
        ("fastsim_blended", dict(nx=30, ny=30, blend_rule="spin")),  # the former default
        ("modified_fastsim", dict(nx=30, ny=30)),
        ("polach", {}), ("fastrip", dict(nx=30, ny=30)), ("exact_table", {})]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=3000)
    ap.add_argument("--seed", type=int, default=20261202)
    ap.add_argument("--nx", type=int, default=27)
    args = ap.parse_args()
    t = time.perf_counter()
    cases = ref.own_exact_cases(args.n, args.seed, args.nx)
    dt = time.perf_counter() - t
    print(f"{args.n} cases, seed {args.seed}; reference: exact, Richardson {args.nx}/"
          f"{2 * args.nx} across ({dt:.0f} s)\n")
    results = [ref.score(m, cases=cases, **o) for m, o in FAST]
    # the exact solver itself on one grid, against its own continuum estimate
    for nx in (args.nx, 2 * args.nx):
        results.append(ref.score("exact", cases=cases, nx=nx, ny=nx))
    print("| method | median | p95 | max | Mz p95 |")
    print("|---|---|---|---|---|")
    for r in results:
        o, z = r.overall, r.mz_overall
        print(f"| {r.label} | {o['median']:.4f} | {o['p95']:.4f} | {o['max']:.4f} "
              f"| {z['p95']:.4f} |")
    print()
    print(ref.table(results))


if __name__ == "__main__":
    main()
