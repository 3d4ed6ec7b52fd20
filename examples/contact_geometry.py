"""Contact points of a wheelset on the rig's two rollers, from rollerrig.geometry.

Two pairs, each drawn on its LEFT side in the rig frame (Y lateral, left positive; Z up,
0 at the top of a roller of nominal radius), the wheel placed by the pose that
``rr.wheelset_contact`` solves for each lateral shift y_ws of the wheelset (shift, axle
height and roll: both wheels touch their rollers), the roller fixed:

* S1002 wheel on a roller with the UIC60 1:40 head, placed as the Manchester benchmark
  places S1002 on UIC60 track (wheel profile origins at +-750 mm, roller profile origins at
  +-760.53 mm: gauge 1435, flange backs 1360 mm), wheel and roller radius 0.46 m.
* The measured wheel/roller pair (MiniProf, rollerrig/data/profiles) on full-scale rollers:
  gauge the mean of the two .ban headers, flange backs 1347 mm apart (CONTACT's roller-rig
  case; an assumption for these profiles), wheel radii from the .whl headers'
  DiameterTaperline, roller radius 0.80010 m at the crown top (CONTACT's NOMRAD), profiles
  smoothed over 2 mm (tests/test_conicity.py, measured_rig, says why).

A third row shows the rolling-radius difference Delta r = r_L - r_R and the left wheel's
contact angle against the shift, for both pairs, and the equivalent conicity at 3 mm.
Positive y_ws moves the wheelset to the left, towards the left flange.

    pip install ".[plot]" && python examples/contact_geometry.py docs   # docs/contact_points.png
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollerrig as rr  # noqa: E402
from rollerrig.geometry.conicity import equivalent_conicity  # noqa: E402

MM = 1e-3


def manchester():
    return rr.RigGeometry(wheel=rr.Profile.s1002(), roller=rr.Profile.uic60(), wheel_radius=0.46,
                          roller_radius=0.46, wheel_y=0.75, roller_y=0.76053)




def measured():
    """The measured pair on the rig (RigGeometry.measured_pair)."""
    return rr.RigGeometry.measured_pair()


def wheel_in_rig(g, c, i):
    """The left wheel's profile mapped into the rig by the pose of row i (as the C core
    maps it: lateral shift, axle height, roll about the axle centre)."""
    s = g.wheel.y
    Yl, Zl = g.wheel_y + s, -g.wheel_radius - g.wheel.z
    cs, sn = np.cos(c.roll[i]), np.sin(c.roll[i])
    return c.y_ws[i] + Yl * cs - Zl * sn, c.z[i] + Yl * sn + Zl * cs


def draw_pair(ax, g, shifts, drawn, colours, title, window):
    c = rr.wheelset_contact(g, shifts)
    x0 = g.roller_y                                   # plot Y relative to the roller origin
    ry, rz = (g.roller_y + g.roller.y - x0) / MM, -g.roller.z / MM
    ax.fill_between(ry, rz, window[2], color="0.85", lw=0)
    ax.plot(ry, rz, "k-", lw=1.3, label="roller (fixed)")
    for i, dy in enumerate(shifts):
        if dy in drawn:
            wy, wz = wheel_in_rig(g, c, i)
            wy = (wy - x0) / MM
            ax.plot(wy, wz / MM, "-", color=colours[dy], lw=1.4)
    for i, dy in enumerate(shifts):
        y, z = (c.left.y[i] - x0) / MM, c.left.z[i] / MM
        angle = np.degrees(c.left.delta[i])
        ax.plot(y, z, "o", ms=7, mfc=colours[dy], mec="k", mew=0.6, zorder=5,
                label=f"y_ws = {dy / MM:+g} mm: contact angle {angle:4.1f} deg"
                      + (", 2-pt" if c.left.two_point[i] else "")
                      + (", wheel drawn" if dy in drawn else ""))
        if c.left.two_point[i]:
            ax.plot(y, z, "o", ms=13, mfc="none", mec=colours[dy], mew=1.0, zorder=4)
    ax.set(xlim=window[:2], ylim=window[2:], aspect="equal", title=title,
           xlabel=f"rig Y - {x0 / MM:.2f} mm (left side, outward +) [mm]",
           ylabel="rig Z (up; 0 = nominal roller top) [mm]")
    ax.grid(alpha=0.3)
    ax.legend(loc="lower right", fontsize=7, framealpha=0.9)
    return c


def table(name, g, shifts):
    c = rr.wheelset_contact(g, shifts)
    print(f"\n{name}\n  y_ws  Delta r   left: wheel  roller  delta   right: wheel  roller  delta"
          f"\n  [mm]    [mm]          [mm]    [mm]  [deg]           [mm]    [mm]  [deg]")
    for i, y in enumerate(shifts):
        L, R = c.left, c.right
        print(f"{y / MM:6.1f} {(L.r[i] - R.r[i]) / MM:7.3f}   "
              f"{L.s_wheel[i] / MM:11.2f}{'*' if L.two_point[i] else ' '} "
              f"{L.s_roller[i] / MM:6.2f} {np.degrees(L.delta[i]):6.2f}   "
              f"{R.s_wheel[i] / MM:12.2f}{'*' if R.two_point[i] else ' '} "
              f"{R.s_roller[i] / MM:6.2f} {np.degrees(R.delta[i]):6.2f}")
    print("  (wheel: profile coordinate, S1002 from the taping line, MiniProf from the flange "
          "back;\n   roller: its profile coordinate; * two-point contact)")


def main(outdir="."):
    os.makedirs(outdir, exist_ok=True)
    pairs = [
        ("S1002 on a UIC60-headed roller (Manchester placement), R0 = 0.46 m", manchester(),
         [0, 2, 4, 5, 6, 6.25], [0, 4, 6.25], (-46, 36, -30, 12), "tab:blue"),
        ("measured wheel on measured roller (MiniProf), R0 = 0.80 m", measured(),
         [0, 2, 4, 6, 8, 9], [0, 6, 9], (-46, 36, -30, 12), "tab:red"),
    ]
    palette = plt.get_cmap("tab10").colors
    palette = [palette[i] for i in (0, 2, 1, 4, 3, 5)]
    fig = plt.figure(figsize=(13, 7.9))
    gs = fig.add_gridspec(2, 2, height_ratios=[1.1, 1], hspace=0.3, wspace=0.18)
    scan = np.round(np.arange(-100, 101) * 0.1, 1) * MM
    ax_dr, ax_de = fig.add_subplot(gs[1, 0]), fig.add_subplot(gs[1, 1])
    for k, (title, g, shifts_mm, drawn_mm, window, colour) in enumerate(pairs):
        short = ("S1002 / UIC60", "measured pair")[k]
        shifts = np.array(shifts_mm, dtype=float) * MM
        drawn = {d * MM for d in drawn_mm}
        colours = dict(zip(shifts, palette))
        draw_pair(fig.add_subplot(gs[0, k]), g, list(shifts), drawn, colours,
                  title + "\nleft wheel on left roller; contact points by lateral shift", window)
        table(title, g, shifts)
        c = rr.wheelset_contact(g, scan, errors="ignore")
        ok = c.status >= 0
        lam = {m: equivalent_conicity(g, 0.003, m) for m in ("harmonic", "klingel")}
        label = (f"{short}: tan $\\gamma_e$(3 mm) = {lam['harmonic']:.3f} (harmonic), "
                 f"{lam['klingel']:.3f} (Klingel)")
        print("  equivalent conicity at 3 mm: " + ", ".join(
            f"{m} {v:.4f}" for m, v in lam.items())
              + f", simple {equivalent_conicity(g, 0.003, 'simple'):.4f}")
        dr = (c.left.r - c.right.r) / MM
        ax_dr.plot(scan[ok] / MM, dr[ok], "-", color=colour, lw=1.2, label=label)
        ax_de.plot(scan[ok] / MM, np.degrees(c.left.delta[ok]), "-", color=colour, lw=1.2,
                   label=short)
        at = rr.wheelset_contact(g, shifts)
        for i, s in enumerate(shifts):
            ax_dr.plot(s / MM, (at.left.r[i] - at.right.r[i]) / MM, "o", ms=6, mfc=colours[s],
                       mec="k", mew=0.5, zorder=5)
            ax_de.plot(s / MM, np.degrees(at.left.delta[i]), "o", ms=6, mfc=colours[s],
                       mec="k", mew=0.5, zorder=5)
    ax_dr.set(xlabel="lateral shift of the wheelset y_ws [mm] (+: to the left)",
              ylabel="$\\Delta r = r_L - r_R$ [mm]",
              title="rolling-radius difference (jumps: contact moves to another band)")
    ax_dr.axhline(0, color="0.5", lw=0.6)
    ax_dr.set_ylim(-6, 6)
    ax_dr.annotate("S1002 flange contact:\n$\\Delta r$ up to 20 mm", xy=(6.35, 5.9),
                   xytext=(1.6, 4.6), fontsize=7.5, arrowprops=dict(arrowstyle="->", lw=0.7))
    ax_de.set(xlabel="lateral shift of the wheelset y_ws [mm] (+: to the left)",
              ylabel="contact angle of the left wheel [deg]",
              title="left contact angle (flange contact: > 15 deg)")
    for ax, where in ((ax_dr, "lower right"), (ax_de, "upper left")):
        ax.grid(alpha=0.3)
        ax.legend(loc=where, fontsize=7.5, framealpha=0.9)
    path = os.path.join(outdir, "contact_points.png")
    fig.savefig(path, dpi=110, bbox_inches="tight")
    print("\nwrote", path)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
