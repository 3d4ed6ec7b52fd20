"""Wheel-roller rolling contact: Hertz, Kalker's coefficients, creep forces.

Every function takes numbers or arrays that broadcast against each other
(numpy rules) and returns arrays of the broadcast shape, or plain floats
when every input was a scalar.  Units are SI (m, N, Pa, rad, s).

Conventions (Kalker's, as in CONTACT): x is the rolling direction, y
lateral; the semi-axis a lies along x, b along y; material enters the patch
at x = +a.  Creepages cx, cy (xi, eta) are the slip of the wheel relative to
the roller or rail divided by the rolling speed; the spin cphi (phi) is in
rad/m, and the rigid slip at (x, y) is (cx - cphi y, cy + cphi x).  Forces
act ON THE WHEEL: for small creepage fx = -G a b C11 cx.  mz is the moment
about the patch centre, the sum of (x py - y px) dA.

Errors: every function takes errors= "raise", "warn" or "ignore".  By
default a call on scalars raises RollerRigError (a ValueError) naming the
argument and its value ("raise"); a call on arrays computes the good
elements, returns NaN with a negative status for the bad ones and gives one
RollerRigWarning ("warn").  Every result carries an int8 `status` per
element: 0 ok; 1 a warning, the result usable (an inner iteration hit its
cap); < 0 an error with NaN results, e.g. -1 an input NaN or infinite, -2 a
load not positive, -3 a semi-axis or curvature not positive, -4 a modulus
or Poisson ratio out of range, -5 friction, -12 inputs so extreme that the
result would not be a finite double.  rollerrig.STATUS maps every code to
its message.
"""
import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from . import _core
from ._errors import RollerRigError, check_status

__all__ = [
    "METHODS", "BOUNDS", "FallingFriction", "HertzContact", "KalkerCoefficients",
    "CreepForces", "TractionField", "hertz", "kalker_coefficients", "creep_forces",
    "fastsim_field",
]

METHODS = {
    "linear": _core.METHOD_LINEAR,
    "fastsim": _core.METHOD_FASTSIM,
    "fastsim_blended": _core.METHOD_FASTSIM_BLENDED,
    "modified_fastsim": _core.METHOD_MODIFIED_FASTSIM,
    "polach": _core.METHOD_POLACH,
}
BOUNDS = {"parabolic": _core.BOUND_PARABOLIC, "elliptic": _core.BOUND_ELLIPTIC}
SLIP_SPEEDS = {"local": _core.SLIP_LOCAL, "rigid": _core.SLIP_RIGID}
GRIDS = {"rect": _core.GRID_RECT, "strips": _core.GRID_STRIPS}


@dataclass(frozen=True)
class FallingFriction:
    """Polach's falling friction mu(w) = mu [(1 - A) exp(-B w) + A].

    mu is the static coefficient given to creep_forces; w the slip speed
    [m/s]; A the ratio of the friction at infinite slip to mu (0 < A <= 1); B the
    decay rate [s/m].  Polach (Wear 258, 2005) fits dry rail with about
    A = 0.4, B = 0.6 s/m.  Falling friction needs the rolling speed.
    """

    A: float = 0.4
    B: float = 0.6

    def mu(self, mu0, w):
        """The friction coefficient at slip speed w for static value mu0."""
        return mu0 * ((1.0 - self.A) * np.exp(-self.B * np.asarray(w, dtype=float)) + self.A)


class HertzContact(NamedTuple):
    a: np.ndarray       #: semi-axis along the rolling direction [m]
    b: np.ndarray       #: lateral semi-axis [m]
    p0: np.ndarray      #: peak pressure [Pa]
    delta: np.ndarray   #: approach of the two bodies [m]
    status: np.ndarray  #: C status per element (0 OK)


class KalkerCoefficients(NamedTuple):
    c11: np.ndarray
    c22: np.ndarray
    c23: np.ndarray
    status: np.ndarray


class CreepForces(NamedTuple):
    fx: np.ndarray      #: longitudinal force on the wheel [N]
    fy: np.ndarray      #: lateral force on the wheel [N]
    mz: np.ndarray      #: spin moment on the wheel [N m]
    status: np.ndarray  #: C status per element (0 OK, > 0 warning, < 0 NaN result)


