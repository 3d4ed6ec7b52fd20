"""Root locus of the scaled wheelset on its rollers and on tangent track.

The plant linearised at its steady state at each speed (rollerrig.stability,
docs/lateral_dynamics.md): the lightly damped lateral/yaw modes against
speed, for the default (stiff) axle-box springs and a soft suspension
(kx = ky = 20 kN/m per box), on the rollers and on track, with and without
the spinning wheelset's gyroscopic terms; prints the linear critical speeds.

    python examples/root_locus.py [output folder]

writes root_locus.png (default: docs/).
"""
import os
import sys

import numpy as np

import rollerrig as rr

SPEEDS = np.linspace(2.0, 150.0, 75)
SOFT = {"suspension": {"kx_N_per_m": 2e4, "ky_N_per_m": 2e4}}
CASES = {"default": {}, "soft (20 kN/m)": SOFT}
#: the plot's left edge [1/s]: the lags' and the contact's fast modes beyond
LEFT = -2000.0


def with_gyro(params, on):
    return {**params, "wheelset": {"gyroscopic": on}}


def critical_speeds(speeds=SPEEDS):
    """{(case, where, gyroscopic): Stability}"""
    out = {}
    for name, params in CASES.items():
        for track in (False, True):
            for gyro in (True, False):
                out[name, "track" if track else "rollers", gyro] = rr.stability(
                    speeds, with_gyro(params, gyro), track=track)
    return out


def main(folder):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    res = critical_speeds()
    print(f"{'suspension':>16} {'where':>8} {'gyroscopic':>10} {'critical speed [m/s]':>21}")
    for (name, where, gyro), st in res.items():
        v = st.critical_speed
        print(f"{name:>16} {where:>8} {str(gyro):>10} "
              f"{'none < %g' % SPEEDS[-1] if v != v else '%.2f' % v:>21}")
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, (name, params) in zip(axes, CASES.items()):
        for where, color in (("rollers", "tab:blue"), ("track", "tab:red")):
            st = res[name, where, True]
            for modes, V in zip(st.modes, st.speeds):
                # the modes the lateral and yaw motions take part in (real
                # ones too: the stiff default has no lateral oscillation)
                osc = [m.eigenvalue for m in modes if not m.neutral
                       and set(m.dominant[:2]) & {"y", "yaw"} and m.eigenvalue.real > LEFT]
                ax.scatter([z.real for z in osc], [z.imag / (2 * np.pi) for z in osc],
                           c=[V] * len(osc), cmap="viridis", vmin=SPEEDS[0],
                           vmax=SPEEDS[-1], s=10, marker="o" if where == "rollers" else "^")
            v = st.critical_speed
            ax.plot([], [], "o" if where == "rollers" else "^", color=color,
                    label=f"{where}: V_c = " + ("none" if v != v else f"{v:.1f} m/s"))
        ax.axvline(0.0, color="k", lw=0.8)
        ax.set_xscale("symlog", linthresh=10.0)
        ax.set_title(f"{name} suspension")
        ax.set_xlabel("real part [1/s] (symlog)")
        ax.legend(loc="upper left", fontsize=8)
    axes[0].set_ylabel("damped frequency [Hz]")
    sm = plt.cm.ScalarMappable(cmap="viridis",
                               norm=plt.Normalize(vmin=SPEEDS[0], vmax=SPEEDS[-1]))
    fig.colorbar(sm, ax=axes, label="speed [m/s]")
    fig.suptitle("Lateral/yaw modes of the scaled wheelset against speed "
                 "(o rollers, ^ track)")
    path = os.path.join(folder, "root_locus.png")
    fig.savefig(path, dpi=110)
    print(f"wrote {path}")
    return res


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..",
                                                              "docs"))
