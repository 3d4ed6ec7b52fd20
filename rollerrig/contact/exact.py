"""Kalker's exact theory of steady rolling contact, one case with its fields.

The forces of many Hertzian cases come from rollerrig.creep_forces(...,
method="exact", nx=, ny=) like every other method; this module gives the
whole solution of one case (pressure, tractions, slip velocities, the
adhesion and slip areas), for any undeformed distance h(x, y) as well as the
Hertzian one, and the Richardson extrapolation of the forces to the
continuum from two grids.

The solver (csrc/contact/rr_exact.c) discretises the potential contact area
into rectangular elements of constant traction, as CONTACT does: the normal
problem by conjugate gradients on the active set (NormCG), the tangential
problem of steady rolling (the material derivative as the upwind difference
over one element) by a semismooth Newton method with GMRES, every product
with the half-space's influence coefficients by FFT.  Forces act on the
wheel (body 1); conventions as rollerrig.contact.creep.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Dict, List, Mapping, Optional, Tuple

import numpy as np
import numpy.typing as npt

from .. import _core
from .._binding import (METHODS, Blame, _as_float, check_creep_options, creep_blame,
                        creep_options, swap_blame, used_numbers)
from .._errors import RollerRigError, check_status
from .creep import CreepForces, TractionField, _case

__all__ = ["ExactSolution", "exact_field", "exact_solve", "exact_richardson"]


@dataclass(frozen=True)
class ExactSolution(TractionField):
    """One case solved by the exact theory, as :func:`exact_field` and
    :func:`exact_solve` return it.

    A :class:`TractionField` (x, y, pn, px, py, slip, area; fx, fy [N], mz
    [N m] on the wheel about the reference point; status) with arrays of
    shape (my, mx), rows at increasing y, columns along increasing x (the
    leading edge, where the material enters, is the last column), and the
    fields below that the exact theory adds.
    """

    #: longitudinal slip velocity over the rolling speed [-], 0 in adhesion
    sx: npt.NDArray[np.float64]
    sy: npt.NDArray[np.float64]  #: lateral slip velocity over the rolling speed [-], 0 in adhesion
    contact: npt.NDArray[np.bool_]  #: True where the element carries pressure
    fn: float           #: normal force found [N]
    delta: float        #: approach [m]
    contact_area: float  #: area of the elements in contact [m^2]
    pmax: float         #: peak pressure [Pa]
    products: Tuple[float, float]  #: FFT products (normal, tangential)
    newton_steps: int   #: Newton steps of the tangential problem
    residuals: Tuple[float, float]  #: final relative residuals (normal, tangential)


def _edge(contact: npt.NDArray[np.bool_]) -> str:
    """Where a contact area (boolean (my, mx)) reaches the grid's edge: the
    sides it touches, as words ("" if none)."""
    sides = (("the first column", contact[:, 0]), ("the last column", contact[:, -1]),
             ("the first row", contact[0]), ("the last row", contact[-1]))
    return ", ".join(name for name, c in sides if c.any())


def _solution(func: str, out: Tuple[Any, ...], args: Mapping[str, npt.NDArray[np.float64]],
              blame: Optional[Blame], edge_ok: bool = False) -> ExactSolution:
    """The ExactSolution of _core.exact_solve's or exact_field's output;
    RollerRigError for an error status (naming the arguments blame(0,
    status) gives: check_status), or (unless edge_ok) for a contact that
    reaches the grid's edge: the grid then cut the contact area off, and the
    solution is not that of the gap given (rig_exact takes it to size a
    larger grid)."""
    status, _, grid, r, pn, px, py, sx, sy, state = out
    mx, my, dx, dy, x0, y0 = grid
    check_status(func, np.array(status, dtype=np.int8), args, "raise", blame)
    edge = _edge(state >= 0)
    if edge and not edge_ok:
        raise RollerRigError(f"{func}: the contact reaches the grid's edge ({edge} of a "
                             f"{my} x {mx} grid): the solution is cut off there, not that of "
                             f"the gap; give h on a grid that holds the contact area with at "
                             f"least one element of margin on every side")
    x = np.broadcast_to(x0 + dx * np.arange(mx), (my, mx))
    y = np.broadcast_to((y0 + dy * np.arange(my))[:, None], (my, mx))
    fx, fy, mz, fn, delta, carea, pmax, _nc, _ns, pn_prod, pt_prod, newton, rn, rt = r
    return ExactSolution(x=x, y=y, pn=pn, px=px, py=py, slip=state == 1,
                         area=np.full((my, mx), dx * dy), sx=sx, sy=sy, contact=state >= 0,
                         fx=fx, fy=fy, mz=mz, fn=fn, delta=delta, contact_area=carea,
                         pmax=pmax, products=(pn_prod, pt_prod), newton_steps=newton,
                         residuals=(rn, rt), status=status)


def exact_field(cx: float, cy: float = 0.0, cphi: float = 0.0, *, a: float, b: float, N: float,
                mu: float, G: float = 8.2e10, nu: float = 0.28, nx: Optional[int] = None,
                ny: Optional[int] = None, tol: Optional[float] = None,
                maxit: Optional[int] = None, spin_shift: Optional[float] = None) -> ExactSolution:
    """The exact solution of one Hertzian case, with its fields.

    Parameters
    ----------
    cx, cy, cphi, a, b, N, mu, G, nu
        As for :func:`creep_forces` [-, -, rad/m, m, m, N, -, Pa, -]:
        scalars; Coulomb friction.
    nx, ny : int, optional
        Elements across the ellipse's 2a and 2b (the grid adds 2 on each
        side); None: the option's default.
    tol, maxit, spin_shift : optional
        The other options of method "exact"
        (``rollerrig.METHODS["exact"].options``); None: their defaults.

    Returns
    -------
    ExactSolution
        The fields (pressure, tractions, slip velocities, adhesion and slip
        areas) and totals of the case (:class:`ExactSolution`).

    Raises
    ------
    RollerRigError
        For an invalid case, naming the argument and its value (as
        creep_forces with errors="raise"), an option out of range, or array
        inputs (one case at a time).

    See Also
    --------
    exact_solve : the same for any undeformed distance on a grid.
    creep_forces : method="exact" gives the forces of many cases.
    exact_richardson : the forces extrapolated to the continuum.

    Examples
    --------
    >>> import rollerrig as rr
    >>> s = rr.exact_field(2e-4, a=6e-3, b=4e-3, N=1e4, mu=0.3, nx=15, ny=15)
    >>> s.pn.shape
    (19, 19)
    >>> print(f"fx = {s.fx:.1f} N, fn = {s.fn:.1f} N")
    fx = -1580.1 N, fn = 10000.0 N
    """
    func = "exact_field"
    options = {k: v for k, v in dict(nx=nx, ny=ny, tol=tol, maxit=maxit,
                                     spin_shift=spin_shift).items() if v is not None}
    opts = creep_options(func, "exact", options)
    shape, scalar, full, flat = _case(func, cx, cy, cphi, a, b, N, mu, G, nu, 0.0, None, "exact")
    if not scalar:
        raise RollerRigError(f"{func}: one case at a time; got inputs of shape {shape}")
    full.update(used_numbers("exact", options))
    return _solution(func, _core.exact_field(opts, *flat), full, creep_blame(opts, flat))


def exact_solve(h: npt.ArrayLike, *, dx: float, dy: float, N: float, mu: float, G: float = 8.2e10,
                nu: float = 0.28, cx: float = 0.0, cy: float = 0.0, cphi: float = 0.0,
                x0: Optional[float] = None, y0: Optional[float] = None,
                tol: Optional[float] = None, maxit: Optional[int] = None,
                spin_shift: Optional[float] = None) -> ExactSolution:
    """The exact solution for any undeformed distance h on a grid.

    Parameters
    ----------
    h : array_like, shape (my, mx)
        The gap between the undeformed surfaces at the element centres [m]
        (any constant offset; the approach is solved for); its lowest
        region must lie inside, with at least one element of margin on
        every side of the contact area.  At most 1024 elements a side (the
        solver's limit).
    dx, dy : float
        Element size [m], > 0 (the area dx dy a normal double, the ratio
        within 1e6).
    N : float
        Normal load [N].
    mu : float
        Coulomb friction coefficient [-].
    G : float, optional
        Combined shear modulus [Pa].
    nu : float, optional
        Combined Poisson ratio [-].
    cx, cy : float, optional
        Creepages [-].
    cphi : float, optional
        Spin [rad/m].
    x0, y0 : float, optional
        The centre of element (0, 0) relative to the reference point (the
        spin's centre and Mz's origin) [m]; default: the grid's centre.
    tol, maxit, spin_shift : optional
        As the options of method "exact"
        (``rollerrig.METHODS["exact"].options``); None: their defaults.

    Returns
    -------
    ExactSolution
        The solution on the grid of h (:class:`ExactSolution`).

    Raises
    ------
    RollerRigError
        Naming the argument and its value: h not a 2-D array of real
        numbers or too large, dx, dy not valid element sizes, a number not
        a scalar, an option out of range, an invalid case (as creep_forces);
        and a contact that reaches the grid's edge (the grid would have cut
        it off).

    See Also
    --------
    rollerrig.undeformed_distance : h of a wheel on its roller.
    exact_field : the Hertzian case, its grid built for it.

    Examples
    --------
    A Hertzian gap (A = 2.5 /m, B = 1/0.6 /m) on a 25 x 25 grid:

    >>> import numpy as np
    >>> import rollerrig as rr
    >>> x = np.linspace(-2e-3, 2e-3, 25)
    >>> y = np.linspace(-2.4e-3, 2.4e-3, 25)
    >>> X, Y = np.meshgrid(x, y)
    >>> s = rr.exact_solve(2.5 * X**2 + Y**2 / 0.6, dx=x[1] - x[0], dy=y[1] - y[0],
    ...                    N=5e3, mu=0.3, cx=5e-4)
    >>> print(f"fx = {s.fx:.1f} N, pmax = {s.pmax / 1e6:.0f} MPa")
    fx = -590.3 N, pmax = 596 MPa
    """
    return _exact_solve("exact_solve", h, dict(dx=dx, dy=dy, N=N, mu=mu, G=G, nu=nu, cx=cx,
                                               cy=cy, cphi=cphi, x0=x0, y0=y0),
                        dict(tol=tol, maxit=maxit, spin_shift=spin_shift))


def _exact_solve(func: str, h: npt.ArrayLike, numbers: Mapping[str, object],
                 options: Mapping[str, object], edge_ok: bool = False) -> ExactSolution:
    """exact_solve's work: numbers, options as its arguments (x0, y0 None: the
    grid centred); edge_ok: a contact at the grid's edge returned, not
    refused (rig_exact, which sizes a larger grid from it)."""
    h_arr = _as_float(func, "h", h)
    if h_arr.ndim != 2:
        raise RollerRigError(f"{func}: h must be a 2-D array (my, mx), got shape {h_arr.shape}")
    my, mx = h_arr.shape
    if mx > _core.EXACT_MAX_GRID or my > _core.EXACT_MAX_GRID:
        raise RollerRigError(f"{func}: h must have at most {_core.EXACT_MAX_GRID} elements a "
                             f"side, got shape {h_arr.shape}")
    # the options by the registry's rules (their names, ranges, integers only)
    options = {k: v for k, v in options.items() if v is not None}
    opts = creep_options(func, "exact", options)
    full: Dict[str, npt.NDArray[np.float64]] = {}
    for k, v in numbers.items():
        if v is None:
            continue
        arr = _as_float(func, k, v)
        if arr.size != 1:
            raise RollerRigError(f"{func}: {k} must be a number, got shape {arr.shape}")
        full[k] = arr.reshape(())
    dx, dy = float(full["dx"]), float(full["dy"])
    for k, d in (("dx", dx), ("dy", dy)):
        if not (d > 0.0 and np.isfinite(d)):
            raise RollerRigError(f"{func}: {k} must be a positive element size [m], got {d!r}")
    with np.errstate(all="ignore"):
        # the solver's limits (rr_exact.h): the element and its area normal
        # doubles, its sides within a factor 1e6
        bad = not (min(dx, dy) >= np.finfo(float).tiny and dx * dy >= np.finfo(float).tiny
                   and np.isfinite(dx * dy) and 1e-6 <= dx / dy <= 1e6)
    if bad:
        raise RollerRigError(f"{func}: dx, dy must be element sizes [m] whose area dx dy is a "
                             f"normal double and whose ratio is within 1e6, got dx = {dx!r}, "
                             f"dy = {dy!r}")
    x0 = float(full["x0"]) if "x0" in full else -0.5 * (mx - 1) * dx
    y0 = float(full["y0"]) if "y0" in full else -0.5 * (my - 1) * dy
    full.update(used_numbers("exact", options))
    names = ("dx", "dy", "x0", "y0", "N", "mu", "G", "nu", "cx", "cy", "cphi")
    case = dict(full, x0=x0, y0=y0)
    out = _core.exact_solve(opts, h_arr, *(float(case[n]) for n in names))

    def status_of(*values: float) -> int:
        return int(_core.exact_solve(opts, h_arr, *values)[0])
    # a valid case on this grid, whose values replace the failed one's one at
    # a time where the C core's report names no argument (a result out of
    # range: swap_blame); the element's own size and the grid centred
    valid = dict(dx=dx, dy=dy, x0=-0.5 * (mx - 1) * dx, y0=-0.5 * (my - 1) * dy, N=1e4,
                 mu=0.3, G=8.2e10, nu=0.28, cx=0.0, cy=0.0, cphi=0.0)
    swapped = swap_blame(status_of, [np.asarray(float(case[n])) for n in names], list(names),
                         valid)
    blamed = out[1]
    return _solution(func, out, full,
                     lambda i, code: [blamed] if blamed else swapped(i, code), edge_ok)


def exact_richardson(cx: npt.ArrayLike, cy: npt.ArrayLike = 0.0, cphi: npt.ArrayLike = 0.0, *,
                     a: npt.ArrayLike, b: npt.ArrayLike, N: npt.ArrayLike, mu: npt.ArrayLike,
                     G: npt.ArrayLike = 8.2e10, nu: npt.ArrayLike = 0.28, nx: int = 27,
                     ny: Optional[int] = None,
                     **options: Any) -> Tuple[CreepForces, CreepForces]:
    """The continuum estimate of the exact forces from two grids.

    Parameters
    ----------
    cx, cy, cphi, a, b, N, mu, G, nu
        As for :func:`creep_forces` [-, -, rad/m, m, m, N, -, Pa, -]; arrays
        broadcast.
    nx : int, optional
        Elements across the ellipse's 2a on the coarse grid, at most half
        the method's largest (the fine grid has 2 nx).
    ny : int, optional
        Elements across 2b on the coarse grid; None: nx.
    **options
        The other options of method "exact" (and ``errors``), as for
        creep_forces; checked with nx, ny before either grid is solved.

    Returns
    -------
    forces : CreepForces
        The continuum estimate 2 F2 - F1 (fx, fy [N], mz [N m], status: the
        lower of the two grids').
    error : CreepForces
        The error estimate ``|F2 - F1|`` in the same fields.

    Raises
    ------
    RollerRigError
        For a ``method`` argument, nx or ny beyond half the method's
        largest, a bad option, and as creep_forces for the cases.

    See Also
    --------
    creep_forces : method="exact" on one grid.

    Notes
    -----
    The discretisation error of the forces is of first order in the element
    size (the upwind difference of steady rolling), so with F1 on nx x ny
    and F2 on 2nx x 2ny elements across the ellipse the continuum value is
    about 2 F2 - F1, with the error estimate ``|F2 - F1|`` (the size of the
    correction itself: an upper bound where the convergence is monotone).

    Examples
    --------
    >>> import rollerrig as rr
    >>> f, err = rr.exact_richardson(2e-4, a=6e-3, b=4e-3, N=1e4, mu=0.3, nx=9)
    >>> print(f"fx = {f.fx:.0f} N +- {err.fx:.0f} N")
    fx = -1491 N +- 82 N
    """
    from .creep import creep_forces
    func = "exact_richardson"
    ny = nx if ny is None else ny
    if "method" in options:
        raise RollerRigError(f"{func}: the method is the exact theory's, got "
                             f"method={options['method']!r:.60}")
    info = METHODS["exact"]
    check_creep_options(func, "exact", dict({k: v for k, v in options.items()
                                             if k in info.options}, nx=nx, ny=ny))
    for name, n in (("nx", nx), ("ny", ny)):
        most = int(info.options[name].hi or 0)     # (an int option: hi is a number)
        if 2 * n > most:
            raise RollerRigError(f"{func}: {name} must be at most {most // 2} (the fine grid "
                                 f"has 2 {name} = {2 * n} elements, the method at most "
                                 f"{most}), got {n!r}")
    kw = dict(a=a, b=b, N=N, mu=mu, G=G, nu=nu, method="exact", **options)
    f1 = creep_forces(cx, cy, cphi, nx=nx, ny=ny, **kw)
    f2 = creep_forces(cx, cy, cphi, nx=2 * nx, ny=2 * ny, **kw)
    status = np.minimum(np.asarray(f1.status), np.asarray(f2.status))
    est: List[Any] = [2.0 * g - f for f, g in zip(f1[:3], f2[:3])]
    err: List[Any] = [np.abs(g - f) for f, g in zip(f1[:3], f2[:3])]
    st: Any = status
    if np.ndim(status) == 0:
        st = int(status)
        est = [float(v) for v in est]
        err = [float(v) for v in err]
    return (CreepForces(est[0], est[1], est[2], st),
            CreepForces(err[0], err[1], err[2], st))
