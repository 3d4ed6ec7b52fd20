"""rollerrig.plot's error maps (a method against the exact cases) and fits."""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable, Dict, Optional, Sequence, Tuple, Union, cast

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from ..analysis.fit import FitResult
    from ..analysis.reference import ScoreResult

import warnings

import numpy as np
import numpy.typing as npt

from .._errors import RollerRigError
from .._typing import F64Array
from ._base import AxesArray, _many_axes, _one_axes, _pyplot, _real_1d, _scale, _xscale, _ylabel


# ------------------------------------------------------------------ error maps

def _map_grid(result: ScoreResult, spin: float, quantity: str, reduce: str,
              ellipticity: Optional[float]) -> Tuple[F64Array, F64Array, F64Array]:
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
    reducers: Dict[str, Callable[..., F64Array]] = {
        "max": np.nanmax, "median": np.nanmedian, "mean": np.nanmean}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)      # all-NaN cells stay NaN
        values = reducers[reduce](stack, axis=2)
    return angles, magnitudes, values


def _error_stats(err: F64Array) -> Dict[str, float]:
    """{"median", "p95", "max"} of the finite errors (NaN: the method failed there)."""
    good = err[np.isfinite(err)]
    if good.size == 0:
        return dict(median=np.nan, p95=np.nan, max=np.nan)
    return dict(median=float(np.median(good)), p95=float(np.percentile(good, 95)),
                max=float(np.max(good)))


def error_map(result: ScoreResult, ax: Any = None, *, spin: Optional[float] = None,
              quantity: str = "force", reduce: str = "max", ellipticity: Optional[float] = None,
              vmax: Optional[float] = None, cmap: str = "viridis",
              colorbar: Optional[bool] = None, title: bool = True) -> Any:
    """Draw a ScoreResult's error over the creepage direction / magnitude plane.

    One panel per spin level, or the one level `spin`.  x: the direction of
    the creepage atan2(cy, cx) in degrees; y: its normalised magnitude (one
    row per table value, not to scale).

    Parameters
    ----------
    result : ScoreResult
        From rollerrig.analysis.reference.score.
    ax : matplotlib.axes.Axes or sequence of Axes, optional
        None: a new figure; or a sequence of as many axes as panels; with
        `spin`, the axes for that level.
    spin : float, optional
        The one spin level drawn.
    quantity : {"force", "mz"}, optional
        "force" (``|dF|/(mu N)``) or "mz" (``|dMz|/(mu N cp)``).
    reduce : {"max", "median", "mean"}, optional
        How each cell reduces the errors of the 5 ellipticities.
    ellipticity : float, optional
        The one a/b drawn instead.
    vmax : float, optional
        Top of the colour scale (default the largest value drawn).
    cmap : str, optional
        The colour map.
    colorbar : bool, optional
        Add one (default: when a figure is made here).
    title : bool, optional
        A title per panel (its statistics) and, on a figure made here, one
        naming the method.

    Returns
    -------
    matplotlib.axes.Axes or ndarray of Axes
        The axes (an array for several panels).

    Raises
    ------
    RollerRigError
        For bad input (naming the argument).

    Examples
    --------
    >>> import rollerrig as rr
    >>> import rollerrig.plot as rp
    >>> axes = rp.error_map(rr.reference.score("fastsim", nx=10, ny=10))
    >>> axes.shape                          # one panel per spin level
    (4,)
    """
    func = "error_map"
    from ..analysis.reference import ScoreResult
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

def fit(result: FitResult, cx: Union[npt.ArrayLike, Sequence[npt.ArrayLike]],
        force: Union[npt.ArrayLike, Sequence[npt.ArrayLike]], ax: Any = None, *,
        mu: Optional[float] = None, N: Optional[float] = None, residuals: bool = False,
        label: Optional[str] = None, xscale: Optional[str] = None) -> Union[Axes, AxesArray]:
    """A FitResult of fit_polach / fit_modified_fastsim over its data.

    The data as markers, the fitted model as a line on a fine grid over the
    data's range, drawn as adhesion (the sign that makes it positive).

    Parameters
    ----------
    result : FitResult
        The fit.
    cx, force : array_like or list of array_like
        The data fitted (one curve, or lists of curves, one per speed of the
        fit): creepage [-], force [N].
    ax : matplotlib.axes.Axes or sequence of 2 Axes, optional
        None: a new figure; two axes with residuals=True.
    mu, N : float, optional
        N: normalise by N [N] (default the fit's N; mu too: by mu N).
    residuals : bool, optional
        Add a second panel with model - data.
    label : str, optional
        The model lines' label.
    xscale : {"log", "linear", None}, optional
        As for creep_curve.

    Returns
    -------
    matplotlib.axes.Axes or ndarray of Axes
        Per curve one data line and one model line; two axes with
        residuals=True.

    Raises
    ------
    RollerRigError
        For bad input (naming the argument).
    """
    func = "fit"
    from ..analysis.fit import PARAMETER_UNITS, FitResult
    if not isinstance(result, FitResult):
        raise RollerRigError(f"{func}: result must be a FitResult from fit_polach or "
                             f"fit_modified_fastsim, got {type(result).__name__}")
    many = isinstance(cx, (list, tuple)) and len(cx) > 0 and np.ndim(cx[0]) == 1
    cxs = [_real_1d(func, "cx", c)
           for c in (cx if many and isinstance(cx, (list, tuple)) else [cx])]
    # many: force is a list of curves as cx is (a sequence, as documented)
    fs = [_real_1d(func, "force", f)
          for f in (cast(Sequence[npt.ArrayLike], force) if many else [force])]
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
    main: Axes
    rax: Axes
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
        from matplotlib.figure import Figure
        if made and isinstance(fig, Figure):      # made here: a Figure
            fig.tight_layout()
        return np.array([main, rax], dtype=object)
    main.set_xlabel("longitudinal creepage cx")
    return main
