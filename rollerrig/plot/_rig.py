"""rollerrig.plot's figures of a rig run (the seed paper's Fig. 7 and 8) and of
the profiles in contact."""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, List, Mapping, Optional, Sequence, Tuple, Union, cast

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from ..geometry.wheelset import RigGeometry
    from ..rig.result import RigResult

import os
import textwrap

import numpy as np
import numpy.typing as npt

from .._errors import RollerRigError
from .._typing import F64Array
from ._base import MM, AxesArray, _many_axes, _one_axes, _pyplot


# ------------------------------------------------------------------ the rig run

def _check_result(func: str, res: object) -> RigResult:
    from ..rig.result import RigResult
    if not isinstance(res, RigResult):
        raise RollerRigError(f"{func}: res must be a RigResult from rr.simulate, got "
                             f"{type(res).__name__}")
    return res


def _drive_sense(res: RigResult) -> Tuple[int, str]:
    """(+1, "braking") or (-1, "traction"): the sign that makes the
    recorded creepage cx (Kalker's sign: > 0 braking) the controller's
    positive creepage, and -fx (fx on the wheel: < 0 braking) the force the
    drive works against."""
    mode = res.params.get("scenario", {}).get("drive_mode", "braking")
    return (-1, "traction") if mode == "traction" else (1, "braking")


def rig_history(res: RigResult, axes: Optional[Sequence[Axes]] = None, *,
                title: bool = True) -> AxesArray:
    """The seed paper's Fig. 7: creepage and surface speeds against time.

    Two panels sharing the time axis: the creepage (contact model, encoder
    estimate, target) and the roller and wheel surface speeds.  The
    creepage is drawn in the drive's sense, as the targets are: cx (Kalker's
    sign) when braking, -cx when driving.

    Parameters
    ----------
    res : RigResult
        A run of rr.simulate.
    axes : sequence of 2 matplotlib.axes.Axes, optional
        None: a new figure.
    title : bool, optional
        A figure title (the drive mode, mu0, dt) when the figure is made
        here.

    Returns
    -------
    ndarray of matplotlib.axes.Axes
        The two axes (creepage: 3 lines; speeds: 2 lines).

    Raises
    ------
    RollerRigError
        For res not a RigResult, or axes not two Axes.

    Examples
    --------
    >>> import rollerrig as rr
    >>> import rollerrig.plot as rp
    >>> res = rr.simulate(duration=1.0, targets=[0.02], target_times=[0.0], progress=False)
    >>> top, bottom = rp.rig_history(res)
    >>> len(top.lines), len(bottom.lines)
    (3, 2)
    """
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
        from matplotlib.figure import Figure
        if isinstance(fig, Figure):                # made here: a Figure
            fig.tight_layout()
    return np.array([ax1, ax2], dtype=object)


def friction_law_text(params: Mapping[str, Mapping[str, Any]]) -> str:
    """The friction law of a run's parameters in words, with its values.

    The caption of rig_force's adhesion panel: Polach's falling law or
    Coulomb, and the adhesion schedule when the run has one.

    Parameters
    ----------
    params : dict
        A run's parameters (RigResult.params: "scenario", "contact",
        "adhesion").

    Returns
    -------
    str
        E.g. "Coulomb friction, mu0 = 0.4".

    Examples
    --------
    >>> import rollerrig as rr
    >>> import rollerrig.plot as rp
    >>> rp.friction_law_text(rr.default_parameters())[:26]
    "Polach's falling friction "
    """
    scen, contact = params.get("scenario", {}), params.get("contact", {})
    adhesion = params.get("adhesion", {})
    mu0 = scen.get("mu0")
    if contact.get("friction_law", "polach_falling") == "coulomb":
        text = f"Coulomb friction, mu0 = {mu0:g}"
    else:
        text = (f"Polach's falling friction mu(w) = mu0 ((1 - A) exp(-B w) + A), w the slip "
                f"speed: mu0 = {mu0:g}, A = {contact.get('polach_A'):g}, "
                f"B = {contact.get('polach_B_s_per_m'):g} s/m")
    if adhesion.get("schedule_times_s"):
        text += "; mu0 (and A, B) from the adhesion schedule"
    return text


def _adhesion_limits(t: F64Array, mu: F64Array) -> Optional[Tuple[float, float]]:
    """A y range that shows the adhesion's differences between targets:
    the samples after the first tenth of the run (past the start-up), padded."""
    keep = np.isfinite(mu) & (t >= t[0] + 0.1 * (t[-1] - t[0]))
    if not np.any(keep):
        return None
    lo, hi = np.percentile(mu[keep], [1, 100])
    pad = max(0.1 * (hi - lo), 0.002)
    return lo - pad, hi + pad


