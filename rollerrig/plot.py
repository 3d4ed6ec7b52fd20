"""Pictures (matplotlib, imported on use, never at ``import rollerrig``).

    import rollerrig.plot as rp
    rp.creep_curves(cx, {"fastsim": f1, "polach": f2}, mu=0.33, N=106.7e3,
                    reference=rr.reference.creep_curves()[1])
    rp.traction_field(rr.fastsim_field(1e-3, 0, 0.3, a=..., b=..., N=..., mu=...))
    rp.rig_history(res); rp.rig_force(res)       # the seed paper's Fig. 7 and Fig. 8
    rp.profiles(rr.RigGeometry.standard(), y_ws=(0, 0.002, 0.004))
    rp.fit(rr.fit_polach(cx, fx, ...), cx, fx)
    rp.error_map(rr.reference.score("fastsim"))  # the error over the 3220 exact cases
    rp.plot_run(res, "out")                      # rig_creepage.png, rig_force.png

Every function takes ``ax=`` (``axes=`` for the two-panel ones): None draws on
a new figure, otherwise on the axes given; it returns the axes (a numpy array
of axes for several panels).  Forces act on the wheel (Kalker's sign: fx < 0
for cx > 0), so creep curves are drawn as -fx by default.  Bad input raises
RollerRigError.
"""
import numbers
import os
import warnings

import numpy as np

from ._errors import RollerRigError
from ._optional import require

__all__ = ["creep_curve", "creep_curves", "traction_field", "rig_history", "rig_force",
           "profiles", "fit", "error_map", "plot_run", "TRACTION_QUANTITIES"]

MM = 1e-3

#: quantity -> (label, unit scale, unit) of traction_field
TRACTION_QUANTITIES = {
    "|p_t|": ("tangential traction |p_t|", 1e-6, "MPa"),
    "px": ("traction px on the wheel", 1e-6, "MPa"),
    "py": ("traction py on the wheel", 1e-6, "MPa"),
    "pn": ("pressure pn", 1e-6, "MPa"),
    "|p_t|/pn": ("traction bound used |p_t| / pn", 1.0, "-"),
    "slip": ("adhesion / slip", 1.0, ""),
}


# ------------------------------------------------------------------ helpers

def _pyplot():
    # matplotlib is a dependency of the base install, but may have been left out
    return require("matplotlib.pyplot", "rollerrig.plot", "plot", package="matplotlib")


def _one_axes(func, ax, figsize):
    """(figure, axes, made here) for an ax= argument."""
    plt = _pyplot()
    from matplotlib.axes import Axes
    if ax is None:
        fig, ax = plt.subplots(figsize=figsize)
        return fig, ax, True
    if not isinstance(ax, Axes):
        raise RollerRigError(f"{func}: ax must be a matplotlib Axes or None, "
                             f"got {type(ax).__name__}")
    return ax.figure, ax, False


def _many_axes(func, axes, n, figsize, **subplots):
    """(figure, array of n axes, made here) for an axes= argument."""
    plt = _pyplot()
    from matplotlib.axes import Axes
    if axes is None:
        fig, axs = plt.subplots(n, 1, figsize=figsize, squeeze=False, **subplots)
        return fig, axs[:, 0], True
    arr = np.asarray(axes, dtype=object).ravel() if not isinstance(axes, Axes) \
        else np.array([axes], dtype=object)
    if arr.size != n or not all(isinstance(a, Axes) for a in arr):
        raise RollerRigError(f"{func}: axes must be None or {n} matplotlib Axes, got "
                             f"{axes!r:.80}")
    return arr[0].figure, arr, False


def _real_1d(func, name, value):
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise RollerRigError(f"{func}: {name} must be real numbers, got "
                             f"{type(value).__name__}") from None
    if arr.ndim != 1 or arr.size == 0:
        raise RollerRigError(f"{func}: {name} must be a non-empty 1-D array, got shape "
                             f"{arr.shape}")
    return arr


def _positive(func, name, value):
    if isinstance(value, bool) or not isinstance(value, numbers.Real) \
            or not np.isfinite(value) or value <= 0:
        raise RollerRigError(f"{func}: {name} must be a positive number, got {value!r}")
    return float(value)


def _scale(func, mu, N):
    """(divisor, text) of the normalisation: mu N, N, or none."""
    if mu is not None and N is None:
        raise RollerRigError(f"{func}: mu given without N; normalising needs both (or N "
                             "alone for force / N)")
    if N is None:
        return 1.0, None
    N = _positive(func, "N", N)
    if mu is None:
        return N, "N"
    mu = _positive(func, "mu", mu)
    return mu * N, "(mu N)"


def _ylabel(comp, sign, norm):
    name = ("-" if sign < 0 else "") + comp
    return f"{name} / {norm}" if norm else f"{name} [N]"


def _xscale(cx, xscale):
    if xscale is None:
        good = cx[np.isfinite(cx)]
        return "log" if good.size and np.all(good > 0) else "linear"
    if xscale not in ("log", "linear"):
        raise RollerRigError(f"xscale must be 'log', 'linear' or None, got {xscale!r}")
    return xscale


