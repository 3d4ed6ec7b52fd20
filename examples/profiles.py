"""Wheel and rail/roller profiles: the S1002 wheel over the UIC60 rail head of the
Manchester contact benchmark, and the measured wheel/roller pair of a roller rig, with the
curvature the Hertz module will see.

Both pairs are drawn in one frame per pair (y towards the field side, z downward, as
rollerrig.geometry.profiles documents); the wheel is moved laterally to a centred position and then
lowered until it touches (the least gap is closed), and the touching point is marked.  This
is a picture of the profiles, not the contact search of the geometry module:

* S1002 on UIC60 (canted 1:40 in the file): gauge 1435 mm measured 14 mm below the top of
  the rail, flange backs 1360 mm apart, taping line 70 mm from the flange back.
* Measured left wheel on the left roller (MiniProf files): the gauge from the roller file's
  header (Gauge = 1436.91 mm at RailGaugePoint = 14 mm) and a flange-back distance of
  1347 mm taken from CONTACT's roller-rig case dry_10mph_13750lbs
  (shared/reference/rig-parameters.csv); that these profiles belong to that rig is an
  assumption made for the picture only.

    pip install ".[plot]" && python examples/profiles.py docs   # writes docs/profiles.png
"""
import os
import sys
import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollerrig as rr  # noqa: E402

MM = 1e-3
DATA = rr.profiles.DATA_DIR




def seat(wheel, rail, dy):
    """The wheel moved by dy and lowered until it touches the rail; the touching point."""
    moved = wheel.shifted(dy, 0.0)
    y = np.linspace(max(moved.y_min, rail.y_min), min(moved.y_max, rail.y_max), 20001)
    gap = rail.z_at(y) - moved.z_at(y)
    k = int(np.argmin(gap))
    return moved.shifted(0.0, gap[k]), y[k]


def draw(ax, wheel, rail, yc, title, wheel_label, rail_label):
    ax.fill_between(rail.y / MM, rail.z / MM, rail.z.max() / MM + 5, color="0.85")
    ax.plot(rail.y / MM, rail.z / MM, "k-", lw=1.2, label=rail_label)
    ax.fill_between(wheel.y / MM, wheel.z / MM, wheel.z.min() / MM - 5, color="tab:blue",
                    alpha=0.15)
    ax.plot(wheel.y / MM, wheel.z / MM, "-", color="tab:blue", lw=1.2, label=wheel_label)
    ax.plot(yc / MM, rail.z_at(yc) / MM, "o", color="tab:red", ms=6,
            label=f"touching point, y = {yc / MM:.1f} mm")
    ax.invert_yaxis()
    ax.set(aspect="equal", xlabel="y, towards the field side [mm]", ylabel="z, downward [mm]",
           title=title)
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right", fontsize=7)


def main(outdir="."):
    os.makedirs(outdir, exist_ok=True)
    fig, axes = plt.subplots(2, 2, figsize=(12, 7.6), gridspec_kw={"height_ratios": [1, 1]})

    # S1002 over UIC60, centred wheelset on standard track
    wheel, rail = rr.Profile.s1002(), rr.Profile.uic60()
    y_gauge = rail.gauge_point(14 * MM)
    dy = y_gauge + (1360 / 2 + 70 - 1435 / 2) * MM
    placed, yc = seat(wheel, rail, dy)
    print(f"S1002 on UIC60: gauge point y = {y_gauge / MM:.2f} mm, taping line at "
          f"y = {dy / MM:.2f} mm, touching at rail y = {yc / MM:.2f} mm "
          f"(wheel y = {(yc - dy) / MM:.2f} mm from its taping line)")
    draw(axes[0, 0], placed, rail, yc, "S1002 wheel on UIC60 rail (Manchester benchmark),\n"
         "centred: gauge 1435, flange backs 1360 mm", "S1002 (wheel)", "UIC60 1:40 (rail)")

    # the measured pair (the roller files fold on the gauge face: removed, with a warning)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rr.RollerRigWarning)
        mwheel = rr.read_profile(os.path.join(DATA, "left-wheel-v1-pre-dry.whl"))
        roller = rr.read_profile(os.path.join(DATA, "left-roller-v1-pre-dry.ban"))
        roller_smooth = rr.read_profile(os.path.join(DATA, "left-roller-v1-pre-dry.ban"),
                                        smoothing=2 * MM)
        mwheel_smooth = rr.read_profile(os.path.join(DATA, "left-wheel-v1-pre-dry.whl"),
                                        smoothing=2 * MM)
    y_gauge = roller.gauge_point(roller.meta["RailGaugePoint"] * MM)
    dy = y_gauge + (1347.0 / 2 - roller.meta["Gauge"] / 2) * MM
    placed, yc = seat(mwheel, roller, dy)
    tape = mwheel.meta["WheelDiameterTaperline"]
    print(f"measured pair: roller gauge point y = {y_gauge / MM:.2f} mm, flange back at "
          f"y = {dy / MM:.2f} mm, touching at roller y = {yc / MM:.2f} mm (wheel "
          f"y = {(yc - dy) / MM:.2f} mm from its flange back, taping line at {tape:g} mm)")
    draw(axes[0, 1], placed, roller, yc, "measured wheel on measured roller (MiniProf), "
         "left side,\ncentred: roller gauge 1436.9, flange backs 1347 mm (assumed)",
         "left wheel", "left roller")

    # curvature: continuous with the cubic spline; measured profiles smoothed over 2 mm
    ax = axes[1, 0]
    t = np.linspace(wheel.y_min, wheel.y_max, 4000)
    ax.plot(t / MM, wheel.curvature(t), "-", color="tab:blue", lw=1, label="S1002 (wheel)")
    t = np.linspace(rail.y_min, rail.y_max, 4000)
    ax.plot(t / MM, rail.curvature(t), "k-", lw=1, label="UIC60 (rail)")
    for R in (300, 80, 13):
        ax.axhline(1000 / R, color="0.6", lw=0.6, ls=":")
        ax.text(-68, 1000 / R + 2, f"1/R{R}", fontsize=7, color="0.4")
    ax.set(ylim=(-120, 120), xlabel="y [mm] (each profile in its own frame)",
           ylabel="curvature z''/(1+z'^2)^1.5 [1/m]",
           title="curvature (> 0: convex rail, concave wheel)")
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right", fontsize=7)

    ax = axes[1, 1]
    for p, q, color, label in ((mwheel, mwheel_smooth, "tab:blue", "left wheel"),
                               (roller, roller_smooth, "k", "left roller")):
        t = np.linspace(p.y_min, p.y_max, 6000)
        ax.plot(t / MM, p.curvature(t), "-", color=color, lw=0.5, alpha=0.45,
                label=f"{label}, interpolated")
        ax.plot(t / MM, q.curvature(t), "-", color=color, lw=1.1,
                label=f"{label}, smoothing = 2 mm")
    ax.set(ylim=(-150, 150), xlabel="y [mm] (each profile in its own frame)",
           ylabel="curvature [1/m]", title="measured profiles: curvature, raw and smoothed")
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right", fontsize=7)

    fig.tight_layout()
    path = os.path.join(outdir, "profiles.png")
    fig.savefig(path, dpi=110)
    print("wrote", path)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
