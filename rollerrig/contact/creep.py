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
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from .. import _core
from .._binding import (METHODS, FallingFriction, MethodInfo, OptionInfo, _broadcast, _finish,
                       _friction, creep_blame, creep_options, methods_doc, swap_blame,
                       used_numbers)
from .._errors import RollerRigError, check_status

__all__ = [
    "METHODS", "BOUNDS", "MethodInfo", "OptionInfo", "FallingFriction", "HertzContact",
    "KalkerCoefficients", "CreepForces", "TractionField", "hertz", "kalker_coefficients",
    "creep_forces", "fastsim_field",
]

#: the traction bounds' names (the choices of the methods' "bound" option)
BOUNDS = next(m.options["bound"].choices for m in METHODS.values() if "bound" in m.options)


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
    c33: np.ndarray     #: spin coefficient (Mz = G c^3 C23 cy - G c^4 C33 cphi)
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


# The scalar path: a call on plain numbers skips numpy (arrays, broadcasting,
# per-element checks: some 40 us) and takes one case straight to C, with the
# method's options parsed once and kept.  Only a clean result (status 0) is
# returned from it; anything else goes the general way, which names the
# culprit.  Results are bitwise those of the general path (the same kernel on
# the same doubles: tests/test_scalar_path.py).
_PLAIN = frozenset((float, int, np.float64))
_tuple_new = tuple.__new__
_SCALAR_OPTIONS = {}
_SCALAR_OPTIONS_MAX = 64


def _scalar_options(method, options):
    """The CreepOptions of a method and its options, parsed once; None where
    they are not hashable or not valid (the general path says why)."""
    try:
        key = method
        if options:
            # the values' types in the key too: 1, 1.0 and True are equal keys,
            # and an option takes what the general path takes, whatever ran
            # before (nx=True once came from the cache of an nx=1)
            items = sorted(options.items())
            key = (method, tuple(items), tuple([type(v) for _, v in items]))
        return _SCALAR_OPTIONS[key]
    except KeyError:
        pass
    except TypeError:
        return None
    if not isinstance(method, str):
        return None
    try:
        o = _core.CreepOptions(method=method, **options)
    except (ValueError, TypeError, OverflowError):
        return None
    if len(_SCALAR_OPTIONS) >= _SCALAR_OPTIONS_MAX:
        _SCALAR_OPTIONS.clear()
    _SCALAR_OPTIONS[key] = o
    return o


def _scalar_creep(method, options, friction, case):
    """CreepForces of one case of plain numbers with status 0, else None."""
    try:
        fA, fB = _friction("creep_forces", friction, method)
    except RollerRigError:                           # the general path says why
        return None
    if not _PLAIN.issuperset(map(type, case)) or type(fA) not in _PLAIN \
            or type(fB) not in _PLAIN:
        return None
    o = _scalar_options(method, options)
    if o is None:
        return None
    try:
        r = _core.creep_forces1(o, *case, fA, fB)
    except OverflowError:                            # an int beyond the doubles
        return None
    # (fx, fy, mz, status) as it came, without a second tuple
    return _tuple_new(CreepForces, r) if r[3] == 0 else None


# one valid case of hertz and of kalker_coefficients, whose values replace a
# failed element's one at a time to find the arguments its status is about
# (swap_blame: the C core judges, no rule is restated here)
_HERTZ_VALID = dict(A=1.0, B=1.0, N=1e4, E=2.1e11, nu=0.28, E2=2.1e11, nu2=0.28)
_KALKER_VALID = dict(a_over_b=1.0, nu=0.28)


def _hertz_status(*v):
    return _core.hertz1(*v)[-1]


def _kalker_status(*v):
    return int(_core.kalker(*(np.array([x]) for x in v))[-1][0])


