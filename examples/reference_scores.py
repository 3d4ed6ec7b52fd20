"""Every creep-force method against CONTACT's exact theory (rollerrig.analysis.reference).

Prints the score table on the 3220 cases of CONTACT's test_table (|dF|/(mu N)
and |dMz|/(mu N cp), overall and split by spin level and ellipticity) and the
creep-curve scores, and with an output folder writes

- reference_error_map.png: FASTSIM's and blended FASTSIM's error over the
  creepage direction / magnitude plane, one panel per spin level (worst of
  the five ellipticities per cell);
- reference_creep_curves.png: the four series of CONTACT's creep-curve
  example with the corresponding rollerrig methods.

    pip install ".[plot]" && python examples/reference_scores.py [output folder]
"""
import os
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import rollerrig as rr  # noqa: E402
from rollerrig import plot as rp  # noqa: E402
from rollerrig.analysis import reference as ref  # noqa: E402

GRID = dict(nx=30, ny=30)     # the FASTSIM variants on the 3220 cases

#: the methods drawn against each creep-curve series (besides the series' own)
CURVE_METHODS = {1: ("fastsim", "fastsim_blended", "polach"),
                 2: ("fastsim", "polach", "modified_fastsim"),
                 3: ("fastsim",),
                 4: ("modified_fastsim",)}
COLOR = {"fastsim": "tab:blue", "fastsim_blended": "tab:orange", "polach": "tab:green",
         "modified_fastsim": "tab:red", "linear": "tab:gray"}
STYLE = {"fastsim": "-", "fastsim_blended": "--", "polach": "-.", "modified_fastsim": "-",
         "linear": ":"}


def score_all():
    results = {}
    for method in rr.METHODS:
        opts = dict(GRID) if "fastsim" in method else {}
        results[method] = ref.score(method, **opts)
    return results


def draw_error_map(results, path):
    pair = [results["fastsim"], results["fastsim_blended"]]
    levels = np.unique(pair[0].cases.spin)
    fig, axes = plt.subplots(2, levels.size, figsize=(11, 8.2), sharex=True, sharey=True,
                             constrained_layout=True)
    top = max(float(np.nanmax(r.error)) for r in pair)
    for row, r in zip(axes, pair):
        rp.error_map(r, ax=row, vmax=top, colorbar=False)
        row[0].set_ylabel(f"{r.method}\ncreepage magnitude (normalised)")
    for axi in axes[0]:
        axi.set_xlabel("")
    fig.colorbar(axes[0, 0].collections[0], ax=axes, shrink=0.8,
                 label="|dF| / (mu N), worst of the 5 ellipticities a/b")
    fig.suptitle("FASTSIM (top) and blended FASTSIM (bottom), 30 x 30, against CONTACT's "
                 "exact theory: 3220 cases, one panel per spin level", fontsize=11)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def draw_creep_curves(path):
    curves = ref.creep_curves()
    fig, axes = plt.subplots(2, 2, figsize=(11, 8.4), sharex=True, constrained_layout=True)
    cx = np.geomspace(7e-6, 0.3, 300)
    for axi, (k, c) in zip(axes.ravel(), curves.items()):
        mu, N = c.case["mu"], c.case["N"]
        axi.plot(c.cx, -c.fx_n, "ko", ms=3.5, mfc="none", label="CONTACT", zorder=3)
        for method in CURVE_METHODS[k]:
            # the series' grid; the series' own method also with its k0, ...
            opts = dict(c.options) if method == c.method else \
                {k: c.options[k] for k in ("nx", "ny") if k in rr.METHODS[method].options}
            s = ref.score_curves(method, series=k, **opts)[k]
            f = rr.creep_forces(cx, method=method, errors="raise", **c.case, **opts)
            grid = ""
            if "fastsim" in method:
                grid = f" {opts.get('nx', 30)}x{opts.get('ny', 30)}"
            axi.plot(cx, -f.fx / (mu * N), STYLE[method], color=COLOR[method],
                     label=f"{method}{grid}: RMS {s.rms:.4f}, max {s.max:.4f}")
        fr = c.case["friction"]
        title = textwrap.fill(f"series {k}: {c.description}", 80)
        if fr is not None:
            title += (f"\nmu0 = {mu:g}, falling friction A = {fr.A:.3f}, "
                      f"B = {fr.B:.3f} s/m")
        axi.set_title(title, fontsize=9)
        if c.note:
            axi.text(0.03, 0.95, textwrap.fill(c.note, 40), transform=axi.transAxes,
                     va="top", fontsize=7.5, color="0.3")
        axi.set(xscale="log", xlim=(7e-6, 0.3), ylim=(0, 1.12))
        axi.grid(alpha=0.3)
        axi.legend(loc="lower right", fontsize=7.5)
    for axi in axes[1]:
        axi.set_xlabel("longitudinal creepage cx")
    for axi in axes[:, 0]:
        axi.set_ylabel("-Fx / (mu N)")
    fig.suptitle("CONTACT's creep-curve example (a = 6.304 mm, b = 12.61 mm, N = 106.7 kN, "
                 "V = 10 m/s): RMS and max of |dFx| / (mu N) over each series' points",
                 fontsize=10)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main(outdir=None):
    results = score_all()
    print(ref.table(results))
    print()
    print("creep curves: RMS / max of |dFx|/(mu N) per series "
          "(FASTSIM variants on the series' grid, 48 x 44)")
    curves = ref.creep_curves()
    print(f"  {'method':<18}" + "".join(f"{f'series {k}':>20}" for k in curves))
    for method in rr.METHODS:
        # the series' grid for the methods that have one (an option a method
        # does not have is refused)
        opts = {k: curves[3].options[k] for k in ("nx", "ny") if k in rr.METHODS[method].options}
        if method == "modified_fastsim":
            opts = dict(curves[4].options)       # k0, alpha_inf, beta as in series 4
        # a Coulomb-only method (exact, fastrip) has no score on the
        # falling-friction series
        wanted = [k for k, c in curves.items()
                  if c.case.get("friction") is None or not rr.METHODS[method].coulomb_only]
        scores = ref.score_curves(method, series=wanted, **opts)
        print(f"  {method:<18}" + "".join(
            f"{f'{scores[k].rms:.4f} / {scores[k].max:.4f}' if k in scores else '-':>20}"
            for k in curves))
    if outdir is not None:
        os.makedirs(outdir, exist_ok=True)
        for name, draw in (("reference_error_map.png", lambda p: draw_error_map(results, p)),
                           ("reference_creep_curves.png", draw_creep_curves)):
            path = os.path.join(outdir, name)
            draw(path)
            print("wrote", path)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else None)
