"""A creep-force sweep on the rig's wheel: FASTSIM 20 x 20 over the
longitudinal creepage, the friction coefficient and the wheel load.

The contact is the default rig's (rollerrig/data/rig_default.toml): the
r = 92 mm conical wheel on the R = 160 mm roller with its 60 mm crown, the
Hertz ellipse recomputed for every load, Polach's falling friction
(A = 0.4, B = 0.6 s/m) at 5 m/s, 521.6 N per wheel nominally.  One call of
rr.sweep evaluates the 3-D grid on all cores and returns it as an
xarray.Dataset, from which the curves are selected by value.

    pip install ".[plot,sweep]" && python examples/sweep_creep.py [output folder]
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollerrig as rr  # noqa: E402
from rollerrig.analysis.sweep import sweep  # noqa: E402

R_WHEEL, R_ROLLER, R_CROWN = 0.092, 0.160, 0.060
A = 0.5 * (1.0 / R_WHEEL + 1.0 / R_ROLLER)     # curvature sums [1/m]: rolling direction
B = 0.5 / R_CROWN                              # lateral (the cone is straight)
N_NOMINAL = 521.6                              # (preload + weight) / 2 [N]
FALLING = rr.FallingFriction(A=0.4, B=0.6)


def wheel_on_roller(cx, N, mu):
    """Creep forces of the rig's wheel at load N: Hertz, then FASTSIM 20 x 20."""
    h = rr.hertz(A, B, N)
    f = rr.creep_forces(cx, a=h.a, b=h.b, N=N, mu=mu, method="fastsim", nx=20, ny=20,
                        speed=5.0, friction=FALLING)
    return {"fx": f.fx, "a": h.a, "b": h.b, "status": np.maximum(f.status, h.status)}


def main(outdir="."):
    os.makedirs(outdir, exist_ok=True)
    grid = {"cx": np.geomspace(1e-5, 0.05, 401), "mu": np.array([0.1, 0.2, 0.3, 0.4, 0.5]),
            "N": np.array([150.0, 300.0, N_NOMINAL, 1000.0])}
    ds = sweep(wheel_on_roller, grid, progress=False)
    assert (ds.status == 0).all()
    cx = ds.cx * 100.0                            # per cent

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.4), sharex=True)
    colors = plt.cm.viridis(np.linspace(0.0, 0.85, 5))
    for color, mu in zip(colors, ds.mu.values):
        f = ds.fx.sel(mu=mu, N=N_NOMINAL)
        ax1.plot(cx, -f / N_NOMINAL, color=color, label=f"mu0 = {mu:.1f}")
    ax1.set(xscale="log", xlim=(1e-3, 5), ylim=(0, 0.55), xlabel="longitudinal creepage cx [%]",
            ylabel="adhesion -fx / N",
            title=f"static friction coefficient, N = {N_NOMINAL:.0f} N")
    ax1.legend(loc="upper left", fontsize=8, ncol=2)

    colors = plt.cm.plasma(np.linspace(0.0, 0.8, 4))
    for color, N in zip(colors, ds.N.values):
        f = ds.fx.sel(mu=0.4, N=N)
        a, b = float(ds.a.sel(N=N, mu=0.4)[0]), float(ds.b.sel(N=N, mu=0.4)[0])
        ax2.plot(cx, -f / (0.4 * N), color=color,
                 label=f"N = {N:.0f} N (a = {a * 1e3:.2f}, b = {b * 1e3:.2f} mm)")
    ax2.set(ylim=(0, 1.25), xlabel="longitudinal creepage cx [%]", ylabel="-fx / (mu0 N)",
            title="wheel load, mu0 = 0.4")
    ax2.legend(loc="upper left", fontsize=8)
    for ax in (ax1, ax2):
        ax.grid(alpha=0.3)
    fig.suptitle("FASTSIM 20 x 20, Polach falling friction (A = 0.4, B = 0.6 s/m) at 5 m/s: "
                 f"one rr.sweep over {ds.fx.size} cases", fontsize=10)
    fig.tight_layout()
    path = os.path.join(outdir, "sweep.png")
    fig.savefig(path, dpi=110)
    print("wrote", path)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