def _case_blame(func, kwargs, code):
    """The arguments the C core blames for status `code` of one case of the
    library function `func` (creep_forces, hertz or kalker_coefficients)
    given as keywords (a sweep's element), or None."""
    if func == "creep_forces":
        kw = dict(kwargs)
        method, friction = kw.pop("method", "fastsim"), kw.pop("friction", None)
        case = [kw.pop(n, d) for n, d in (("cx", None), ("cy", 0.0), ("cphi", 0.0),
                                           ("a", None), ("b", None), ("N", None), ("mu", None),
                                           ("G", 8.2e10), ("nu", 0.28), ("speed", 0.0))]
        kw.pop("errors", None)
        flat = _case(func, *case, friction, method)[3]
        return creep_blame(creep_options(func, method, kw), flat)(0, code)
    if func == "hertz":
        kw = dict(_HERTZ_VALID, **{k: v for k, v in kwargs.items() if k != "errors"})
        kw["E2"] = kwargs.get("E2") if kwargs.get("E2") is not None else kw["E"]
        kw["nu2"] = kwargs.get("nu2") if kwargs.get("nu2") is not None else kw["nu"]
        names = list(_HERTZ_VALID)
        return swap_blame(_hertz_status, [np.asarray(float(kw[n])) for n in names], names,
                          _HERTZ_VALID)(0, code)
    if func == "kalker_coefficients":
        kw = dict(_KALKER_VALID, **{k: v for k, v in kwargs.items() if k != "errors"})
        names = list(_KALKER_VALID)
        return swap_blame(_kalker_status, [np.asarray(float(kw[n])) for n in names], names,
                          _KALKER_VALID)(0, code)
    return None


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
    if errors is None and _PLAIN.issuperset(map(type, (A, B, N, E, nu, E2, nu2))):
        try:
            r = _core.hertz1(A, B, N, E, nu, E2, nu2)
        except OverflowError:                        # an int beyond the doubles
            r = (-1,)
        if r[-1] == 0:                               # the scalar path (see creep_forces)
            return _tuple_new(HertzContact, r)
    named = dict(A=A, B=B, N=N, E=E, nu=nu, E2=E2, nu2=nu2)
    shape, scalar, full, flat = _broadcast("hertz", named)
    a, b, p0, delta, status = _core.hertz(*flat)
    return HertzContact(*_finish("hertz", shape, scalar, full, (a, b, p0, delta), status,
                                 errors, swap_blame(_hertz_status, flat, list(named),
                                                    _HERTZ_VALID)))


def kalker_coefficients(a_over_b, nu=0.28, *, errors=None):
    """Kalker's creep and spin coefficients C11, C22, C23, C33 (Kalker 1990,
    Table E.3).

    Exact at the table's nodes; linear in g = min(a/b, b/a) between them, a
    parabola through 1/C in nu; Kalker's asymptotes below g = 0.1 (for C33,
    which has none in CONTACT, the continuation csrc/contact/rr_kalker.h
    describes).
    a_over_b: semi-axis along the rolling direction over the lateral one
    (> 0); nu: Poisson ratio, 0 <= nu <= 0.5.  errors: as for hertz.
    Returns KalkerCoefficients(c11, c22, c23, c33, status), dimensionless.
    """
    shape, scalar, full, flat = _broadcast("kalker_coefficients",
                                           dict(a_over_b=a_over_b, nu=nu))
    c11, c22, c23, c33, status = _core.kalker(*flat)
    return KalkerCoefficients(*_finish("kalker_coefficients", shape, scalar, full,
                                       (c11, c22, c23, c33), status, errors,
                                       swap_blame(_kalker_status, flat, ["a_over_b", "nu"],
                                                  _KALKER_VALID)))


def _case(func, cx, cy, cphi, a, b, N, mu, G, nu, speed, friction, method=None):
    fA, fB = _friction(func, friction, method)
    named = dict(cx=cx, cy=cy, cphi=cphi, a=a, b=b, N=N, mu=mu, G=G, nu=nu, speed=speed)
    named["friction.A"] = fA
    named["friction.B"] = fB
    return _broadcast(func, named)


