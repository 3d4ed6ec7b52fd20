"""A flange excursion on the measured pair: the rig braking at a creepage of
0.02 on the measured MiniProf wheels and rollers (scaled to the 1/5 rig)
while a lateral force pushes the wheelset to the left until its left wheel
runs on its flange root (rollerrig/data/rig_flange_excursion.toml).

    python examples/flange_excursion.py [output folder]

writes flange_excursion.png: the lateral force and the wheelset's shift;
each wheel's contact point on its profile (from the taping line, full size)
and contact angle; the normal loads and the creep forces, over time; prints
the largest contact angle and how far the contact point moved.
tests/test_rig_profiles_flange.py runs the same scenario.
"""
import os
import sys
import warnings

import numpy as np

import rollerrig as rr

SCENARIO = os.path.join(os.path.dirname(rr.__file__), "data", "rig_flange_excursion.toml")


def run():
    """(the run, the contact geometry along it: rollerrig.WheelsetContact)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rr.RollerRigWarning)   # the rollers' gauge-face folds
        res = rr.simulate(params=SCENARIO)
        table = rr.build_rig(SCENARIO)[2]
    return res, table.lookup(res.y)


def lateral_force(res):
    """The applied force at each record's sample (the disturbance section's,
    linear between its points, taken at the sample's start)."""
    D = res.params["disturbance"]
    return np.interp(res.time - res.record_dt, D["lateral_force_times_s"], D["lateral_force_N"])


def figure(res, geo, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    scale = res.params["wheelset"]["profile_scale"]
    fig, axes = plt.subplots(4, 1, figsize=(8, 10), sharex=True)
    t = res.time
    ax = axes[0]
    ax.plot(t, lateral_force(res) / 1e3, "k", label="lateral force [kN]")
    ax.set_ylabel("force [kN]")
    ax2 = ax.twinx()
    ax2.plot(t, res.y * 1e3, "C3", label="wheelset shift y")
    ax2.set_ylabel("shift y [mm]", color="C3")
    ax.legend(loc="upper left")
    ax.set_title("flange excursion on the measured pair (1/5 rig, braking at 0.02)")
    ax = axes[1]
    for side, c in (("left", "C0"), ("right", "C1")):
        s = getattr(geo, side).s_wheel / scale * 1e3
        ax.plot(t, s, c, label=f"{side} wheel")
    ax.set_ylabel("contact on the wheel [mm]\n(from the taping line, full size;\n< 0 toward "
                  "the flange)")
    ax.legend(loc="lower left")
    ax = axes[2]
    for side, c in (("left", "C0"), ("right", "C1")):
        ax.plot(t, np.degrees(getattr(geo, side).delta), c, label=f"{side} wheel")
    ax.set_ylabel("contact angle [deg]")
    ax.legend(loc="upper left")
    ax = axes[3]
    ax.plot(t, res.normal_load_left, "C0", label="normal load, left")
    ax.plot(t, res.normal_load_right, "C1", label="normal load, right")
    ax.plot(t, -res.fx, "C2", label="braking force -fx (both wheels)")
    ax.plot(t, res.fy, "C4", label="lateral creep force fy (both wheels)")
    ax.set_ylabel("force [N]")
    ax.set_xlabel("time [s]")
    ax.legend(loc="upper left", fontsize="small", ncol=2)
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def main(out="."):
    res, geo = run()
    scale = res.params["wheelset"]["profile_scale"]
    s = geo.left.s_wheel / scale * 1e3
    print(f"status {res.status} ({res.message}); largest shift {np.max(np.abs(res.y)) * 1e3:.3f} "
          f"mm; left contact angle up to {np.degrees(geo.left.delta.max()):.1f} deg; left "
          f"contact point from {s[res.time < 1].mean():.1f} to {s.min():.1f} mm (full size, "
          f"from the taping line); right wheel's load down to {res.normal_load_right.min():.0f} N")
    os.makedirs(out, exist_ok=True)
    print("wrote", figure(res, geo, os.path.join(out, "flange_excursion.png")))


if __name__ == "__main__":
    main(*sys.argv[1:])
