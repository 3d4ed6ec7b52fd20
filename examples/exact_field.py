"""One case of Kalker's exact theory with spin: pressure, tangential
traction and the adhesion/slip map (docs/exact_field.png); and the
non-Hertzian patch of the measured wheel on its roller at a lateral shift
of 3.5 mm, where it splits in two (docs/exact_nonhertz.png).

The case: a = 6 mm, b = 4 mm, N = 50 kN, G = 82 GPa, nu = 0.28, mu = 0.3,
creepages cx = 2e-4, spin 0.5 rad/m, 40 elements across each axis (the
grid adds 2 on each side).

    pip install ".[plot]" && python examples/exact_field.py [output folder]
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import rollerrig as rr  # noqa: E402
import rollerrig.plot as rp  # noqa: E402


def main(out="."):
    s = rr.exact_field(2e-4, 0.0, 0.5, a=6e-3, b=4e-3, N=5e4, mu=0.3, nx=40, ny=40)
    fig, axs = plt.subplots(1, 3, figsize=(16, 4.6))
    rp.traction_field(s, axs[0], quantity="pn", show_slip=False, arrows=False, colorbar=True,
                      title=False)
    axs[0].set_title(f"pressure, peak {s.pmax / 1e6:.0f} MPa", fontsize=9)
    rp.traction_field(s, axs[1], quantity="|p_t|", colorbar=True)
    rp.traction_field(s, axs[2], quantity="slip", arrows=False)
    fig.tight_layout()
    path = os.path.join(out, "exact_field.png")
    fig.savefig(path, dpi=100)
    print(path, s.fx, s.fy, s.mz)

    # the measured MiniProf wheel on its roller, the rig's wheel load
    # (CONTACT's testbank case: 61.2 kN, mu 0.52), braking creepage with spin
    r = rr.rig_exact(rr.RigGeometry.measured_pair(), 3.5e-3, mu=0.52, Fz=61163.05, cx=0.002,
                     cy=0.0, cphi=0.5, n=60)
    fig, axs = plt.subplots(1, 2, figsize=(11.5, 4.8))
    rp.traction_field(r.solution, axs[0], quantity="pn", show_slip=False, arrows=False,
                      colorbar=True, title=False)
    axs[0].set_title(f"measured wheel on its roller, y = 3.5 mm: pressure, "
                     f"{r.shape.regions} regions", fontsize=9)
    rp.traction_field(r.solution, axs[1], quantity="slip", arrows=False)
    fig.tight_layout()
    path = os.path.join(out, "exact_nonhertz.png")
    fig.savefig(path, dpi=100)
    print(path, r.solution.fx, r.solution.fy)


if __name__ == "__main__":
    main(*sys.argv[1:])
