"""rollerrig.plot's creep curves and traction fields."""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Mapping, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

from .._errors import RollerRigError
from .._typing import F64Array
from ._base import (MM, TRACTION_QUANTITIES, _one_axes, _real_1d, _scale, _sign, _xscale,
                    _ylabel)

if TYPE_CHECKING:                      # matplotlib is imported on use only
    from matplotlib.axes import Axes

    from ..analysis.reference import CreepCurve
    from ..contact.creep import CreepForces, TractionField

#: a force as the creep-curve functions take it: values [N] or a CreepForces
Force = Union["npt.ArrayLike", "CreepForces"]
#: a reference curve: a CreepCurve or (cx, force[, label])
Reference = Union["CreepCurve", Tuple[Any, ...]]


# ------------------------------------------------------------------ creep curves

_COMPONENTS = ("fx", "fy", "|f|")


def _force_values(func: str, force: object, component: str, n: int) -> F64Array:
    from ..contact.creep import CreepForces
    if component not in _COMPONENTS:
        raise RollerRigError(f"{func}: component must be one of {_COMPONENTS}, "
                             f"got {component!r}")
    vals: npt.NDArray[Any]
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


def creep_curve(cx: npt.ArrayLike, force: Force, *, ax: Optional[Axes] = None,
                label: Optional[str] = None, mu: Optional[float] = None,
                N: Optional[float] = None, sign: int = -1, component: str = "fx",
                xscale: Optional[str] = None, **line_kw: Any) -> Axes:
    """One creep curve: sign * force / (mu N) against the creepage cx.

    Parameters
    ----------
    cx : array_like
        Creepages [-], one per force.
    force : array_like or CreepForces
        Forces [N], one per cx, or a CreepForces (its `component`).
    ax : matplotlib.axes.Axes, optional
        The axes to draw on; None: a new figure.
    label : str, optional
        The line's label.
    mu, N : float, optional
        Normalise by mu N (N alone: by N [N]; neither: the force in N).
    sign : {-1, 1}, optional
        -1 (default) draws -fx, the adhesion on the wheel.
    component : {"fx", "fy", "|f|"}, optional
        The component of a CreepForces.
    xscale : {"log", "linear", None}, optional
        None: log when every cx > 0.
    **line_kw
        Passed to Axes.plot.

    Returns
    -------
    matplotlib.axes.Axes
        The axes, one line added.  On axes that already hold lines, the
        scale and the axis labels are left as they are.

    Raises
    ------
    RollerRigError
        For bad input (naming the argument).

    Examples
    --------
    >>> import numpy as np
    >>> import rollerrig as rr
    >>> import rollerrig.plot as rp
    >>> cx = np.geomspace(1e-5, 1e-2, 30)
    >>> f = rr.creep_forces(cx, a=6e-3, b=4e-3, N=1e4, mu=0.3, nx=10, ny=10)
    >>> ax = rp.creep_curve(cx, f, mu=0.3, N=1e4, label="fastsim")
    >>> ax.get_xscale(), ax.get_ylabel()
    ('log', '-fx / (mu N)')
    """
    func = "creep_curve"
    x = _real_1d(func, "cx", cx)
    sign = _sign(func, sign)
    vals = _force_values(func, force, component, x.size)
    div, norm = _scale(func, mu, N)
    _, axes, _ = _one_axes(func, ax, (6, 4))
    fresh = not axes.get_lines()     # keep the scale and labels of axes drawn on before
    axes.plot(x, sign * vals / div, label=label, **line_kw)
    if fresh:
        axes.set_xscale(_xscale(x, xscale))
        axes.set_xlabel("longitudinal creepage cx" if component == "fx" else "creepage")
        axes.set_ylabel(_ylabel(component, sign, norm))
    if label is not None:
        axes.legend(fontsize=8)
    return axes


def _reference_points(func: str, reference: object) -> Tuple[
        F64Array, F64Array, str, Optional[float], Optional[float]]:
    """(cx, fx [N], label, mu, N) of a reference curve."""
    from ..analysis.reference import CreepCurve
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


