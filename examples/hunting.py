"""The hunting bifurcation diagram of the scaled wheelset on a soft suspension,
on its rollers and on tangent track.

rr.hunting runs the rig in time (its integrator and controllers, the wheelset
free rolling) down a ramp of speeds from a 1 mm shift: at each speed 2 s of
settling, then the limit cycle's amplitude over 1 s; the linear critical
speed of rr.stability is marked beside it (docs/lateral_dynamics.md).  The
axle boxes are kx = ky = 20 kN/m (the default ones hold the wheelset so
stiffly that it does not hunt at any speed).

    python examples/hunting.py [output folder]

writes hunting.png (default: docs/).
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollerrig as rr  # noqa: E402

SOFT = {"suspension": {"kx_N_per_m": 2e4, "ky_N_per_m": 2e4}}
RAMP = np.arange(140.0, 58.0, -3.0)          # m/s, decreasing: from a growing cycle down
LINEAR = np.linspace(40.0, 160.0, 121)        # m/s, for the linear critical speed


def main(folder):
    fig, ax = plt.subplots(figsize=(7.5, 4.2), constrained_layout=True)
    for track, colour in ((False, "tab:blue"), (True, "tab:red")):
        where = "track" if track else "rollers"
        h = rr.hunting(RAMP, SOFT, track=track)
        vc = rr.stability(LINEAR, SOFT, track=track).critical_speed
        ok = np.asarray(h.sustained, dtype=bool)
        ax.plot(h.speeds, h.amplitude * 1e3, "-", lw=0.8, color=colour, alpha=0.5)
        ax.plot(h.speeds[ok], h.amplitude[ok] * 1e3, "o", ms=4, color=colour,
                label=f"{where}: sustained cycle (nonlinear critical speed "
                      f"{h.nonlinear_critical_speed:.0f} m/s)")
        ax.plot(h.speeds[~ok], h.amplitude[~ok] * 1e3, "o", ms=4, mfc="none", color=colour,
                label=f"{where}: still decaying over the 1 s measured")
        ax.axvline(vc, color=colour, ls=":", lw=1.2, label=f"{where}: linear critical speed "
                                                          f"{vc:.1f} m/s")
        print(f"{where:>8}: linear critical speed {vc:.2f} m/s, nonlinear "
              f"{h.nonlinear_critical_speed:.0f} m/s, amplitude at {h.speeds[0]:.0f} m/s "
              f"{h.amplitude[0] * 1e3:.2f} mm")
    ax.set_xlabel("speed [m/s]")
    ax.set_ylabel("hunting amplitude of the lateral shift y [mm]")
    ax.set_title("Hunting of the 1/5 wheelset, axle boxes kx = ky = 20 kN/m: on its rollers "
                 "and on track\n(rr.hunting: a ramp down in speed; rr.stability: the "
                 "linearisation)", fontsize=9.5)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, "hunting.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print("wrote", path)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..",
                                                            "docs"))