def rig_force(res: RigResult, ax: Optional[Axes] = None, *, title: bool = True,
              adhesion: Optional[bool] = None) -> Axes:
    """The seed paper's Fig. 8: the longitudinal creep force of both wheels against time.

    Drawn in the sense the drive works against (braking: -fx, since fx on
    the wheel is < 0 when braking; driving: fx), with the friction limit mu0
    N (N both wheels' normal loads; each wheel's own mu0 where the adhesion
    changes, which is then drawn against time on a second y axis,
    ax.mu_axis).

    Parameters
    ----------
    res : RigResult
        A run of rr.simulate.
    ax : matplotlib.axes.Axes, optional
        None: a new figure.
    title : bool, optional
        A title naming the force's sense and its limit.
    adhesion : bool, optional
        A second panel below, ax.adhesion_axis, with the adhesion
        coefficient F / N [1] (the force over both normal loads) on a scale
        that shows the targets' differences, titled with the friction law
        that sets them (:func:`friction_law_text`).  Default: True when ax
        is None.

    Returns
    -------
    matplotlib.axes.Axes
        The force's axes (2 lines), forces in N.

    Raises
    ------
    RollerRigError
        For res not a RigResult, or adhesion=True with an ax given (the
        panels are drawn on a figure of their own).

    Examples
    --------
    >>> import rollerrig as rr
    >>> import rollerrig.plot as rp
    >>> res = rr.simulate(duration=1.0, targets=[0.02], target_times=[0.0], progress=False)
    >>> ax = rp.rig_force(res)
    >>> len(ax.lines), ax.adhesion_axis.get_ylabel()
    (2, 'adhesion F / N [1]')
    """
    func = "rig_force"
    _check_result(func, res)
    if adhesion is None:
        adhesion = ax is None
    if adhesion and ax is None:
        plt = _pyplot()
        fig, (ax, ax_mu) = plt.subplots(2, 1, figsize=(8, 6.2), sharex=True,
                                        gridspec_kw={"height_ratios": [3, 2]})
        made = True
    else:
        fig, ax, made = _one_axes(func, ax, (8, 3.6))
        ax_mu = None
        if adhesion:
            raise RollerRigError(f"{func}: adhesion=True draws its own two panels: pass ax=None")
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
        mu_axis = ax.twinx()
        setattr(ax, "mu_axis", mu_axis)            # an attribute of the axes returned
        mu_axis.plot(t, res.mu_left, color="tab:green", lw=0.8, alpha=0.7,
                     label="mu0 at the left contact")
        if np.any(res.mu_right != res.mu_left):
            mu_axis.plot(t, res.mu_right, color="tab:olive", lw=0.8, alpha=0.7,
                         label="mu0 at the right contact")
        mu_axis.set_ylabel("friction coefficient mu0 [1]")
        mu_axis.set_ylim(0.0, 1.1 * np.max(mus))
        mu_axis.legend(fontsize=8, loc="upper right")
    if ax_mu is None:
        ax.set_xlabel("time [s]")
    ax.set_ylabel(f"{mode} force {fx} [N]")
    shown = np.concatenate([force[np.isfinite(force)], limit[np.isfinite(limit)]])
    if shown.size and np.max(shown) > 0:         # the whole curve, also past the limit
        ax.set_ylim(min(0.0, 1.1 * np.min(shown)), 1.1 * np.max(shown))
    ax.legend(fontsize=8, loc="lower right")
    ax.grid(alpha=0.3)
    if ax_mu is not None:
        with np.errstate(divide="ignore", invalid="ignore"):
            mu = force / res.normal_load
        ax_mu.plot(t, mu, lw=0.8, color="tab:red", label=f"adhesion {fx} / N (N both normal loads)")
        limits = _adhesion_limits(t, mu)
        if limits is not None:
            ax_mu.set_ylim(*limits)
        for target, start in zip(res.targets, res.target_times):    # which target set it
            ax_mu.annotate(f"target {target:g}", (start, 0.97), xycoords=("data", "axes fraction"),
                           fontsize=7, va="top", color="0.3")
        ax_mu.set_xlabel("time [s]")
        ax_mu.set_ylabel("adhesion F / N [1]")
        ax_mu.grid(alpha=0.3)
        ax_mu.legend(fontsize=8, loc="lower right")
        ax_mu.set_title(textwrap.fill(friction_law_text(res.params), 125), fontsize=8.5)
        setattr(ax, "adhesion_axis", ax_mu)        # an attribute of the axes returned
    if title:
        sign = "fx < 0 on the wheel when braking" if sense > 0 else \
            "fx > 0 on the wheel when driving"
        ax.set_title(f"Longitudinal creep force {fx} ({sign}) and its limit mu0 N "
                     f"(paper Fig. 8)", fontsize=9)
    if made:
        fig.tight_layout()
    return ax