def _sign(func, sign):
    if sign not in (1, -1):
        raise RollerRigError(f"{func}: sign must be +1 or -1, got {sign!r}")
    return sign


# ------------------------------------------------------------------ creep curves

_COMPONENTS = ("fx", "fy", "|f|")


def _force_values(func, force, component, n):
    from .contact.creep import CreepForces
    if component not in _COMPONENTS:
        raise RollerRigError(f"{func}: component must be one of {_COMPONENTS}, "
                             f"got {component!r}")
    if isinstance(force, CreepForces):
        fx, fy = np.asarray(force.fx, dtype=float), np.asarray(force.fy, dtype=float)
        vals = {"fx": fx, "fy": fy, "|f|": np.hypot(fx, fy)}[component]
    elif isinstance(force, (str, bytes, dict)) or force is None:
        raise RollerRigError(f"{func}: a force must be an array [N] or a CreepForces, got "
                             f"{type(force).__name__}")
    else:
        vals = _real_1d(func, "force", force)
    vals = np.ravel(vals)
    if vals.size != n:
        raise RollerRigError(f"{func}: force has {vals.size} values for {n} creepages")
    return vals


def creep_curve(cx, force, *, ax=None, label=None, mu=None, N=None, sign=-1,
                component="fx", xscale=None, **line_kw):
    """One creep curve: sign * force / (mu N) against the creepage cx.

    force: an array [N] (one per cx) or a CreepForces (its `component`:
    "fx", "fy" or "|f|").  mu, N: normalise by mu N (N alone: by N; neither:
    the force in N).  sign: -1 (default) draws -fx, the adhesion on the
    wheel.  xscale: "log", "linear" or None (log when every cx > 0).
    line_kw go to Axes.plot.  On axes that already hold lines, the scale and
    the axis labels are left as they are.  Returns the axes."""
    func = "creep_curve"
    cx = _real_1d(func, "cx", cx)
    sign = _sign(func, sign)
    vals = _force_values(func, force, component, cx.size)
    div, norm = _scale(func, mu, N)
    _, ax, _ = _one_axes(func, ax, (6, 4))
    fresh = not ax.get_lines()       # keep the scale and labels of axes drawn on before
    ax.plot(cx, sign * vals / div, label=label, **line_kw)
    if fresh:
        ax.set_xscale(_xscale(cx, xscale))
        ax.set_xlabel("longitudinal creepage cx" if component == "fx" else "creepage")
        ax.set_ylabel(_ylabel(component, sign, norm))
    if label is not None:
        ax.legend(fontsize=8)
    return ax


def _reference_points(func, reference):
    """(cx, fx [N], label, mu, N) of a reference curve."""
    from .analysis.reference import CreepCurve
    if isinstance(reference, CreepCurve):
        what = "exact theory (CONTACT)" if reference.method is None \
            else f"CONTACT's {reference.method}"
        return (np.asarray(reference.cx, float), np.asarray(reference.fx, float),
                f"{what}, series {reference.series}", reference.case["mu"],
                reference.case["N"])
    if isinstance(reference, tuple) and len(reference) in (2, 3):
        cx = _real_1d(func, "reference cx", reference[0])
        fx = _real_1d(func, "reference force", reference[1])
        if cx.size != fx.size:
            raise RollerRigError(f"{func}: reference has {cx.size} creepages and "
                                 f"{fx.size} forces")
        label = str(reference[2]) if len(reference) == 3 else "reference"
        return cx, fx, label, None, None
    raise RollerRigError(f"{func}: reference must be a rollerrig.analysis.reference.CreepCurve or a "
                         f"tuple (cx, force[, label]), got {type(reference).__name__}")


_STYLES = ("-", "--", "-.", ":")


def creep_curves(cx, curves, *, mu=None, N=None, reference=None, ax=None, sign=-1,
                 component="fx", xscale=None, title=None):
    """Several creep curves on one axes, optionally over reference points.

    curves: {label: force} (arrays [N] or CreepForces, one value per cx) or
    a single force.  reference: a rollerrig.analysis.reference.CreepCurve (e.g.
    rr.reference.creep_curves()[1], CONTACT's exact theory) or a tuple
    (cx, force[, label]), drawn as black markers; a CreepCurve also supplies
    mu and N when they are not given.  Normalisation, sign, component and
    xscale as for creep_curve.  Returns the axes: one line per curve (in
    order), then one for the reference; a legend when there are labels."""
    func = "creep_curves"
    cx = _real_1d(func, "cx", cx)
    if not isinstance(curves, dict):
        curves = {None: curves}
    if not curves:
        raise RollerRigError(f"{func}: curves is empty")
    ref = _reference_points(func, reference) if reference is not None else None
    if ref is not None and mu is None and N is None and ref[3] is not None:
        mu, N = ref[3], ref[4]
    sign = _sign(func, sign)
    div, norm = _scale(func, mu, N)
    values = {label: _force_values(func, f, component, cx.size) for label, f in curves.items()}
    _, ax, _ = _one_axes(func, ax, (6.4, 4.2))
    for k, (label, vals) in enumerate(values.items()):
        ax.plot(cx, sign * vals / div, _STYLES[k % len(_STYLES)], lw=1.4,
                label=None if label is None else str(label))
    if ref is not None:
        ax.plot(ref[0], sign * ref[1] / div, "ko", ms=4, label=ref[2], zorder=3)
    ax.set_xscale(_xscale(cx, xscale))
    ax.set_xlabel("longitudinal creepage cx" if component == "fx" else "creepage")
    ax.set_ylabel(_ylabel(component, sign, norm))
    if norm == "(mu N)":             # |F| <= mu N: clip the linear theory's straight line
        shown = sign * np.concatenate(list(values.values())) / div
        lo, hi = float(np.nanmin(shown)), float(np.nanmax(shown))
        ax.set_ylim(min(0.0, 1.08 * lo) if lo > -1.2 else -1.2,
                    max(0.0, 1.08 * hi) if hi < 1.2 else 1.2)
    ax.grid(alpha=0.3, which="both", lw=0.5)
    if title:
        ax.set_title(title, fontsize=10)
    if any(line.get_label() and not line.get_label().startswith("_")
           for line in ax.get_lines()):
        ax.legend(fontsize=8, loc="best")
    return ax


