"""Creep-force curves of every method against CONTACT's exact theory, and the
FASTSIM traction field of one case.

The case is CONTACT's creep-curve example (Polach's Eurosprinter wheel,
Vollebregt 2014): a = 6.304 mm, b = 12.61 mm, N = 106.7 kN, G = 82 GPa,
nu = 0.28, mu = 0.33, 10 m/s.  The exact-theory points come from
tests/data/creep_curves_exact_vs_fastsim.csv (CONTACT's reference output).

    pip install ".[plot]" && python examples/creep_curves.py [output folder]
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollerrig as rr  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "..", "tests", "data", "creep_curves_exact_vs_fastsim.csv")
CASE = dict(a=6.304e-3, b=12.61e-3, N=106.7e3, G=8.2e10, nu=0.28, speed=10.0)


def reference_series():
    """{series number: (cx, fx / (mu N))} from CONTACT's reference output."""
    with open(DATA) as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))][1:]
    out = {}
    for r in rows:
        out.setdefault(int(r[1]), []).append((float(r[3]), float(r[6])))
    return {k: np.array(v).T for k, v in out.items()}


def main(outdir="."):
    os.makedirs(outdir, exist_ok=True)
    ref = reference_series()
    cx = np.geomspace(1e-5, 0.25, 400)
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))

    mu = 0.33
    ax1.plot(ref[1][0], -ref[1][1], "ko", ms=4, label="exact theory (CONTACT)")
    for method, style in (("linear", ":"), ("fastsim", "-"), ("fastsim_blended", "--"),
                          ("polach", "-.")):
        f = rr.creep_forces(cx, method=method, mu=mu, **CASE)
        ax1.plot(cx, -f.fx / (mu * CASE["N"]), style, label=method)
    ax1.set(xscale="log", xlim=(1e-4, 0.25), ylim=(0, 1.15), xlabel="longitudinal creepage cx",
            ylabel="-fx / (mu N)", title="Coulomb friction, mu = 0.33")
    ax1.legend(loc="upper left", fontsize=8)

    # falling friction: CONTACT's series 4 parameters (static mu 0.36)
    mu0 = 0.36
    falling = rr.FallingFriction(A=0.1368 / mu0, B=np.log(2) / 0.99)
    ax2.plot(ref[4][0], -ref[4][1], "ks", ms=4, label="modified FASTSIM (CONTACT)")
    for method, style in (("modified_fastsim", "-"), ("fastsim", "--"), ("polach", "-.")):
        f = rr.creep_forces(cx, method=method, mu=mu0, friction=falling, **CASE)
        ax2.plot(cx, -f.fx / (mu0 * CASE["N"]), style, label=method)
    ax2.set(xscale="log", xlim=(1e-4, 0.25), ylim=(0, 1.15), xlabel="longitudinal creepage cx",
            ylabel="-fx / (mu0 N)",
            title="falling friction mu(w) = mu0[(1-A)exp(-Bw)+A]")
    ax2.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    path = os.path.join(outdir, "creep_curves.png")
    fig.savefig(path, dpi=110)
    print("wrote", path)

    # traction field of a case with creepage and spin
    t = rr.fastsim_field(1.0e-3, 0.5e-3, 0.3, mu=mu, nx=24, ny=24, **CASE)
    fig, ax = plt.subplots(figsize=(5.5, 5))
    inside = t.pn > 0
    ax.scatter(t.x[inside] * 1e3, t.y[inside] * 1e3, c=np.where(t.slip[inside], "tab:red",
               "tab:blue"), s=40, alpha=0.35)
    ax.quiver(t.x[inside] * 1e3, t.y[inside] * 1e3, t.px[inside], t.py[inside], width=0.003)
    ax.set(aspect="equal", xlabel="x, rolling direction [mm]", ylabel="y [mm]",
           title=f"FASTSIM tractions: adhesion (blue), slip (red)\n"
                 f"fx = {t.fx / 1e3:.1f} kN, fy = {t.fy / 1e3:.1f} kN, mz = {t.mz:.1f} N m")
    fig.tight_layout()
    path = os.path.join(outdir, "traction_field.png")
    fig.savefig(path, dpi=110)
    print("wrote", path)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
