"""Fit Polach's method and modified FASTSIM to a creep curve of the exact theory.

The "measurement" is CONTACT's exact theory with falling friction and an
interfacial layer (series 2 of tests/data/creep_curves_exact_vs_fastsim.csv:
Polach's Eurosprinter wheel, a = 6.304 mm, b = 12.61 mm, N = 106.7 kN,
G = 82 GPa, nu = 0.28, 10 m/s; friction mu0 = 0.33, A = 0.14/0.33,
B = ln 2 / 1.25 s/m).  Polach's five parameters are all fitted; modified
FASTSIM's k0, alpha_inf, beta are fitted with the friction law held at the
one CONTACT was given.  One speed only: A and B come from the falling branch
here, and are better pinned with curves at several speeds.

    pip install ".[test]" && python examples/fit_creep_curve.py [output folder]
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollerrig as rr  # noqa: E402
from rollerrig.analysis.fit import fit_modified_fastsim, fit_polach  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "tests", "data", "creep_curves_exact_vs_fastsim.csv")
CASE = dict(a=6.304e-3, b=12.61e-3, N=106.7e3, G=8.2e10, nu=0.28, speed=10.0)
MU = 0.33                                             # CONTACT's static coefficient
CONTACT_FRICTION = dict(mu0=MU, A=0.14 / MU, B=math.log(2.0) / 1.25)


def series2():
    """(cx, FX [N]) of series 2."""
    with open(DATA) as f:
        rows = [r for r in csv.DictReader(line for line in f if not line.startswith("#"))]
    rows = [r for r in rows if r["series"] == "2"]
    return (np.array([float(r["cksi"]) for r in rows]),
            np.array([float(r["FX"]) for r in rows]))


def report(title, res):
    mun = MU * CASE["N"]
    print(f"{title}: {res.message} ({res.nfev} evaluations)")
    for name, value in res.params.items():
        if name in res.fitted:
            note = "  (on its bound)" if name in res.at_bound else ""
            print(f"  {name:9s} = {value:8.4f} +- {res.stderr[name]:.4f}{note}")
        else:
            print(f"  {name:9s} = {value:8.4f}    held")
    print(f"  RMS residual {res.rms / mun:.4f} mu N, "
          f"max {np.max(np.abs(res.residuals)) / mun:.4f} mu N")


def main(outdir="."):
    os.makedirs(outdir, exist_ok=True)
    cx, fx = series2()
    pol = fit_polach(cx, fx, **CASE)
    mf = fit_modified_fastsim(cx, fx, x0=CONTACT_FRICTION, **CASE)
    report("Polach", pol)
    report("modified FASTSIM", mf)

    mun = MU * CASE["N"]
    grid = np.geomspace(5e-6, 0.3, 400)
    fr = CONTACT_FRICTION
    unfitted = rr.creep_forces(grid, method="polach", mu=fr["mu0"],
                               friction=rr.FallingFriction(fr["A"], fr["B"]), kA=1.0,
                               kS=0.4, **CASE).fx

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.3),
                                   gridspec_kw=dict(width_ratios=[1.35, 1]))
    ax1.plot(cx, -fx / mun, "ko", ms=4.5, label="exact theory (CONTACT), series 2", zorder=3)
    p = pol.params
    ax1.plot(grid, -pol.predict(grid) / mun, "-", color="tab:blue", lw=1.8,
             label=f"Polach fitted: mu0 {p['mu0']:.3f}, A {p['A']:.2f}, B {p['B']:.2f} s/m,"
                   f"\n    kA {p['kA']:.2f}, kS {p['kS']:.2f}")
    q = mf.params
    ax1.plot(grid, -mf.predict(grid) / mun, "--", color="tab:red", lw=1.8,
             label=f"modified FASTSIM fitted: k0 {q['k0']:.2f}, alpha_inf {q['alpha_inf']:.2f},"
                   f"\n    beta {q['beta']:.2f} (friction held)")
    ax1.plot(grid, -unfitted / mun, ":", color="0.45", lw=1.5,
             label="Polach unfitted: CONTACT's friction, kA 1, kS 0.4")
    ax1.set(xscale="log", xlim=(5e-6, 0.3), ylim=(0, 1.15), xlabel="longitudinal creepage cx",
            ylabel="-fx / (mu N),  mu = 0.33",
            title="Fits to the exact theory with falling friction, 10 m/s")
    ax1.legend(loc="upper left", fontsize=7.5, frameon=False)
    ax1.grid(alpha=0.3, which="both", lw=0.5)

    ax2.axhline(0.0, color="0.5", lw=0.8)
    ax2.plot(cx, pol.residuals / mun * 100, "o-", color="tab:blue", ms=4,
             label=f"Polach, RMS {pol.rms / mun * 100:.2f} %")
    ax2.plot(cx, mf.residuals / mun * 100, "s--", color="tab:red", ms=4,
             label=f"modified FASTSIM, RMS {mf.rms / mun * 100:.2f} %")
    ax2.set(xscale="log", xlim=(5e-6, 0.3), xlabel="longitudinal creepage cx",
            ylabel="fit - exact  [% of mu N]", title="Residuals")
    ax2.legend(loc="upper left", fontsize=8, frameon=False)
    ax2.grid(alpha=0.3, which="both", lw=0.5)
    fig.tight_layout()
    path = os.path.join(outdir, "fit_polach.png")
    fig.savefig(path, dpi=110)
    print("wrote", path)


if __name__ == "__main__":
    main(*sys.argv[1:2])