# ------------------------------------------------------------------ traction field

def _cell_sizes(t):
    """(dx per element, dy) of the field's elements [m]."""
    ny, nx = t.x.shape
    if ny > 1:
        dy = float(np.abs(t.y[1, 0] - t.y[0, 0]))
        dx = t.area / dy
    elif nx > 1:
        dx = np.abs(np.diff(t.x, axis=1)[:, :1]) * np.ones_like(t.x)
        dy = float(t.area.flat[0] / dx.flat[0])
    else:
        dx = np.sqrt(t.area)
        dy = float(dx.flat[0])
    return dx, dy


def traction_field(t, ax=None, *, quantity="|p_t|", show_slip=True, arrows=True,
                   colorbar=None, cmap="viridis", title=True):
    """A traction field element by element: FASTSIM's (rr.fastsim_field) or
    the exact theory's (rr.exact_field, rr.exact_solve).

    quantity: one of TRACTION_QUANTITIES, the elements' colour ("slip": blue
    adhesion, red slip); show_slip: hatch the elements that slip and outline
    the adhesion/slip boundary; arrows: the tangential tractions (quiver,
    at most ~16 per direction); colorbar: add one (default: when a figure is
    made here); title: the forces in the title.  x, y in mm.  Returns the
    axes, with the collections in this order: the elements (label
    "elements"), then with show_slip the slip hatch ("slip area", when any
    element slips) and the boundary ("adhesion/slip boundary"), then the
    arrows ("tractions")."""
    func = "traction_field"
    from .contact.creep import TractionField
    if not isinstance(t, TractionField):
        raise RollerRigError(f"{func}: t must be a TractionField (rr.fastsim_field, "
                             f"rr.exact_field), got "
                             f"{type(t).__name__}")
    if quantity not in TRACTION_QUANTITIES:
        raise RollerRigError(f"{func}: quantity must be one of {list(TRACTION_QUANTITIES)}, "
                             f"got {quantity!r}")
    fig, ax, made = _one_axes(func, ax, (5.8, 5.2))
    from matplotlib.collections import LineCollection, PolyCollection
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch

    inside = t.pn > 0
    if not np.any(inside):
        raise RollerRigError(f"{func}: no element carries pressure")
    dx, dy = _cell_sizes(t)
    X, Y = t.x / MM, t.y / MM
    hx, hy = dx / MM / 2, dy / MM / 2

    def boxes(mask):
        xs, ys, wx = X[mask], Y[mask], hx[mask]
        return np.stack([np.stack([xs - wx, ys - hy], -1), np.stack([xs + wx, ys - hy], -1),
                         np.stack([xs + wx, ys + hy], -1), np.stack([xs - wx, ys + hy], -1)],
                        axis=1)

    pt = np.hypot(t.px, t.py)
    with np.errstate(divide="ignore", invalid="ignore"):
        values = {"|p_t|": pt, "px": t.px, "py": t.py, "pn": t.pn,
                  "|p_t|/pn": np.where(inside, pt / t.pn, np.nan),
                  "slip": t.slip.astype(float)}[quantity]
    name, scale, unit = TRACTION_QUANTITIES[quantity]
    if quantity == "slip":
        cmap_used, vmin, vmax = ListedColormap(["#9ecae1", "#fc9272"]), 0.0, 1.0
    else:
        cmap_used, vmin, vmax = cmap, None, None
    if quantity in ("px", "py"):
        top = float(np.nanmax(np.abs(values[inside]))) * scale or 1.0
        cmap_used, vmin, vmax = ("RdBu_r" if cmap == "viridis" else cmap), -top, top
    cells = PolyCollection(boxes(inside), array=values[inside] * scale, cmap=cmap_used,
                           edgecolors="face", linewidths=0.2, label="elements")
    cells.set_clim(vmin, vmax)
    ax.add_collection(cells)

    handles = []
    if show_slip:
        slip = inside & t.slip
        if np.any(slip):
            hatch = PolyCollection(boxes(slip), facecolors="none", edgecolors="0.15",
                                   linewidths=0.0, hatch="////", label="slip area")
            ax.add_collection(hatch)
        # element edges with adhesion on one side and slip (or nothing) on the other
        adh = inside & ~t.slip
        segs = []
        ny, nx = t.x.shape
        for j in range(ny):
            for i in range(nx):
                if not adh[j, i]:
                    continue
                x0, x1 = X[j, i] - hx[j, i], X[j, i] + hx[j, i]
                y0, y1 = Y[j, i] - hy, Y[j, i] + hy
                if i + 1 < nx and slip[j, i + 1]:
                    segs.append([(x1, y0), (x1, y1)])
                if i > 0 and slip[j, i - 1]:
                    segs.append([(x0, y0), (x0, y1)])
                if j + 1 < ny and slip[j + 1, i]:
                    segs.append([(max(x0, X[j + 1, i] - hx[j + 1, i]), y1),
                                 (min(x1, X[j + 1, i] + hx[j + 1, i]), y1)])
                if j > 0 and slip[j - 1, i]:
                    segs.append([(max(x0, X[j - 1, i] - hx[j - 1, i]), y0),
                                 (min(x1, X[j - 1, i] + hx[j - 1, i]), y0)])
        ax.add_collection(LineCollection(segs, colors="k", linewidths=1.6,
                                         label="adhesion/slip boundary"))
        handles = [Patch(facecolor="white", edgecolor="0.3", label="adhesion"),
                   Patch(facecolor="white", edgecolor="0.3", hatch="////", label="slip")]
    if arrows:
        ny, nx = t.x.shape
        sj, si = max(1, -(-ny // 16)), max(1, -(-nx // 16))
        sub = np.zeros_like(inside)
        sub[sj // 2::sj, si // 2::si] = True
        sub &= inside
        ax.quiver(X[sub], Y[sub], t.px[sub], t.py[sub], color="k", width=0.004,
                  pivot="mid", label="tractions")
    ax.autoscale_view()
    ax.set_aspect("equal")
    ax.set_xlabel("x, rolling direction [mm]")
    ax.set_ylabel("y, lateral [mm]")
    if title:
        pct = 100.0 * np.sum(t.area[inside & t.slip]) / np.sum(t.area[inside])
        fx, fy, mz = (0.0 if abs(v) < 1e-9 else v for v in (t.fx, t.fy, t.mz))
        ax.set_title(f"{name}: fx = {fx / 1e3:.3g} kN, fy = {fy / 1e3:.3g} kN, "
                     f"mz = {mz:.3g} N m\nslip area {pct:.0f} %", fontsize=9)
    if handles:
        ax.legend(handles=handles, loc="upper right", fontsize=8, framealpha=0.85)
    if quantity != "slip" and (colorbar or (colorbar is None and made)):
        fig.colorbar(cells, ax=ax, label=f"{name} [{unit}]", shrink=0.85)
    return ax


# ------------------------------------------------------------------ the rig run

def _check_result(func, res):
    from .rig.result import RigResult
    if not isinstance(res, RigResult):
        raise RollerRigError(f"{func}: res must be a RigResult from rr.simulate, got "
                             f"{type(res).__name__}")
    return res


def _drive_sense(res):
    """(+1, "braking") or (-1, "traction"): the sign that makes the
    recorded creepage cx (Kalker's sign: > 0 braking) the controller's
    positive creepage, and -fx (fx on the wheel: < 0 braking) the force the
    drive works against."""
    mode = res.params.get("scenario", {}).get("drive_mode", "braking")
    return (-1, "traction") if mode == "traction" else (1, "braking")


def rig_history(res, axes=None, *, title=True):
    """The seed paper's Fig. 7: creepage (contact model, encoder estimate,
    target) and the roller and wheel surface speeds against time, two panels
    sharing the time axis.  The creepage is drawn in the drive's sense, as
    the targets are: cx (Kalker's sign) when braking, -cx when driving.
    axes: None or two axes.  Returns the two axes (creepage: 3 lines;
    speeds: 2 lines)."""
    func = "rig_history"
    _check_result(func, res)
    fig, (ax1, ax2), made = _many_axes(func, axes, 2, (8, 6.4), sharex=True)
    sense, mode = _drive_sense(res)
    cx = "cx" if sense > 0 else "-cx"
    t = res.time
    ax1.plot(t, sense * res.creepage, lw=0.8, label=f"creepage {cx} (contact model, mean of "
             "both wheels)")
    ax1.plot(t, res.xi_est, lw=0.6, alpha=0.7, label="estimate from the encoders (eq. 16)")
    ax1.step(t, res.xi_ref, where="post", color="k", lw=1.0, ls="--", label="target")
    ax1.set_ylabel(f"longitudinal creepage {cx} [-]")
    ax1.legend(fontsize=8, loc="upper right")
    ax1.grid(alpha=0.3)
    ax2.plot(t, res.roller_speed, label="roller surface speed")
    ax2.plot(t, res.wheelset_speed, label="wheel surface speed")
    ax2.set_xlabel("time [s]")
    ax2.set_ylabel("surface speed [m/s]")
    ax2.legend(fontsize=8, loc="lower right")
    ax2.grid(alpha=0.3)
    if title and made:
        mu0 = res.params["scenario"]["mu0"]
        sign = "> 0 when braking" if sense > 0 else "cx < 0 when driving"
        fig.suptitle(f"{mode.capitalize()} under creepage control (mu0 = {mu0}, dt = "
                     f"{res.dt * 1e3:g} ms, {res.method or 'creep model'}): paper Fig. 7\n"
                     f"creepage {cx} \u2248 {'' if sense > 0 else '-'}(roller \u2212 wheel "
                     f"surface speed) / mean speed ({sign})", fontsize=9.5)
        fig.tight_layout()
    return np.array([ax1, ax2], dtype=object)


def rig_force(res, ax=None, *, title=True):
    """The seed paper's Fig. 8: the longitudinal creep force of both wheels
    against time, in the sense the drive works against (braking: -fx, since
    fx on the wheel is < 0 when braking; driving: fx), with the friction
    limit mu0 N (N both wheels' normal loads; each wheel's own mu0 where the
    adhesion changes, which is then drawn against time on a second y axis,
    ax.mu_axis).  Returns the axes (2 lines)."""
    func = "rig_force"
    _check_result(func, res)
    fig, ax, made = _one_axes(func, ax, (8, 3.6))
    sense, mode = _drive_sense(res)
    fx = "-fx" if sense > 0 else "fx"
    t = res.time
    mu0 = res.params["scenario"]["mu0"]
    force = -sense * res.fx
    limit = res.mu_left * res.normal_load_left + res.mu_right * res.normal_load_right
    mus = np.concatenate([res.mu_left, res.mu_right])
    mus = mus[np.isfinite(mus)]
    changing = mus.size > 0 and np.ptp(mus) > 0
    ax.plot(t, force, lw=0.8, label=f"{mode} force {fx} on the wheels (both)")
    ax.plot(t, limit, color="k", ls=":",
            label="friction limit mu0 N (each wheel's mu0 in time, N its normal load)"
            if changing else f"friction limit mu0 N (mu0 = {mu0:g}, N both normal loads)")
    if changing:
        ax.mu_axis = ax.twinx()
        ax.mu_axis.plot(t, res.mu_left, color="tab:green", lw=0.8, alpha=0.7,
                        label="mu0 at the left contact")
        if np.any(res.mu_right != res.mu_left):
            ax.mu_axis.plot(t, res.mu_right, color="tab:olive", lw=0.8, alpha=0.7,
                            label="mu0 at the right contact")
        ax.mu_axis.set_ylabel("friction coefficient mu0 [-]")
        ax.mu_axis.set_ylim(0.0, 1.1 * np.max(mus))
        ax.mu_axis.legend(fontsize=8, loc="upper right")
    ax.set_xlabel("time [s]")
    ax.set_ylabel(f"{mode} force {fx} [N]")
    shown = np.concatenate([force[np.isfinite(force)], limit[np.isfinite(limit)]])
    if shown.size and np.max(shown) > 0:         # the whole curve, also past the limit
        ax.set_ylim(min(0.0, 1.1 * np.min(shown)), 1.1 * np.max(shown))
    ax.legend(fontsize=8, loc="lower right")
    ax.grid(alpha=0.3)
    if title:
        sign = "fx < 0 on the wheel when braking" if sense > 0 else \
            "fx > 0 on the wheel when driving"
        ax.set_title(f"Longitudinal creep force {fx} ({sign}) and its limit mu0 N "
                     f"(paper Fig. 8)", fontsize=9)
    if made:
        fig.tight_layout()
    return ax


def plot_run(res, outdir, prefix="rig"):
    """Write <prefix>_creepage.png (Fig. 7) and <prefix>_force.png (Fig. 8)
    for RigResult `res` into outdir (created if needed); returns the paths.
    Each goes to a new path or replaces a regular file (never a symbolic
    link, a device or a FIFO: RollerRigError naming it, checked for both
    before either is drawn)."""
    plt = _pyplot()          # the backend is the caller's (rollerrig simulate: Agg)
    from ._files import check_output, make_folder, write_file

    _check_result("plot_run", res)
    make_folder(outdir, what="plot_run: outdir")
    paths = {n: check_output(os.path.join(outdir, f"{prefix}_{n}.png"), what="plot_run:")
             for n in ("creepage", "force")}
    for name, draw in (("creepage", lambda: rig_history(res)[0].figure),
                       ("force", lambda: rig_force(res).figure)):
        fig = draw()
        try:
            write_file(paths[name], lambda fh: fig.savefig(fh, format="png", dpi=130),
                       what="plot_run:", binary=True)
        finally:
            plt.close(fig)
    return list(paths.values())


# ------------------------------------------------------------------ profiles

def _shifts(func, y_ws):
    try:
        y = np.atleast_1d(np.asarray(y_ws, dtype=float))
    except (TypeError, ValueError):
        raise RollerRigError(f"{func}: y_ws must be numbers [m], got {y_ws!r:.60}") from None
    if y.ndim != 1 or y.size == 0 or not np.all(np.isfinite(y)):
        raise RollerRigError(f"{func}: y_ws must be finite numbers [m], got {y_ws!r:.60}")
    return y


def profiles(geometry, y_ws=(0.0, 0.002, 0.004, 0.006), ax=None, *, side="left",
             wheels=True, window=None, legend=True):
    """Wheel and roller profiles of one side, the wheel placed by
    rr.wheelset_contact at each lateral shift y_ws [m] (+: the wheelset to
    the left), and its contact point marked.

    Drawn in the plane of the axle: horizontal the roller's own profile
    coordinate (rig Y measured outward from the roller profile's origin),
    vertical the rig Z (up, 0 = the nominal roller top), in mm.  side:
    "left" or "right"; wheels: draw the wheel at every shift (True), at
    none (False), or at those listed; window: (x0, x1, z0, z1) in mm
    (default: around the contact points).  Returns the axes: the roller
    line (label "roller"), then per shift a wheel line (when drawn) and a
    contact marker labelled with the shift and contact angle; shifts
    without contact are marked "no contact" in the legend only."""
    func = "profiles"
    from .geometry.wheelset import RigGeometry, wheelset_contact
    if not isinstance(geometry, RigGeometry):
        raise RollerRigError(f"{func}: geometry must be a RigGeometry, got "
                             f"{type(geometry).__name__}")
    if side not in ("left", "right"):
        raise RollerRigError(f"{func}: side must be 'left' or 'right', got {side!r}")
    shifts = _shifts(func, y_ws)
    if wheels is True:
        drawn = set(range(shifts.size))
    elif wheels is False or wheels is None:
        drawn = set()
    else:
        want = _shifts(func, wheels)
        drawn = {i for i, s in enumerate(shifts) if np.any(np.isclose(s, want, atol=1e-9))}
    if window is not None:
        window = tuple(float(v) for v in window)
        if len(window) != 4:
            raise RollerRigError(f"{func}: window must be (x0, x1, z0, z1) in mm")
    c = wheelset_contact(geometry, shifts, errors="ignore")
    sgn = 1.0 if side == "left" else -1.0
    cs = c.left if side == "left" else c.right
    wheel = geometry.wheel if side == "left" else (geometry.wheel_right or geometry.wheel)
    roller = geometry.roller if side == "left" else (geometry.roller_right or geometry.roller)
    _, ax, _ = _one_axes(func, ax, (7, 4.6))
    colours = [f"C{k % 10}" for k in range(shifts.size)]

    rx, rz = roller.y / MM, -roller.z / MM
    ok = c.status >= 0
    px = (sgn * cs.y - geometry.roller_y) / MM
    pz = cs.z / MM
    s = wheel.y
    Yl, Zl = sgn * (geometry.wheel_y + s), -geometry.wheel_radius - wheel.z
    curves = {}
    for i in range(shifts.size):
        if ok[i] and (i in drawn or window is None):
            co, sn = np.cos(c.roll[i]), np.sin(c.roll[i])
            wy = c.y_ws[i] + Yl * co - Zl * sn
            wz = c.z[i] + Yl * sn + Zl * co
            curves[i] = ((sgn * wy - geometry.roller_y) / MM, wz / MM)
    if window is None:                 # the contact points, the flanges and the roller head
        if curves:
            flange = min(x[np.argmin(z)] for x, z in curves.values())
            lo = min(np.nanmin(px[ok]) - 30.0, flange - 8.0)
            hi = np.nanmax(px[ok]) + 35.0
            zlo = min(np.min(z[(x >= lo) & (x <= hi)]) for x, z in curves.values())
        else:
            lo, hi, zlo = rx.min() - 5.0, rx.max() + 5.0, np.min(rz)
        sel = (rx >= lo) & (rx <= hi)
        top = max(np.nanmax(pz[ok]) if np.any(ok) else 0.0,
                  np.max(rz[sel]) if np.any(sel) else 0.0)
        window = (lo, hi, min(zlo, -10.0) - 4.0, top + 10.0)
    ax.fill_between(rx, rz, window[2], color="0.88", lw=0)
    ax.plot(rx, rz, "k-", lw=1.3, label="roller")
    for i in sorted(curves):
        if i in drawn:
            ax.plot(*curves[i], "-", color=colours[i], lw=1.3)
    for i, dy in enumerate(shifts):
        if not ok[i]:
            ax.plot([], [], "x", color=colours[i], label=f"y_ws = {dy / MM:+g} mm: no contact")
            continue
        label = (f"y_ws = {dy / MM:+g} mm: contact angle {np.degrees(cs.delta[i]):.1f} deg"
                 + (", 2-point" if cs.two_point[i] else ""))
        ax.plot(px[i], pz[i], "o", ms=7, mfc=colours[i], mec="k", mew=0.6, zorder=5,
                label=label)
    ax.set(xlim=window[:2], ylim=window[2:], aspect="equal",
           xlabel=f"lateral, outward from the roller profile origin [mm] ({side} side)",
           ylabel="Z, up from the nominal roller top [mm]")
    ax.grid(alpha=0.3)
    if legend:
        ax.legend(loc="lower right", fontsize=7, framealpha=0.9)
    return ax


# ------------------------------------------------------------------ error maps

def _map_grid(result, spin, quantity, reduce, ellipticity):
    """(angles, magnitudes, values[n_mag, n_ang]) of one spin level."""
    t = result.cases
    err = result.error if quantity == "force" else result.mz_error
    sel = t.spin == spin
    if ellipticity is not None:
        sel &= t.a_over_b == ellipticity
    angles, magnitudes = np.unique(t.angle), np.unique(t.magnitude)
    ia = np.searchsorted(angles, t.angle[sel])
    im = np.searchsorted(magnitudes, t.magnitude[sel])
    stack = np.full((magnitudes.size, angles.size, np.unique(t.a_over_b).size), np.nan)
    count = np.zeros((magnitudes.size, angles.size), dtype=int)
    for i, j, e in zip(im, ia, err[sel]):
        stack[i, j, count[i, j]] = e
        count[i, j] += 1
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)      # all-NaN cells stay NaN
        values = {"max": np.nanmax, "median": np.nanmedian, "mean": np.nanmean}[reduce](
            stack, axis=2)
    return angles, magnitudes, values


def _error_stats(err):
    """{"median", "p95", "max"} of the finite errors (NaN: the method failed there)."""
    good = err[np.isfinite(err)]
    if good.size == 0:
        return dict(median=np.nan, p95=np.nan, max=np.nan)
    return dict(median=float(np.median(good)), p95=float(np.percentile(good, 95)),
                max=float(np.max(good)))


def error_map(result, ax=None, *, spin=None, quantity="force", reduce="max",
              ellipticity=None, vmax=None, cmap="viridis", colorbar=None, title=True):
    """Draw a ScoreResult's error (rollerrig.analysis.reference.score) over the creepage
    direction / magnitude plane.

    One panel per spin level (ax None: a new figure; or a sequence of as many
    axes), or the one level `spin` on the axes `ax`.  x: the direction of
    the creepage atan2(cy, cx) in degrees; y: its normalised magnitude (one
    row per table value, not to scale).  Each cell shows the error of the
    5 ellipticities reduced by `reduce` ("max", "median" or "mean"), or of
    the one a/b `ellipticity`.  quantity: "force" (|dF|/(mu N)) or "mz"
    (|dMz|/(mu N cp)).  vmax: top of the colour scale (default the largest
    value drawn).  colorbar: add one (default: when a figure is made here).
    Returns the axes (an array for several panels).
    """
    func = "error_map"
    from .analysis.reference import ScoreResult
    if not isinstance(result, ScoreResult):
        raise RollerRigError(f"{func}: result must be a ScoreResult from "
                             f"rollerrig.analysis.reference.score(), got {type(result).__name__}")
    if quantity not in ("force", "mz"):
        raise RollerRigError(f"{func}: quantity must be 'force' or 'mz', got {quantity!r}")
    if reduce not in ("max", "median", "mean"):
        raise RollerRigError(f"{func}: reduce must be 'max', 'median' or 'mean', "
                             f"got {reduce!r}")
    t = result.cases
    levels = [float(v) for v in np.unique(t.spin)]
    if ellipticity is not None and float(ellipticity) not in set(t.a_over_b.tolist()):
        raise RollerRigError(f"{func}: ellipticity must be one of "
                             f"{sorted(set(t.a_over_b.tolist()))}, got {ellipticity!r}")
    if spin is not None:
        if float(spin) not in levels:
            raise RollerRigError(f"{func}: spin must be one of {levels}, got {spin!r}")
        levels = [float(spin)]
    made = ax is None
    if made:
        fig, axes = _pyplot().subplots(1, len(levels), figsize=(2.6 * len(levels) + 1.2, 4.4),
                                 sharey=True, squeeze=False, constrained_layout=True)
        axes = axes[0]
    else:
        axes = np.atleast_1d(np.asarray(ax, dtype=object)).ravel()
        if axes.size != len(levels):
            raise RollerRigError(f"{func}: {len(levels)} spin level(s) to draw but "
                                 f"{axes.size} axes given; pass spin= for one panel")
        fig = axes[0].figure
    grids = [_map_grid(result, s, quantity, reduce, ellipticity) for s in levels]
    top = vmax if vmax is not None else max(np.nanmax(g[2]) for g in grids)
    mesh = None
    for axi, s, (angles, magnitudes, values) in zip(axes, levels, grids):
        deg = np.degrees(angles)
        step = deg[1] - deg[0] if deg.size > 1 else 30.0
        xe = np.concatenate([deg - step / 2, [deg[-1] + step / 2]])
        ye = np.arange(magnitudes.size + 1) - 0.5
        mesh = axi.pcolormesh(xe, ye, values, cmap=cmap, vmin=0.0, vmax=top, shading="flat")
        axi.set_xticks(deg[::max(1, deg.size // 4)] if deg.size > 7 else deg)
        axi.set_xticklabels([f"{d:.0f}" for d in axi.get_xticks()])
        show = [i for i, m in enumerate(magnitudes) if m in (0, 0.5, 1.1, 2, 3, 5, 8, 12)] \
            or list(range(0, magnitudes.size, 3))
        axi.set_yticks(show)
        axi.set_yticklabels([f"{magnitudes[i]:g}" for i in show])
        axi.set_xlabel("creepage direction [deg]")
        if title:
            sel = t.spin == s
            if ellipticity is not None:
                sel = sel & (t.a_over_b == float(ellipticity))
            e = (result.error if quantity == "force" else result.mz_error)[sel]
            st = _error_stats(e)
            axi.set_title(f"spin {s:g}: median {st['median']:.3f}\n"
                          f"p95 {st['p95']:.3f}, max {st['max']:.3f}", fontsize=9)
    if made or axes[0].get_subplotspec() is None or axes[0].get_subplotspec().is_first_col():
        axes[0].set_ylabel("creepage magnitude (normalised)")
    if colorbar or (colorbar is None and made):
        what = "|dF| / (mu N)" if quantity == "force" else "|dMz| / (mu N cp)"
        how = f"a/b = {ellipticity:g}" if ellipticity is not None else f"{reduce} over a/b"
        fig.colorbar(mesh, ax=list(axes), label=f"{what}, {how}", shrink=0.9)
    if made and title:
        fig.suptitle(f"{result.label} against CONTACT's exact theory", fontsize=10)
    return axes[0] if len(axes) == 1 else axes


# ------------------------------------------------------------------ fits

def fit(result, cx, force, ax=None, *, mu=None, N=None, residuals=False, label=None,
        xscale=None):
    """A FitResult of fit_polach / fit_modified_fastsim over its data.

    cx, force: the data fitted (one curve, or lists of curves, one per
    speed of the fit).  The data as markers, the fitted model as a line on a
    fine grid over the data's range, drawn as adhesion (the sign that makes
    it positive).  N: normalise by N (default the fit's N; mu too: by mu N).
    residuals: add a second panel with model - data (then ax is None or two
    axes, and two axes are returned).  Returns the axes: per curve one data
    line and one model line."""
    func = "fit"
    from .analysis.fit import PARAMETER_UNITS, FitResult
    if not isinstance(result, FitResult):
        raise RollerRigError(f"{func}: result must be a FitResult from fit_polach or "
                             f"fit_modified_fastsim, got {type(result).__name__}")
    many = isinstance(cx, (list, tuple)) and len(cx) > 0 and np.ndim(cx[0]) == 1
    cxs = [_real_1d(func, "cx", c) for c in (cx if many else [cx])]
    fs = [_real_1d(func, "force", f) for f in (force if many else [force])]
    speeds = result.settings.get("speeds", ())
    if len(cxs) != len(fs) or len(cxs) != len(speeds):
        raise RollerRigError(f"{func}: the fit had {len(speeds)} curve(s) (speeds "
                             f"{list(speeds)}); got {len(cxs)} cx and {len(fs)} force arrays")
    for c, f in zip(cxs, fs):
        if c.size != f.size:
            raise RollerRigError(f"{func}: {c.size} creepages but {f.size} forces")
    allc, allf = np.concatenate(cxs), np.concatenate(fs)
    sign = -1 if float(np.nansum(allf * np.sign(allc))) < 0 else 1
    div, norm = _scale(func, mu, result.settings["N"] if N is None else N)
    if residuals:
        fig, axs, made = _many_axes(func, ax, 2, (6.4, 6.2), sharex=True,
                                    gridspec_kw=dict(height_ratios=[2, 1]))
        main, rax = axs
    else:
        fig, main, made = _one_axes(func, ax, (6.4, 4.2))
    xs = _xscale(allc, xscale)
    p = result.params
    shown = ", ".join(f"{k} {p[k]:.3g}" + ("" if PARAMETER_UNITS[k] == "1" else
                                          f" {PARAMETER_UNITS[k]}") for k in result.fitted)
    for k, (c, f, v) in enumerate(zip(cxs, fs, speeds)):
        colour = f"C{k % 10}"
        at = f", {v:g} m/s" if len(speeds) > 1 else ""
        if xs == "log":
            pos = c[c > 0]
            grid = np.geomspace(pos.min(), pos.max(), 300)
        else:
            grid = np.linspace(np.nanmin(c), np.nanmax(c), 300)
        main.plot(c, sign * f / div, "o", color=colour if many else "k", ms=4,
                  label=f"data{at}", zorder=3)
        main.plot(grid, sign * result.predict(grid, speed=v) / div, "-", color=colour,
                  lw=1.6, label=(label or f"{result.model} fit: {shown}") + at)
        if residuals:
            r = sign * (result.predict(c, speed=v) - f) / div
            rax.plot(c, r, "o-", color=colour, ms=3.5, lw=0.8,
                     label=f"RMS {np.sqrt(np.mean(r ** 2)):.3g}{at}")
    main.set_xscale(xs)
    main.set_ylabel(_ylabel("fx", sign, norm))
    main.grid(alpha=0.3, which="both", lw=0.5)
    main.legend(fontsize=7.5, loc="best")
    if residuals:
        rax.axhline(0.0, color="0.5", lw=0.8)
        rax.set_xscale(xs)
        rax.set_xlabel("longitudinal creepage cx")
        rax.set_ylabel("model - data" + (f" / {norm}" if norm else " [N]"))
        rax.grid(alpha=0.3, which="both", lw=0.5)
        rax.legend(fontsize=7.5, loc="best")
        if made:
            fig.tight_layout()
        return np.array([main, rax], dtype=object)
    main.set_xlabel("longitudinal creepage cx")
    return main