def creep_curves(cx: npt.ArrayLike, curves: Union[Mapping[Any, Force], Force], *,
                 mu: Optional[float] = None, N: Optional[float] = None,
                 reference: Optional[Reference] = None, ax: Optional[Axes] = None,
                 sign: int = -1, component: str = "fx", xscale: Optional[str] = None,
                 title: Optional[str] = None) -> Axes:
    """Several creep curves on one axes, optionally over reference points.

    Parameters
    ----------
    cx : array_like
        Creepages [-].
    curves : dict or array_like or CreepForces
        {label: force} (arrays [N] or CreepForces, one value per cx) or a
        single force.
    mu, N, sign, component, xscale, ax
        As for :func:`creep_curve`.
    reference : CreepCurve or tuple, optional
        A rollerrig.analysis.reference.CreepCurve (e.g.
        rr.reference.creep_curves()[1], CONTACT's exact theory) or a tuple
        (cx, force[, label]), drawn as black markers; a CreepCurve also
        supplies mu and N when they are not given.
    title : str, optional
        The axes' title.

    Returns
    -------
    matplotlib.axes.Axes
        One line per curve (in order), then one for the reference; a
        legend when there are labels.

    Raises
    ------
    RollerRigError
        For bad input (naming the argument).
    """
    func = "creep_curves"
    x = _real_1d(func, "cx", cx)
    by_label: Mapping[Any, object] = curves if isinstance(curves, dict) else {None: curves}
    if not by_label:
        raise RollerRigError(f"{func}: curves is empty")
    ref = _reference_points(func, reference) if reference is not None else None
    if ref is not None and mu is None and N is None and ref[3] is not None:
        mu, N = ref[3], ref[4]
    sign = _sign(func, sign)
    div, norm = _scale(func, mu, N)
    values = {label: _force_values(func, f, component, x.size)
              for label, f in by_label.items()}
    _, axes, _ = _one_axes(func, ax, (6.4, 4.2))
    for k, (label, vals) in enumerate(values.items()):
        axes.plot(x, sign * vals / div, _STYLES[k % len(_STYLES)], lw=1.4,
                label=None if label is None else str(label))
    if ref is not None:
        axes.plot(ref[0], sign * ref[1] / div, "ko", ms=4, label=ref[2], zorder=3)
    axes.set_xscale(_xscale(x, xscale))
    axes.set_xlabel("longitudinal creepage cx" if component == "fx" else "creepage")
    axes.set_ylabel(_ylabel(component, sign, norm))
    if norm == "(mu N)":             # |F| <= mu N: clip the linear theory's straight line
        shown = sign * np.concatenate(list(values.values())) / div
        lo, hi = float(np.nanmin(shown)), float(np.nanmax(shown))
        axes.set_ylim(min(0.0, 1.08 * lo) if lo > -1.2 else -1.2,
                      max(0.0, 1.08 * hi) if hi < 1.2 else 1.2)
    axes.grid(alpha=0.3, which="both", lw=0.5)
    if title:
        axes.set_title(title, fontsize=10)
    if any(line.get_label() and not str(line.get_label()).startswith("_")
           for line in axes.get_lines()):
        axes.legend(fontsize=8, loc="best")
    return axes


# ------------------------------------------------------------------ traction field

def _cell_sizes(t: TractionField) -> Tuple[F64Array, float]:
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