def plot_run(res: RigResult, outdir: Union[str, "os.PathLike[str]"],
             prefix: str = "rig") -> List[str]:
    """Write <prefix>_creepage.png (Fig. 7) and <prefix>_force.png (Fig. 8) of a run.

    Parameters
    ----------
    res : RigResult
        A run of rr.simulate.
    outdir : str or path-like
        The folder (created if needed).
    prefix : str, optional
        The files' prefix.

    Returns
    -------
    list of str
        The two paths.

    Raises
    ------
    RollerRigError
        Each file goes to a new path or replaces a regular file (never a
        symbolic link, a device or a FIFO: RollerRigError naming it, checked
        for both before either is drawn).
    """
    plt = _pyplot()          # the backend is the caller's (rollerrig simulate: Agg)
    from .._files import check_output, make_folder, write_file

    _check_result("plot_run", res)
    make_folder(outdir, what="plot_run: outdir")
    paths = {n: check_output(os.path.join(outdir, f"{prefix}_{n}.png"), what="plot_run:")
             for n in ("creepage", "force")}
    for name, draw in (("creepage", lambda: rig_history(res)[0].figure),
                       ("force", lambda: rig_force(res).figure)):
        fig = cast("Figure", draw())               # made here: a Figure, not a SubFigure
        try:
            write_file(paths[name], lambda fh: fig.savefig(fh, format="png", dpi=130),
                       what="plot_run:", binary=True)
        finally:
            plt.close(fig)
    return list(paths.values())


# ------------------------------------------------------------------ profiles

def _shifts(func: str, y_ws: object) -> F64Array:
    try:
        y = np.atleast_1d(np.asarray(y_ws, dtype=float))
    except (TypeError, ValueError):
        raise RollerRigError(f"{func}: y_ws must be numbers [m], got {y_ws!r:.60}") from None
    if y.ndim != 1 or y.size == 0 or not np.all(np.isfinite(y)):
        raise RollerRigError(f"{func}: y_ws must be finite numbers [m], got {y_ws!r:.60}")
    return y


def profiles(geometry: RigGeometry, y_ws: npt.ArrayLike = (0.0, 0.002, 0.004, 0.006),
             ax: Optional[Axes] = None, *, side: str = "left",
             wheels: Union[bool, npt.ArrayLike] = True,
             window: Optional[Sequence[float]] = None, legend: bool = True) -> Axes:
    """Wheel and roller profiles of one side, the wheel placed at each lateral shift.

    The wheel is placed by rr.wheelset_contact at each lateral shift y_ws
    and its contact point marked.  Drawn in the plane of the axle:
    horizontal the roller's own profile coordinate (rig Y measured outward
    from the roller profile's origin), vertical the rig Z (up, 0 = the
    nominal roller top), in mm.

    Parameters
    ----------
    geometry : RigGeometry
        The profiles and their placement.
    y_ws : float or sequence of float, optional
        Lateral shifts [m] (+: the wheelset to the left).
    ax : matplotlib.axes.Axes, optional
        None: a new figure.
    side : {"left", "right"}, optional
        The side drawn.
    wheels : bool or sequence of float, optional
        Draw the wheel at every shift (True), at none (False), or at those
        listed.
    window : tuple of 4 float, optional
        (x0, x1, z0, z1) in mm (default: around the contact points).
    legend : bool, optional
        Add a legend.

    Returns
    -------
    matplotlib.axes.Axes
        The roller line (label "roller"), then per shift a wheel line (when
        drawn) and a contact marker labelled with the shift and contact
        angle; shifts without contact are marked "no contact" in the legend
        only.

    Raises
    ------
    RollerRigError
        For bad input (naming the argument).

    Examples
    --------
    >>> import rollerrig as rr
    >>> import rollerrig.plot as rp
    >>> ax = rp.profiles(rr.RigGeometry.standard(), y_ws=(0.0, 0.004))
    >>> ax.lines[-1].get_label()
    'y_ws = +4 mm: contact angle 6.2 deg'
    """
    func = "profiles"
    from ..geometry.wheelset import RigGeometry, wheelset_contact
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
