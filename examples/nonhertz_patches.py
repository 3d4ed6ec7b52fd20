"""The fast non-Hertzian contact's patches beside the exact solution's, at
several lateral shifts of the wheelset on both profile pairs of CONTACT's
roller cases: the measured MiniProf pair (rr.RigGeometry.measured_pair())
and S1002 on a UIC60-headed roller (rr.RigGeometry.standard(roller_radius=
0.8001)); the left wheel, 61.2 kN, mu 0.52, braking at a creepage of about
0.002 (the roller at 5.587302 rad/s, CONTACT's testbank case).

    python examples/nonhertz_patches.py [output folder]

writes nonhertz_patches.png.  Each panel: the exact solution's pressure
(rr.rig_exact, 80 elements across, the reference of tests/test_nonhertz_fast.py)
element by element in its contact plane, its contours at 300, 600, 900
and 1200 MPa and its centroid x (white); and in red what rig_contact(..., patch="nonhertz")
computes for each patch: its pressure centroid (+) and an ellipse of the
patch's contact area with the a/b of the table's pressure moments (at the
patch's load, the two rows' values blended as the method blends them),
with a Hertzian pressure of the patch's peak on it (dashed, the same
levels).  Titles: |dF| / (mu N) of the wheel's total force against the
exact, and both peaks.  The table holds only the rows 0.1 mm either side
of each shift (each shift half-way between two rows, the blend at its
worst), so the script runs in about half a minute.
"""
import os
import sys
import time
import warnings

import numpy as np

import rollerrig as rr
from rollerrig import _core

FZ, MU, ROLLER_SPIN, CREEP = 61163.05, 0.52, 5.587302, 0.002
E, NU = 2.1e11, 0.28
N_REF = 80                  # rig_exact's elements across (its n = 40 is 0.01-0.02 mu N off)
HALF = 1e-4                 # table rows this far either side of a shift
LEVELS = (300e6, 600e6, 900e6, 1200e6)
#: (pair, geometry, lateral shifts [m]); MiniProf 3.5 mm and S1002 4.7 mm:
#: the exact patch in two regions (tread and flange root, one patch within
#: CONTACT's D_COMB of 4 mm); S1002 5.5 mm on the flange root
PAIRS = (("MiniProf (measured pair)", rr.RigGeometry.measured_pair,
          (0.0, 2.0e-3, 3.5e-3, 4.5e-3)),
         ("S1002 / UIC60", lambda: rr.RigGeometry.standard(roller_radius=0.8001),
          (-2.5e-3, 3.0e-3, 4.7e-3, 5.5e-3)))


def _ab(row, N):
    """a/b of a row's first patch at normal load N: the nodes' a/b, linear
    in the lowering e between nodes, e found from N = e^1.5 q(e) (as
    rr_nonhertz.c's node interpolation)."""
    p = row[_core.NH_ROW_HEAD:_core.NH_ROW_HEAD + _core.NH_PATCH_LEN]
    k = _core.NH_NODES

    def node(q):
        return p[1 + q * k:1 + (q + 1) * k]
    e, q, ab = node(0), node(1), node(9)       # RR_NH_E, RR_NH_Q, RR_NH_AB
    ee = np.linspace(e[0], e[-1], 2000)
    loads = ee ** 1.5 * np.interp(ee, e, q)
    return float(np.interp(N, loads, np.interp(ee, e, ab)))


def case(geometry, ctable, nh, y):
    """(exact RigExact, the fast wheel, |dF|/(mu N), per patch its a/b)."""
    L = ctable.lookup(np.array([y])).left
    spin = ROLLER_SPIN * float(L.R[0]) / float(L.r[0]) * (1.0 - CREEP)
    ref = rr.rig_exact(geometry, y, Fz=FZ, mu=MU, spin=spin, roller_spin=ROLLER_SPIN, E=E,
                       nu=NU, table=ctable, n=N_REF)
    fast = rr.rig_contact(ctable, y=y, spin=spin, roller_spin=ROLLER_SPIN, mu=MU, E=E, nu=NU,
                          Fz_left=FZ, Fz_right=FZ, patch="nonhertz", nonhertz=nh).left
    err = float(np.linalg.norm(fast.force - ref.force) / (MU * ref.N))
    rows = nh.left.rows
    i = int(np.searchsorted(rows[:, 0], y)) - 1
    w = (y - rows[i, 0]) / (rows[i + 1, 0] - rows[i, 0])
    abs_ = [(1 - w) * _ab(rows[i], p.N) + w * _ab(rows[i + 1], p.N) for p in fast.patches]
    return ref, fast, err, abs_