def traction_field(t: TractionField, ax: Optional[Axes] = None, *, quantity: str = "|p_t|",
                   show_slip: bool = True, arrows: bool = True,
                   colorbar: Optional[bool] = None, cmap: str = "viridis",
                   title: bool = True) -> Axes:
    """A traction field element by element.

    Parameters
    ----------
    t : TractionField or ExactSolution
        FASTSIM's (rr.fastsim_field) or the exact theory's (rr.exact_field,
        rr.exact_solve).
    ax : matplotlib.axes.Axes, optional
        None: a new figure.
    quantity : str, optional
        One of TRACTION_QUANTITIES, the elements' colour ("slip": blue
        adhesion, red slip).
    show_slip : bool, optional
        Hatch the elements that slip and outline the adhesion/slip boundary.
    arrows : bool, optional
        The tangential tractions (quiver, at most ~16 per direction).
    colorbar : bool, optional
        Add one (default: when a figure is made here).
    cmap : str, optional
        The colour map.
    title : bool, optional
        The forces in the title.

    Returns
    -------
    matplotlib.axes.Axes
        x, y in mm, with the collections in this order: the elements (label
        "elements"), then with show_slip the slip hatch ("slip area", when
        any element slips) and the boundary ("adhesion/slip boundary"), then
        the arrows ("tractions").

    Raises
    ------
    RollerRigError
        For bad input (naming the argument).

    Examples
    --------
    >>> import rollerrig as rr
    >>> import rollerrig.plot as rp
    >>> t = rr.fastsim_field(2e-4, a=6e-3, b=4e-3, N=1e4, mu=0.3, nx=10, ny=10)
    >>> ax = rp.traction_field(t)
    >>> [c.get_label() for c in ax.collections]
    ['elements', 'slip area', 'adhesion/slip boundary', 'tractions']
    """
    func = "traction_field"
    from ..contact.creep import TractionField
    if not isinstance(t, TractionField):
        raise RollerRigError(f"{func}: t must be a TractionField (rr.fastsim_field, "
                             f"rr.exact_field), got "
                             f"{type(t).__name__}")
    if quantity not in TRACTION_QUANTITIES:
        raise RollerRigError(f"{func}: quantity must be one of {list(TRACTION_QUANTITIES)}, "
                             f"got {quantity!r}")
    fig, axes, made = _one_axes(func, ax, (5.8, 5.2))
    from matplotlib.collections import LineCollection, PolyCollection
    from matplotlib.colors import Colormap, ListedColormap
    from matplotlib.patches import Patch

    inside = t.pn > 0
    if not np.any(inside):
        raise RollerRigError(f"{func}: no element carries pressure")
    dx, dy = _cell_sizes(t)
    X, Y = t.x / MM, t.y / MM
    hx, hy = dx / MM / 2, dy / MM / 2

    def boxes(mask: npt.NDArray[np.bool_]) -> F64Array:
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
    cmap_used: Union[str, Colormap]
    vmin: Optional[float]
    vmax: Optional[float]
    if quantity == "slip":
        cmap_used, vmin, vmax = ListedColormap(["#9ecae1", "#fc9272"]), 0.0, 1.0
    else:
        cmap_used, vmin, vmax = cmap, None, None
    if quantity in ("px", "py"):
        top = float(np.nanmax(np.abs(values[inside]))) * scale or 1.0
        cmap_used, vmin, vmax = ("RdBu_r" if cmap == "viridis" else cmap), -top, top
    # (matplotlib's stubs want a sequence of polygons: an (n, 4, 2) array is one)
    cells = PolyCollection(boxes(inside),  # type: ignore[arg-type]
                           array=values[inside] * scale, cmap=cmap_used,
                           edgecolors="face", linewidths=0.2, label="elements")
    cells.set_clim(vmin, vmax)
    axes.add_collection(cells)

    handles = []
    if show_slip:
        slip = inside & t.slip
        if np.any(slip):
            hatch = PolyCollection(boxes(slip),  # type: ignore[arg-type]
                                   facecolors="none", edgecolors="0.15",
                                   linewidths=0.0, hatch="////", label="slip area")
            axes.add_collection(hatch)
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
        axes.add_collection(LineCollection(segs, colors="k", linewidths=1.6,
                                         label="adhesion/slip boundary"))
        handles = [Patch(facecolor="white", edgecolor="0.3", label="adhesion"),
                   Patch(facecolor="white", edgecolor="0.3", hatch="////", label="slip")]
    if arrows:
        ny, nx = t.x.shape
        sj, si = max(1, -(-ny // 16)), max(1, -(-nx // 16))
        sub = np.zeros_like(inside)
        sub[sj // 2::sj, si // 2::si] = True
        sub &= inside
        axes.quiver(X[sub], Y[sub], t.px[sub], t.py[sub], color="k", width=0.004,
                  pivot="mid", label="tractions")
    axes.autoscale_view()
    axes.set_aspect("equal")
    axes.set_xlabel("x, rolling direction [mm]")
    axes.set_ylabel("y, lateral [mm]")
    if title:
        pct = 100.0 * np.sum(t.area[inside & t.slip]) / np.sum(t.area[inside])
        fx, fy, mz = (0.0 if abs(v) < 1e-9 else v for v in (t.fx, t.fy, t.mz))
        axes.set_title(f"{name}: fx = {fx / 1e3:.3g} kN, fy = {fy / 1e3:.3g} kN, "
                     f"mz = {mz:.3g} N m\nslip area {pct:.0f} %", fontsize=9)
    if handles:
        axes.legend(handles=handles, loc="upper right", fontsize=8, framealpha=0.85)
    if quantity != "slip" and (colorbar or (colorbar is None and made)):
        fig.colorbar(cells, ax=axes, label=f"{name} [{unit}]", shrink=0.85)
    return axes