@dataclass(frozen=True)
class TractionField:
    """The FASTSIM traction field of one case; arrays of shape (ny, nx), rows
    at increasing y, columns along increasing x (the leading edge is the
    last column); elements outside the ellipse have zero pressure."""

    x: np.ndarray      #: element centre, rolling direction [m]
    y: np.ndarray      #: element centre, lateral [m]
    pn: np.ndarray     #: pressure [Pa]
    px: np.ndarray     #: tangential traction on the wheel [Pa]
    py: np.ndarray
    slip: np.ndarray   #: True where the element slips, False where it adheres
    area: np.ndarray   #: element area [m^2]
    fx: float
    fy: float
    mz: float
    status: int


def _as_float(func, name, value):
    arr = np.asarray(value)
    if arr.dtype.kind not in "iuf":
        raise RollerRigError(f"{func}: {name} must be real numbers, got dtype {arr.dtype} "
                             f"({value!r:.60})")
    if arr.size == 0:
        raise RollerRigError(f"{func}: {name} is empty")
    return arr.astype(np.float64, copy=False)


def _broadcast(func, named):
    """Convert, broadcast and flatten the inputs for the binding.

    Returns (shape, scalar, {name: array as given}, [1-D arrays]) where a
    1-element input stays 1 element long (the binding broadcasts it)."""
    arrays = {name: _as_float(func, name, v) for name, v in named.items()}
    try:
        shape = np.broadcast_shapes(*(a.shape for a in arrays.values()))
    except ValueError:
        shapes = ", ".join(f"{n}{a.shape}" for n, a in arrays.items() if a.ndim)
        raise RollerRigError(f"{func}: shapes do not broadcast: {shapes}") from None
    flat = []
    for a in arrays.values():
        if a.size == 1:
            flat.append(a.reshape(1))
        else:
            flat.append(np.ascontiguousarray(np.broadcast_to(a, shape)).reshape(-1))
    scalar = all(a.ndim == 0 for a in arrays.values())
    # broadcast_to only where a shape differs: it costs 5 us an input, most of
    # a scalar call's time (full is read, never written)
    full = {n: a if a.shape == shape else np.broadcast_to(a, shape) for n, a in arrays.items()}
    return shape, scalar, full, flat


def _finish(func, shape, scalar, full, outputs, status, errors):
    if errors is None:
        errors = "raise" if scalar else "warn"
    if errors not in ("raise", "warn", "ignore"):
        raise RollerRigError(f"{func}: errors must be 'raise', 'warn' or 'ignore', "
                             f"got {errors!r}")
    status = status.reshape(shape)
    check_status(func, status, full, errors)
    outs = [o.reshape(shape) for o in outputs]
    if scalar:
        return [float(o) for o in outs] + [int(status)]
    return outs + [status]


def hertz(A, B, N, E=2.1e11, nu=0.28, E2=None, nu2=None, *, errors=None):
    """Hertzian contact ellipse of two elastic bodies.

    A, B:  curvature sums [1/m] in the rolling and lateral direction: the
           gap is h = A x^2 + B y^2, so A = (1/R1x + 1/R2x)/2 (on a roller,
           1/r_wheel + 1/R_roller enters A); the long axis lies along the
           smaller sum.
    N:     normal load [N].
    E, nu: Young's modulus [Pa] and Poisson ratio of the wheel; E2, nu2 of
           the roller (default: the same material).
    errors: "raise", "warn" or "ignore" (module docstring).
    Returns HertzContact(a [m], b [m], p0 [Pa], delta [m], status); a along
    the rolling direction.  Elliptic integrals to machine precision
    (Carlson), the ellipticity solved to full double precision (Johnson
    1985, 4.2).
    """
    E2 = E if E2 is None else E2
    nu2 = nu if nu2 is None else nu2
    named = dict(A=A, B=B, N=N, E=E, nu=nu, E2=E2, nu2=nu2)
    shape, scalar, full, flat = _broadcast("hertz", named)
    a, b, p0, delta, status = _core.hertz(*flat)
    return HertzContact(*_finish("hertz", shape, scalar, full, (a, b, p0, delta), status,
                                 errors))


def kalker_coefficients(a_over_b, nu=0.28, *, errors=None):
    """Kalker's creep coefficients C11, C22, C23 (Kalker 1990, Table E.3).

    Exact at the table's nodes; linear in g = min(a/b, b/a) between them, a
    parabola through 1/C in nu; Kalker's asymptotes below g = 0.1.
    a_over_b: semi-axis along the rolling direction over the lateral one
    (> 0); nu: Poisson ratio, 0 <= nu <= 0.5.  errors: as for hertz.
    Returns KalkerCoefficients(c11, c22, c23, status), dimensionless.
    """
    shape, scalar, full, flat = _broadcast("kalker_coefficients",
                                           dict(a_over_b=a_over_b, nu=nu))
    c11, c22, c23, status = _core.kalker(*flat)
    return KalkerCoefficients(*_finish("kalker_coefficients", shape, scalar, full,
                                       (c11, c22, c23), status, errors))


