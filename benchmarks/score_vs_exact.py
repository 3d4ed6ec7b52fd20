"""Every fast creep-force method against the library's own exact theory.

    python benchmarks/score_vs_exact.py [--n 3000] [--seed 20261202] [--nx 27]

The cases (seeded, reproducible): a/b log-uniform in [0.1, 10]; c = sqrt(ab)
uniform 3-9 mm; N uniform 5-120 kN; mu uniform 0.1-0.5; G = 82 GPa,
nu = 0.28; the creepage |(xi, eta)| = m xi_ch, m uniform in [0, 3], in a
uniform direction, xi_ch = mu N / (G c^2 C11); the spin phi = psi mu N /
(G c^3 C23), psi uniform in [-1, 1], in two thirds of the cases (0 in the
rest); the draws in that order from numpy.random.default_rng(seed), as the
300 CONTACT cases of tests/data/contact_exact_cases.csv were drawn.

The reference: method "exact" extrapolated to the continuum from nx and 2 nx
elements across the ellipse (exact_richardson, first order).  Each method
is scored as rollerrig.reference.score does (|(dFx, dFy)|/(mu N), |dMz|/(mu N
c)), split by spin and a/b class; the table is printed in Markdown.
"""
import argparse
import time

import numpy as np

import rollerrig as rr
from rollerrig import reference as ref

FAST = [("linear", {}), ("fastsim", dict(nx=30, ny=30)),
        ("fastsim_blended", dict(nx=30, ny=30)), ("modified_fastsim", dict(nx=30, ny=30)),
        ("polach", {})]


def random_cases(n, seed):
    rng = np.random.default_rng(seed)
    aob = np.exp(rng.uniform(np.log(0.1), np.log(10.0), n))
    c = rng.uniform(3e-3, 9e-3, n)
    N = rng.uniform(5e3, 120e3, n)
    mu = rng.uniform(0.1, 0.5, n)
    m = rng.uniform(0.0, 3.0, n)
    theta = rng.uniform(0.0, 2 * np.pi, n)
    psi = rng.uniform(-1.0, 1.0, n)
    psi[rng.permutation(n) >= (2 * n) // 3] = 0.0
    G, nu = 8.2e10, 0.28
    k = rr.kalker_coefficients(aob, nu)
    xi_ch = mu * N / (G * c * c * k.c11)
    a, b = c * np.sqrt(aob), c / np.sqrt(aob)
    return dict(aob=aob, a=a, b=b, c=c, N=N, mu=mu, G=G, nu=nu,
                cx=m * xi_ch * np.cos(theta), cy=m * xi_ch * np.sin(theta),
                cphi=psi * mu * N / (G * c ** 3 * k.c23), psi=psi, m=m)


def as_cases(d, F):
    """An ExactCases of the draws with the reference forces F (normalised)."""
    edges = np.array([0.1, 0.3, 0.7, 1.4, 3.3, 10.01])
    labels = np.array([0.2, 0.5, 1.0, 2.0, 5.0])
    aob_class = labels[np.clip(np.searchsorted(edges, d["aob"]) - 1, 0, 4)]
    spin_class = np.where(d["psi"] == 0, 0.0, np.where(np.abs(d["psi"]) <= 0.5, 0.5, 1.0))
    n = d["aob"].size
    return ref.ExactCases(cx=d["cx"], cy=d["cy"], cphi=d["cphi"], a=d["a"], b=d["b"], cp=d["c"],
                          Fx=F[0], Fy=F[1], Mz=F[2], pct_slip=np.full(n, np.nan),
                          a_over_b=aob_class, spin=spin_class,
                          angle=np.arctan2(d["cy"], d["cx"]), magnitude=d["m"], N=d["N"],
                          mu=d["mu"], G=d["G"], nu=d["nu"], source="own exact (Richardson)")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=3000)
    ap.add_argument("--seed", type=int, default=20261202)
    ap.add_argument("--nx", type=int, default=27)
    args = ap.parse_args()
    d = random_cases(args.n, args.seed)
    t = time.perf_counter()
    est, err = rr.exact_richardson(d["cx"], d["cy"], d["cphi"], a=d["a"], b=d["b"], N=d["N"],
                                   mu=d["mu"], G=d["G"], nu=d["nu"], nx=args.nx)
    dt = time.perf_counter() - t
    muN = d["mu"] * d["N"]
    F = (est.fx / muN, est.fy / muN, est.mz / (muN * d["c"]))
    rich = np.hypot(err.fx, err.fy) / muN
    print(f"{args.n} cases, seed {args.seed}; reference: exact, Richardson {args.nx}/"
          f"{2 * args.nx} across ({dt:.0f} s); its estimated error |dF|/(mu N): median "
          f"{np.median(rich):.1e}, p95 {np.percentile(rich, 95):.1e}\n")
    cases = as_cases(d, F)
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