def compute():
    """Per pair: (label, [(y, ref, fast, err, a/b per patch)]); and the seconds."""
    t0 = time.perf_counter()
    out = []
    for label, make, ys in PAIRS:
        g = make()
        ct = rr.contact_table(g, -0.0065, 0.0065, 261)
        rows = sorted({round(v, 9) for y in ys for v in (y - HALF, y + HALF)})
        with warnings.catch_warnings():
            # a region beyond combine that touches at some node's load is
            # warned by the table (one patch per row); the exact reference
            # solves the same one patch
            warnings.simplefilter("ignore", rr.RollerRigWarning)
            t = rr.nonhertz_table(g, None, None, y=rows, Fz=FZ, mu_ref=MU, E=E, nu=NU,
                                  sides=("left",))
        nh = rr.NonHertzTable(t.left, t.left, t.Fz)    # the right side unused
        out.append((label, [(y, *case(g, ct, nh, y)) for y in ys]))
    return out, time.perf_counter() - t0


def _panel(ax, label, y, ref, fast, err, abs_):
    import rollerrig.plot as rp
    s, P = ref.solution, ref.patch
    rp.traction_field(s, ax, quantity="pn", show_slip=False, arrows=False, colorbar=True,
                      title=False)
    X, Y = s.x * 1e3, s.y * 1e3
    lv = [v for v in LEVELS if v < s.pmax]
    if lv:
        ax.contour(X, Y, s.pn, levels=lv, colors="w", linewidths=0.7)
    w = s.pn / s.pn.sum()
    ax.plot((w * X).sum(), (w * Y).sum(), "wx", ms=8, mew=1.6)     # the exact centroid
    th = np.linspace(0.0, 2.0 * np.pi, 181)
    for p, ab in zip(fast.patches, abs_):
        d = p.point - P.point
        u, v = float(d @ P.t1) * 1e3, float(d @ P.t2) * 1e3     # centroid in the exact plane
        a = np.sqrt(p.area * ab / np.pi) * 1e3
        b = a / ab
        ax.plot(u + a * np.cos(th), v + b * np.sin(th), "r", lw=1.4)
        ax.plot(u, v, "r+", ms=9, mew=1.6)
        for lev in LEVELS:
            if lev < p.pmax:
                k = np.sqrt(1.0 - (lev / p.pmax) ** 2)        # Hertz: p = pmax sqrt(1 - r^2)
                ax.plot(u + k * a * np.cos(th), v + k * b * np.sin(th), "r--", lw=0.7)
    regions = ref.shape.regions
    ax.set_title(f"{label}, y = {y * 1e3:+.1f} mm ({regions} region"
                 f"{'s' if regions > 1 else ''})\n|dF|/(mu N) = {err:.4f}; peak "
                 f"{s.pmax / 1e6:.0f} exact, {fast.pmax / 1e6:.0f} MPa fast", fontsize=8.5)
    ax.tick_params(labelsize=7)
    ax.xaxis.label.set_size(8)
    ax.yaxis.label.set_size(8)


def figure(results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    ncol = max(len(c) for _, c in results)
    fig, axes = plt.subplots(len(results), ncol, figsize=(4.6 * ncol, 4.3 * len(results)),
                             squeeze=False)
    for r, (label, cases) in enumerate(results):
        for c, item in enumerate(cases):
            _panel(axes[r, c], label, *item)
    handles = [Line2D([], [], color="w", lw=0.7, marker="x", mew=1.6,
                      label="exact: pressure contours, x its centroid"),
               Line2D([], [], color="r", lw=1.4, label="fast: ellipse of the patch's area, "
                                                       "table's a/b; + its centroid"),
               Line2D([], [], color="r", ls="--", lw=0.7, label="fast: Hertzian pressure of "
                                                                "the patch's peak")]
    leg = fig.legend(handles=handles, loc="lower center", ncol=3, fontsize=8.5,
                     facecolor="0.6")
    leg.get_frame().set_alpha(0.9)
    fig.suptitle("Left wheel on its roller, 61.2 kN, mu 0.52, braking at cx 0.002: exact "
                 "pressure (colour, rr.rig_exact n = 80) and the fast non-Hertzian contact "
                 "(red, rig_contact patch='nonhertz'); contours at 300, 600, 900, 1200 MPa",
                 fontsize=9.5)
    fig.tight_layout(rect=(0, 0.04, 1, 0.97))
    fig.savefig(path, dpi=100)
    plt.close(fig)
    return path


def main(out="."):
    """Compute, print the errors, draw: (the results as compute(), the figure's path)."""
    results, seconds = compute()
    for label, cases in results:
        for y, ref, fast, err, abs_ in cases:
            print(f"{label:26s} y = {y * 1e3:+.1f} mm: |dF|/(mu N) = {err:.4f}, patches "
                  f"{len(fast.patches)}, area {fast.area / ref.solution.contact_area - 1:+.3f}"
                  f", peak {fast.pmax / ref.solution.pmax - 1:+.3f} (relative to the exact)")
    print(f"computed in {seconds:.1f} s")
    os.makedirs(out, exist_ok=True)
    path = figure(results, os.path.join(out, "nonhertz_patches.png"))
    print("wrote", path)
    return results, path


if __name__ == "__main__":
    main(*sys.argv[1:])