def creep_forces(cx, cy=0.0, cphi=0.0, *, a, b, N, mu, G=8.2e10, nu=0.28, method="fastsim",
                 speed=0.0, friction=None, errors=None, **options):
    """Creep forces and spin moment on the wheel of a Hertzian contact.

    cx, cy:  longitudinal and lateral creepage [-]; cphi: spin [rad/m]
    a, b:    semi-axes [m] (a along the rolling direction); N: load [N]
    mu:      (static) friction coefficient; G [Pa], nu: combined material
    method:  a name of rollerrig.METHODS (below)
    speed:   rolling speed [m/s]; falling friction needs it > 0
    friction: None (Coulomb) or FallingFriction(A, B)
    errors:  "raise" (default for scalar inputs), "warn" (default for
             arrays) or "ignore" (module docstring)
    **options: the method's options (rollerrig.METHODS[method].options; an
             option the method does not have is refused; None: its default):
{methods}
    Returns CreepForces(fx [N], fy [N], mz [N m], status): forces on the
    wheel, status per element (0 ok, 1 the falling-friction iteration hit
    its cap somewhere, < 0 an error with NaN forces; rollerrig.STATUS).
    Every method that saturates (all but "linear") keeps |(fx, fy)| <= mu N
    (the static mu).  The Polach method has no spin moment (mz = 0); the
    linear theory's spin moment uses Kalker's C33 (kalker_coefficients).
    """
    func = "creep_forces"
    if errors is None:
        fast = _scalar_creep(method, options, friction, (cx, cy, cphi, a, b, N, mu, G, nu, speed))
        if fast is not None:
            return fast
    opts = creep_options(func, method, options)       # parsed once for the batch
    shape, scalar, full, flat = _case(func, cx, cy, cphi, a, b, N, mu, G, nu, speed, friction,
                                      method)
    fx, fy, mz, status = _core.creep_forces(opts, *flat)
    # the method's own numbers may explain a failure too (beta = 1e307)
    full.update(used_numbers(method, options))
    return CreepForces(*_finish(func, shape, scalar, full, (fx, fy, mz), status, errors,
                                creep_blame(opts, flat)))


def fastsim_field(cx, cy=0.0, cphi=0.0, *, a, b, N, mu, G=8.2e10, nu=0.28, method="fastsim",
                  speed=0.0, friction=None, **options):
    """The traction field of one case, for plots and checks.

    Arguments as creep_forces (scalars only; a method with a traction
    field: rollerrig.METHODS[method].has_field, the FASTSIM variants).
    Returns a TractionField with the element centres [m], pressure and
    tractions [Pa], the adhesion/slip map, element areas [m^2] and the
    total forces [N] and moment [N m]; an invalid case raises RollerRigError.
    """
    func = "fastsim_field"
    opts = creep_options(func, method, options)
    if not METHODS[method].has_field:
        with_field = ", ".join(repr(k) for k, m in METHODS.items() if m.has_field)
        raise RollerRigError(f"{func}: method must have a traction field ({with_field}), "
                             f"got {method!r}")
    shape, scalar, full, flat = _case(func, cx, cy, cphi, a, b, N, mu, G, nu, speed, friction)
    if not scalar:
        raise RollerRigError(f"{func}: one case at a time; got inputs of shape {shape}")
    fx, fy, mz, status, x, y, pn, px, py, slip, area = _core.fastsim_field(opts, *flat)
    full.update(used_numbers(method, options))
    check_status(func, np.array(status, dtype=np.int8), full, "raise", creep_blame(opts, flat))
    return TractionField(x=x, y=y, pn=pn, px=px, py=py, slip=slip.astype(bool), area=area,
                         fx=fx, fy=fy, mz=mz, status=status)


creep_forces.__doc__ = creep_forces.__doc__.format(methods=methods_doc())
