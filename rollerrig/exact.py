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
wheel (body 1); conventions as rollerrig.contact.
"""
from dataclasses import dataclass

import numpy as np

from . import _core
from ._binding import _as_float, check_creep_options, used_numbers
from ._errors import RollerRigError, check_status
from .contact import TractionField, _case

__all__ = ["ExactSolution", "exact_field", "exact_solve", "exact_richardson"]


@dataclass(frozen=True)
class ExactSolution(TractionField):
    """One case solved by the exact theory: a TractionField (x, y, pn, px,
    py, slip, area; fx, fy, mz on the wheel [N], [N m] about the reference
    point; status), arrays of shape (my, mx), rows at increasing y, columns
    along increasing x (the leading edge, where the material enters, is the
    last column), and what the exact theory adds:"""

    sx: np.ndarray      #: slip velocity over the rolling speed [-], 0 in adhesion
    sy: np.ndarray
    contact: np.ndarray  #: True where the element carries pressure
    fn: float           #: normal force found [N]
    delta: float        #: approach [m]
    contact_area: float  #: area of the elements in contact [m^2]
    pmax: float         #: peak pressure [Pa]
    products: tuple     #: FFT products (normal, tangential)
    newton_steps: int
    residuals: tuple    #: final relative residuals (normal, tangential)


def _solution(func, grid, out, args):
    mx, my, dx, dy, x0, y0 = grid
    status, r, pn, px, py, sx, sy, state = out
    check_status(func, np.array(status, dtype=np.int8), args, "raise")
    x = np.broadcast_to(x0 + dx * np.arange(mx), (my, mx))
    y = np.broadcast_to((y0 + dy * np.arange(my))[:, None], (my, mx))
    fx, fy, mz, fn, delta, carea, pmax, _nc, _ns, pn_prod, pt_prod, newton, rn, rt = r
    return ExactSolution(x=x, y=y, pn=pn, px=px, py=py, slip=state == 1,
                         area=np.full((my, mx), dx * dy), sx=sx, sy=sy, contact=state >= 0,
                         fx=fx, fy=fy, mz=mz, fn=fn, delta=delta, contact_area=carea,
                         pmax=pmax, products=(pn_prod, pt_prod), newton_steps=newton,
                         residuals=(rn, rt), status=status)


def exact_field(cx, cy=0.0, cphi=0.0, *, a, b, N, mu, G=8.2e10, nu=0.28, nx=None, ny=None,
                tol=None, maxit=None, spin_shift=None):
    """The exact solution of one Hertzian case, with its fields.

    Arguments as rollerrig.creep_forces (scalars; Coulomb friction), and the
    options of method "exact": nx, ny elements across the ellipse's 2a and
    2b (the grid adds 2 on each side), tol, maxit, spin_shift
    (rollerrig.METHODS["exact"].options).  Returns an ExactSolution; an
    invalid case raises RollerRigError.
    """
    func = "exact_field"
    options = {k: v for k, v in dict(nx=nx, ny=ny, tol=tol, maxit=maxit,
                                     spin_shift=spin_shift).items() if v is not None}
    opts = check_creep_options(func, "exact", options)
    shape, scalar, full, flat = _case(func, cx, cy, cphi, a, b, N, mu, G, nu, 0.0, None, "exact")
    if not scalar:
        raise RollerRigError(f"{func}: one case at a time; got inputs of shape {shape}")
    pb = _core.exact_hertz_problem(*flat, **opts)
    full.update(used_numbers("exact", options))
    check_status(func, np.array(pb[0], dtype=np.int8), full, "raise")
    grid = pb[1:7]
    out = _core.exact_solve(*grid, None, *pb[7:])
    return _solution(func, grid, out, full)


def exact_solve(h, *, dx, dy, N, mu, G=8.2e10, nu=0.28, cx=0.0, cy=0.0, cphi=0.0, x0=None,
                y0=None, tol=1e-6, maxit=5000, spin_shift=1.0 / 6.0):
    """The exact solution for any undeformed distance h on a grid.

    h:       array (my, mx): the gap between the undeformed surfaces at the
             element centres [m] (any constant offset; the approach is
             solved for); its lowest region must lie inside, with at least
             one element of margin on every side of the contact area
    dx, dy:  element size [m]; x0, y0: the centre of element (0, 0) relative
             to the reference point (the spin's centre and Mz's origin;
             default: the grid's centre)
    N:       normal load [N]; mu: Coulomb friction; G [Pa], nu: material
    cx, cy, cphi: creepages [-], [-], [rad/m]
    tol, maxit, spin_shift: as the options of method "exact"
    Returns an ExactSolution.
    """
    func = "exact_solve"
    h = _as_float(func, "h", h)
    if h.ndim != 2:
        raise RollerRigError(f"{func}: h must be a 2-D array (my, mx), got shape {h.shape}")
    my, mx = h.shape
    named = dict(dx=dx, dy=dy, N=N, mu=mu, G=G, nu=nu, cx=cx, cy=cy, cphi=cphi, tol=tol,
                 spin_shift=spin_shift)
    full = {}
    for k, v in named.items():
        arr = _as_float(func, k, v)
        if arr.size != 1:
            raise RollerRigError(f"{func}: {k} must be a number, got shape {arr.shape}")
        full[k] = arr.reshape(())
    if not isinstance(maxit, (int, np.integer)) or maxit < 1:
        raise RollerRigError(f"{func}: maxit must be a positive integer, got {maxit!r}")
    if x0 is None:
        x0 = -0.5 * (mx - 1) * float(full["dx"])
    if y0 is None:
        y0 = -0.5 * (my - 1) * float(full["dy"])
    grid = (mx, my, float(full["dx"]), float(full["dy"]), float(x0), float(y0))
    out = _core.exact_solve(*grid, h, 1.0, 1.0, float(full["N"]), float(full["G"]),
                            float(full["nu"]), float(full["mu"]), float(full["cx"]),
                            float(full["cy"]), float(full["cphi"]), float(full["spin_shift"]),
                            float(full["tol"]), int(maxit))
    return _solution(func, grid, out, full)


def exact_richardson(cx, cy=0.0, cphi=0.0, *, a, b, N, mu, G=8.2e10, nu=0.28, nx=27,
                     ny=None, **options):
    """The continuum estimate of the exact forces from two grids.

    The discretisation error of the forces is of first order in the element
    size (the upwind difference of steady rolling), so with F1 on nx x ny
    and F2 on 2nx x 2ny elements across the ellipse the continuum value is
    about 2 F2 - F1, with the error estimate |F2 - F1| (the size of the
    correction itself: an upper bound where the convergence is monotone).
    Arguments as creep_forces (arrays broadcast) with method "exact".
    Returns (forces, error): two CreepForces-like tuples (fx, fy, mz, status).
    """
    from .contact import CreepForces, creep_forces
    ny = nx if ny is None else ny
    kw = dict(a=a, b=b, N=N, mu=mu, G=G, nu=nu, method="exact", **options)
    f1 = creep_forces(cx, cy, cphi, nx=nx, ny=ny, **kw)
    f2 = creep_forces(cx, cy, cphi, nx=2 * nx, ny=2 * ny, **kw)
    status = np.minimum(np.asarray(f1.status), np.asarray(f2.status))
    est = [2.0 * g - f for f, g in zip(f1[:3], f2[:3])]
    err = [np.abs(g - f) for f, g in zip(f1[:3], f2[:3])]
    if np.ndim(status) == 0:
        status = int(status)
        est = [float(v) for v in est]
        err = [float(v) for v in err]
    return CreepForces(*est, status), CreepForces(*err, status)