def _choice(func, name, value, table, none_ok=False):
    """One of a table's names (a str: a list or a dict is not looked up)."""
    if (value is None and none_ok) or (isinstance(value, str) and value in table):
        return
    names = ", ".join(repr(k) for k in table) + (" or None" if none_ok else "")
    raise RollerRigError(f"{func}: {name} must be one of {names}, got {value!r:.60}")


def _options(func, method, nx, ny, bound, grid, slip_speed, k0, alpha_inf, beta, kA, kS):
    _choice(func, "method", method, METHODS)
    _choice(func, "bound", bound, BOUNDS)
    _choice(func, "grid", grid, GRIDS)
    _choice(func, "slip_speed", slip_speed, SLIP_SPEEDS, none_ok=True)
    for name, n in (("nx", nx), ("ny", ny)):
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) \
                or not 1 <= n <= _core.FASTSIM_MAX_GRID:
            raise RollerRigError(f"{func}: {name} must be an integer from 1 to "
                                 f"{_core.FASTSIM_MAX_GRID}, got {n!r}")
    checks = (("k0", k0, 0.0, 1.0, False), ("alpha_inf", alpha_inf, 0.0, 1.0, True),
              ("beta", beta, 0.0, np.inf, True), ("kA", kA, 0.0, 1.0, False),
              ("kS", kS, 0.0, kA, False))
    for name, v, lo, hi, lo_ok in checks:
        try:
            x = float(v) if isinstance(v, (int, float, np.integer, np.floating)) \
                and not isinstance(v, bool) else math.nan
        except OverflowError:                          # an int beyond the doubles
            x = math.nan
        ok = math.isfinite(x) and (x >= lo if lo_ok else x > lo) and x <= hi
        if not ok:
            bracket = "[" if lo_ok else "("
            raise RollerRigError(f"{func}: {name} must be in {bracket}{lo}, {hi}], got {v!r}")
    opts = dict(method=METHODS[method], nx=int(nx), ny=int(ny), bound=BOUNDS[bound],
                grid=GRIDS[grid],
                k0=float(k0), alpha_inf=float(alpha_inf), beta=float(beta), kA=float(kA),
                kS=float(kS))
    if slip_speed is not None:
        opts["slip_speed"] = SLIP_SPEEDS[slip_speed]
    return opts


def _friction(func, friction):
    if friction is None or friction == "coulomb":
        return 1.0, 0.0
    if isinstance(friction, FallingFriction):
        return friction.A, friction.B
    raise RollerRigError(f"{func}: friction must be None, 'coulomb' or a FallingFriction, "
                         f"got {friction!r}")


def creep_forces(cx, cy=0.0, cphi=0.0, *, a, b, N, mu, G=8.2e10, nu=0.28,
                 method="fastsim", nx=30, ny=30, bound="parabolic", grid="rect", speed=0.0,
                 friction=None, slip_speed=None, k0=0.54, alpha_inf=0.02, beta=0.62,
                 kA=1.0, kS=1.0, errors=None):
    """Creep forces and spin moment on the wheel of a Hertzian contact.

    cx, cy:  longitudinal and lateral creepage [-]; cphi: spin [rad/m]
    a, b:    semi-axes [m] (a along the rolling direction); N: load [N]
    mu:      (static) friction coefficient; G [Pa], nu: combined material
    method:  "linear" (Kalker's linear theory), "fastsim" (Kalker 1982, three
             flexibilities), "fastsim_blended" (flexibilities blended from
             three to one, Vollebregt and Voltr 2023), "modified_fastsim"
             (Spiryagin, Polach and Cole 2013: k0, alpha_inf, beta),
             "polach" (Polach 1999/2005 with spin: reduction factors
             0 < kS <= kA <= 1)
    nx, ny:  FASTSIM elements along x per row, and rows (1 to FASTSIM_MAX_GRID)
    bound:   FASTSIM traction bound, "parabolic" (Kalker's) or "elliptic"
    grid:    FASTSIM rows spanning the ellipse's bounding box, outside
             elements empty ("rect", CONTACT's grid) or each row's own chord
             ("strips", Kalker's strips: converges faster in the grid)
    speed:   rolling speed [m/s]; falling friction needs it > 0
    friction: None (Coulomb) or FallingFriction(A, B)
    slip_speed: FASTSIM falling friction at each element's own slip speed
             ("local", the default) or at the rigid slip speed ("rigid",
             the default of modified_fastsim, whose k0, alpha_inf, beta
             were fitted that way)
    errors:  "raise" (default for scalar inputs), "warn" (default for
             arrays) or "ignore" (module docstring)
    Returns CreepForces(fx [N], fy [N], mz [N m], status): forces on the
    wheel, status per element (0 ok, 1 the falling-friction iteration hit
    its cap somewhere, < 0 an error with NaN forces; rollerrig.STATUS).
    Every method but "linear" keeps |(fx, fy)| <= mu N (the static mu).
    The Polach method has no spin moment (mz = 0); the linear theory's spin
    moment uses the simplified theory's C33 (Kalker's C33 is not in our
    table).
    """
    func = "creep_forces"
    opts = _options(func, method, nx, ny, bound, grid, slip_speed, k0, alpha_inf, beta, kA,
                    kS)
    fA, fB = _friction(func, friction)
    named = dict(cx=cx, cy=cy, cphi=cphi, a=a, b=b, N=N, mu=mu, G=G, nu=nu, speed=speed)
    named["friction.A"] = fA
    named["friction.B"] = fB
    shape, scalar, full, flat = _broadcast(func, named)
    fx, fy, mz, status = _core.creep_forces(*flat, **opts)
    # the method's own numbers may explain a failure too (beta = 1e307)
    full.update(_used_numbers(method, opts))
    return CreepForces(*_finish(func, shape, scalar, full, (fx, fy, mz), status, errors))


def _used_numbers(method, opts):
    """The numeric options the method reads, as 0-d arrays for messages."""
    names = {"modified_fastsim": ("k0", "alpha_inf", "beta"), "polach": ("kA", "kS")}
    return {n: np.asarray(opts[n]) for n in names.get(method, ())}


def fastsim_field(cx, cy=0.0, cphi=0.0, *, a, b, N, mu, G=8.2e10, nu=0.28,
                  method="fastsim", nx=30, ny=30, bound="parabolic", grid="rect", speed=0.0,
                  friction=None, slip_speed=None, k0=0.54, alpha_inf=0.02, beta=0.62):
    """The FASTSIM traction field of one case, for plots and checks.

    Arguments as creep_forces (scalars only; method a FASTSIM variant).
    Returns a TractionField with the element centres [m], pressure and
    tractions [Pa], the adhesion/slip map, element areas [m^2] and the
    total forces [N] and moment [N m]; an invalid case raises RollerRigError.
    """
    func = "fastsim_field"
    if method not in ("fastsim", "fastsim_blended", "modified_fastsim"):
        raise RollerRigError(f"{func}: method must be a FASTSIM variant, got {method!r}")
    opts = _options(func, method, nx, ny, bound, grid, slip_speed, k0, alpha_inf, beta, 1.0,
                    1.0)
    del opts["kA"], opts["kS"]
    fA, fB = _friction(func, friction)
    named = dict(cx=cx, cy=cy, cphi=cphi, a=a, b=b, N=N, mu=mu, G=G, nu=nu, speed=speed)
    named["friction.A"] = fA
    named["friction.B"] = fB
    shape, scalar, full, flat = _broadcast(func, named)
    if not scalar:
        raise RollerRigError(f"{func}: one case at a time; got inputs of shape {shape}")
    fx, fy, mz, status, x, y, pn, px, py, slip = _core.fastsim_field(*flat, **opts)
    full.update(_used_numbers(method, opts))
    check_status(func, np.array(status, dtype=np.int8), full, "raise")
    # row j of width 2b/ny has nx elements of length 2 a_j / nx
    yh = -1.0 + (2.0 * np.arange(ny) + 1.0) / ny
    a_j = float(a) * (np.sqrt(1.0 - yh * yh) if grid == "strips" else np.ones(ny))
    area = np.repeat((2.0 * a_j / nx * 2.0 * float(b) / ny)[:, None], nx, axis=1)
    return TractionField(x=x, y=y, pn=pn, px=px, py=py, slip=slip.astype(bool), area=area,
                         fx=fx, fy=fy, mz=mz, status=status)
