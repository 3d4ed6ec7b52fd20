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
from __future__ import annotations

from dataclasses import dataclass
import inspect
from typing import Any, Dict, List, Mapping, NamedTuple, Optional, Tuple, Union

import numpy as np
import numpy.typing as npt

from .. import _core
from .._binding import (METHODS, FallingFriction, MethodInfo, OptionInfo, _broadcast, _finish,
                       _friction, creep_blame, creep_options, methods_doc, swap_blame,
                       used_numbers)
from .._errors import RollerRigError, check_status
from .._typing import FloatResult, StatusResult

__all__ = [
    "METHODS", "BOUNDS", "MethodInfo", "OptionInfo", "FallingFriction", "HertzContact",
    "KalkerCoefficients", "CreepForces", "TractionField", "hertz", "kalker_coefficients",
    "creep_forces", "fastsim_field",
]

#: the traction bounds' names (the choices of the methods' "bound" option)
BOUNDS = next(m.options["bound"].choices for m in METHODS.values() if "bound" in m.options)


class HertzContact(NamedTuple):
    """The Hertzian contact ellipse, as :func:`hertz` returns it.

    Each field is a float for a call on scalars, else an array of the
    broadcast shape (``status`` an int / int8 array).
    """

    a: FloatResult       #: semi-axis along the rolling direction [m]
    b: FloatResult       #: lateral semi-axis [m]
    p0: FloatResult      #: peak pressure [Pa]
    delta: FloatResult   #: approach of the two bodies [m]
    status: StatusResult  #: C status per element (0 OK; rollerrig.STATUS)


class KalkerCoefficients(NamedTuple):
    """Kalker's creep and spin coefficients, as :func:`kalker_coefficients`
    returns them (dimensionless).

    With c = sqrt(a b): Fx = -G c^2 C11 cx, Fy = -G c^2 C22 cy - G c^3 C23
    cphi, Mz = G c^3 C23 cy - G c^4 C33 cphi.
    """

    c11: FloatResult     #: longitudinal creep coefficient [-]
    c22: FloatResult     #: lateral creep coefficient [-]
    c23: FloatResult     #: lateral-spin coupling coefficient [-]
    c33: FloatResult     #: spin coefficient [-] (Mz = G c^3 C23 cy - G c^4 C33 cphi)
    status: StatusResult  #: C status per element (0 OK; rollerrig.STATUS)


class CreepForces(NamedTuple):
    """Creep forces and spin moment on the wheel, as :func:`creep_forces`
    returns them.

    Each field is a float for a call on scalars, else an array of the
    broadcast shape (``status`` an int / int8 array).
    """

    fx: FloatResult      #: longitudinal force on the wheel [N]
    fy: FloatResult      #: lateral force on the wheel [N]
    mz: FloatResult      #: spin moment on the wheel [N m]
    status: StatusResult  #: C status per element (0 OK, > 0 warning, < 0 NaN result)


@dataclass(frozen=True)
class TractionField:
    """The FASTSIM traction field of one case, as :func:`fastsim_field`
    returns it.

    The arrays have shape (ny, nx), rows at increasing y, columns along
    increasing x (the leading edge is the last column); elements outside
    the ellipse have zero pressure.
    """

    x: npt.NDArray[np.float64]  #: element centre, rolling direction [m]
    y: npt.NDArray[np.float64]  #: element centre, lateral [m]
    pn: npt.NDArray[np.float64]  #: pressure [Pa]
    px: npt.NDArray[np.float64]  #: longitudinal tangential traction on the wheel [Pa]
    py: npt.NDArray[np.float64]  #: lateral tangential traction on the wheel [Pa]
    slip: npt.NDArray[np.bool_]  #: True where the element slips, False where it adheres
    area: npt.NDArray[np.float64]  #: element area [m^2]
    fx: float          #: total longitudinal force on the wheel [N]
    fy: float          #: total lateral force on the wheel [N]
    mz: float          #: total spin moment on the wheel [N m]
    status: int        #: C status (0 OK, 1 a warning; rollerrig.STATUS)


# The scalar path: a call on plain numbers skips numpy (arrays, broadcasting,
# per-element checks: some 40 us) and takes one case straight to C, with the
# method's options parsed once and kept.  Only a clean result (status 0) is
# returned from it; anything else goes the general way, which names the
# culprit.  Results are bitwise those of the general path (the same kernel on
# the same doubles: tests/test_scalar_path.py).
_PLAIN = frozenset((float, int, np.float64))
_tuple_new = tuple.__new__
_SCALAR_OPTIONS: Dict[object, _core.CreepOptions] = {}
_SCALAR_OPTIONS_MAX = 64


def _scalar_options(method: object,
                    options: Mapping[str, object]) -> Optional[_core.CreepOptions]:
    """The CreepOptions of a method and its options, parsed once; None where
    they are not hashable or not valid (the general path says why)."""
    try:
        key: object = method
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


def _scalar_creep(method: str, options: Mapping[str, object], friction: object,
                  case: Tuple[Any, Any, Any, Any, Any, Any, Any, Any, Any, Any]
                  ) -> Optional[CreepForces]:
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


def _hertz_status(*v: float) -> int:
    return _core.hertz1(*v)[4]


def _kalker_status(*v: float) -> int:
    return int(_core.kalker(*(np.array([x]) for x in v))[-1][0])


def _case_blame(func: str, kwargs: Mapping[str, Any], code: int) -> Optional[List[str]]:
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
        cx, cy, cphi, a, b, N, mu, G, nu, speed = case
        flat = _case(func, cx, cy, cphi, a, b, N, mu, G, nu, speed, friction, method)[3]
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


def hertz(A: npt.ArrayLike, B: npt.ArrayLike, N: npt.ArrayLike, E: npt.ArrayLike = 2.1e11,
          nu: npt.ArrayLike = 0.28, E2: Optional[npt.ArrayLike] = None,
          nu2: Optional[npt.ArrayLike] = None, *,
          errors: Optional[str] = None) -> HertzContact:
    """Hertzian contact ellipse of two elastic bodies.

    Elliptic integrals to machine precision (Carlson), the ellipticity
    solved to full double precision (Johnson 1985, 4.2).

    Parameters
    ----------
    A, B : float or array_like
        Curvature sums [1/m] in the rolling and lateral direction: the gap
        is h = A x^2 + B y^2, so A = (1/R1x + 1/R2x)/2 (on a roller,
        1/r_wheel + 1/R_roller enters A); the long axis lies along the
        smaller sum.  > 0.
    N : float or array_like
        Normal load [N], > 0.
    E : float or array_like, optional
        Young's modulus of the wheel [Pa].
    nu : float or array_like, optional
        Poisson ratio of the wheel [-], 0 <= nu <= 0.5.
    E2, nu2 : float or array_like, optional
        Young's modulus [Pa] and Poisson ratio [-] of the roller; None
        (default): the wheel's (the same material).
    errors : {None, "raise", "warn", "ignore"}, optional
        What a bad element does (Notes); None: "raise" for a call on
        scalars, "warn" for arrays.

    Returns
    -------
    HertzContact
        ``(a, b, p0, delta, status)``: the semi-axes a (along the rolling
        direction) and b [m], the peak pressure p0 [Pa], the approach delta
        [m] and the status per element (:class:`HertzContact`).  Floats and
        an int for scalar inputs, else arrays of the broadcast shape.

    Raises
    ------
    RollerRigError
        With errors="raise" (the default for scalars), naming the argument
        and its value: NaN or infinite input (status -1), a load not
        positive (-2), a curvature sum not positive (-3), a modulus or
        Poisson ratio out of range (-4); also for inputs that are not real
        numbers, are empty or do not broadcast, and for a bad `errors`.

    See Also
    --------
    kalker_coefficients : the creep coefficients of the ellipse's a / b.
    creep_forces : the forces of a contact of semi-axes a, b.

    Notes
    -----
    The arguments broadcast against each other (numpy rules).  A call on
    arrays computes the good elements and gives NaN with a negative status
    for each bad one; errors="warn" (the default for arrays) gives one
    RollerRigWarning naming the first, "ignore" none, "raise" raises
    RollerRigError.  ``rollerrig.STATUS`` maps every status to its message.

    Examples
    --------
    A wheel of radius 0.45 m on a roller of radius 0.2 m, both with a
    lateral radius of curvature of 0.3 m in sum, under 10 kN:

    >>> import rollerrig as rr
    >>> h = rr.hertz(A=1/0.45 + 1/0.2, B=1/0.3, N=1e4)
    >>> print(f"a = {h.a * 1e3:.3f} mm, b = {h.b * 1e3:.3f} mm, p0 = {h.p0 / 1e9:.3f} GPa")
    a = 1.447 mm, b = 2.419 mm, p0 = 1.364 GPa

    On arrays a bad element is NaN with a negative status:

    >>> h = rr.hertz([1/0.45 + 1/0.2, -1.0], 1/0.3, 1e4, errors="ignore")
    >>> h.status
    array([ 0, -3], dtype=int8)
    """
    E2 = E if E2 is None else E2
    nu2 = nu if nu2 is None else nu2
    if errors is None and _PLAIN.issuperset(map(type, (A, B, N, E, nu, E2, nu2))):
        r: Tuple[float, ...]
        try:
            # (the _PLAIN check above: plain numbers, which mypy cannot narrow to)
            r = _core.hertz1(A, B, N, E, nu, E2, nu2)  # type: ignore[arg-type]
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


def kalker_coefficients(a_over_b: npt.ArrayLike, nu: npt.ArrayLike = 0.28, *,
                        errors: Optional[str] = None) -> KalkerCoefficients:
    """Kalker's creep and spin coefficients C11, C22, C23, C33.

    From Kalker 1990, Table E.3: exact at the table's nodes; linear in
    g = min(a/b, b/a) between them, a parabola through 1/C in nu; Kalker's
    asymptotes below g = 0.1 (for C33, which has none in CONTACT, the
    continuation csrc/contact/rr_kalker.h describes).

    Parameters
    ----------
    a_over_b : float or array_like
        Semi-axis along the rolling direction over the lateral one [-], > 0.
    nu : float or array_like, optional
        Poisson ratio [-], 0 <= nu <= 0.5.
    errors : {None, "raise", "warn", "ignore"}, optional
        As for :func:`hertz`: None is "raise" for scalars, "warn" for
        arrays.

    Returns
    -------
    KalkerCoefficients
        ``(c11, c22, c23, c33, status)``, dimensionless
        (:class:`KalkerCoefficients`); floats and an int for scalar inputs,
        else arrays of the broadcast shape.

    Raises
    ------
    RollerRigError
        With errors="raise", naming the argument and its value: NaN or
        infinite (status -1), a/b not positive (-3), nu out of range (-4).

    See Also
    --------
    hertz : the semi-axes a, b.
    creep_forces : method="linear" is Kalker's linear theory with these.

    Notes
    -----
    A call on arrays gives NaN and a negative status for each bad element
    (errors="warn": one RollerRigWarning; "ignore": none).

    Examples
    --------
    >>> import rollerrig as rr
    >>> k = rr.kalker_coefficients(0.8, nu=0.28)
    >>> print(f"{k.c11:.4f} {k.c22:.4f} {k.c23:.4f} {k.c33:.4f}")
    4.0189 3.4377 1.2662 1.3749
    """
    shape, scalar, full, flat = _broadcast("kalker_coefficients",
                                           dict(a_over_b=a_over_b, nu=nu))
    c11, c22, c23, c33, status = _core.kalker(*flat)
    return KalkerCoefficients(*_finish("kalker_coefficients", shape, scalar, full,
                                       (c11, c22, c23, c33), status, errors,
                                       swap_blame(_kalker_status, flat, ["a_over_b", "nu"],
                                                  _KALKER_VALID)))


def _case(func: str, cx: object, cy: object, cphi: object, a: object, b: object, N: object,
          mu: object, G: object, nu: object, speed: object, friction: object,
          method: Optional[str] = None) -> Tuple[Tuple[int, ...], bool, Dict[str, Any],
                                                List[npt.NDArray[np.float64]]]:
    fA, fB = _friction(func, friction, method)
    named = dict(cx=cx, cy=cy, cphi=cphi, a=a, b=b, N=N, mu=mu, G=G, nu=nu, speed=speed)
    named["friction.A"] = fA
    named["friction.B"] = fB
    return _broadcast(func, named)


def creep_forces(cx: npt.ArrayLike, cy: npt.ArrayLike = 0.0, cphi: npt.ArrayLike = 0.0, *,
                 a: npt.ArrayLike, b: npt.ArrayLike, N: npt.ArrayLike, mu: npt.ArrayLike,
                 G: npt.ArrayLike = 8.2e10, nu: npt.ArrayLike = 0.28, method: str = "fastsim",
                 speed: npt.ArrayLike = 0.0,
                 friction: Optional[Union[FallingFriction, str]] = None,
                 errors: Optional[str] = None, **options: Any) -> CreepForces:
    """Creep forces and spin moment on the wheel of a Hertzian contact.

    Parameters
    ----------
    cx, cy : float or array_like
        Longitudinal and lateral creepage [-] (slip over rolling speed;
        module conventions).
    cphi : float or array_like
        Spin creepage [rad/m].
    a, b : float or array_like
        Semi-axes [m], a along the rolling direction; > 0.
    N : float or array_like
        Normal load [N], > 0.
    mu : float or array_like
        (Static) friction coefficient [-], > 0.
    G : float or array_like, optional
        Combined shear modulus [Pa], > 0.
    nu : float or array_like, optional
        Combined Poisson ratio [-], 0 <= nu <= 0.5.
    method : str, optional
        A name of ``rollerrig.METHODS`` (listed under Notes).
    speed : float or array_like, optional
        Rolling speed [m/s]; falling friction needs it > 0.
    friction : None or FallingFriction, optional
        None (or "coulomb"): Coulomb friction; a :class:`FallingFriction`
        (A, B): Polach's falling friction (not for the Coulomb-only
        methods, ``METHODS[method].coulomb_only``).
    errors : {None, "raise", "warn", "ignore"}, optional
        None: "raise" for a call on scalars, "warn" for arrays (Notes).
    **options
        The method's options (``rollerrig.METHODS[method].options``, listed
        under Notes); an option the method does not have is refused; None:
        its default.

    Returns
    -------
    CreepForces
        ``(fx, fy, mz, status)``: the forces on the wheel fx, fy [N], the
        spin moment mz [N m] and the status per element: 0 ok, 1 the
        falling-friction iteration hit its cap somewhere, < 0 an error with
        NaN forces (:class:`CreepForces`, ``rollerrig.STATUS``).  Floats and
        an int for scalar inputs, else arrays of the broadcast shape.

    Raises
    ------
    RollerRigError
        With errors="raise" (the default for scalars), naming the argument
        and its value, for a bad element: NaN or infinite input (status
        -1), a load not positive (-2), a semi-axis not positive (-3), a
        modulus or Poisson ratio out of range (-4), a friction coefficient
        or law out of range (-5), falling friction without a positive
        speed (-7), inputs so extreme that the result would not be a finite
        double (-12), a case outside the built-in table of method
        "exact_table" (-14).  Whatever `errors`: an unknown
        method, an option the method lacks or out of its range (naming the
        option, range and value), a falling law for a Coulomb-only method,
        inputs that are not real numbers, are empty or do not broadcast.

    See Also
    --------
    hertz : the semi-axes a, b and the load's ellipse.
    fastsim_field : the traction field of one case.
    exact_field : the exact theory's solution of one case.
    sweep : this function over a grid of its arguments.

    Notes
    -----
    Every method that saturates (all but "linear") keeps ``|(fx, fy)| <= mu
    N`` (the static mu).  The Polach method has no spin moment (mz = 0); the
    linear theory's spin moment uses Kalker's C33
    (:func:`kalker_coefficients`).

    The arguments broadcast against each other (numpy rules).  A call on
    arrays computes the good elements and gives NaN with a negative status
    for each bad one; errors="warn" gives one RollerRigWarning for the call,
    "ignore" none, "raise" raises RollerRigError naming the first.  A
    status of 1 (a warning) leaves a usable result.

    The methods and their options (name=default [unit]: meaning; valid
    values):

    {methods}

    Examples
    --------
    >>> import numpy as np
    >>> import rollerrig as rr
    >>> f = rr.creep_forces(2e-4, a=6e-3, b=4e-3, N=1e4, mu=0.3)
    >>> print(f"fx = {f.fx:.1f} N, status {f.status}")
    fx = -1534.8 N, status 0

    Arrays broadcast; a bad element is NaN with a negative status:

    >>> f = rr.creep_forces([1e-4, 2e-4, np.nan], a=6e-3, b=4e-3, N=1e4, mu=0.3,
    ...                     method="polach", errors="ignore")
    >>> f.status
    array([ 0,  0, -1], dtype=int8)

    Falling friction needs the rolling speed:

    >>> f = rr.creep_forces(2e-3, a=6e-3, b=4e-3, N=1e4, mu=0.3, speed=10.0,
    ...                     friction=rr.FallingFriction(A=0.4, B=0.6))
    >>> print(f"{-f.fx / (0.3 * 1e4):.3f}")
    0.993
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


def fastsim_field(cx: float, cy: float = 0.0, cphi: float = 0.0, *, a: float, b: float, N: float,
                  mu: float, G: float = 8.2e10, nu: float = 0.28, method: str = "fastsim",
                  speed: float = 0.0, friction: Optional[Union[FallingFriction, str]] = None,
                  **options: Any) -> TractionField:
    """The traction field of one case, for plots and checks.

    Parameters
    ----------
    cx, cy, cphi, a, b, N, mu, G, nu, speed, friction
        As for :func:`creep_forces` [-, -, rad/m, m, m, N, -, Pa, -, m/s],
        scalars only.
    method : str, optional
        A method with a traction field (``rollerrig.METHODS[method].has_field``:
        the FASTSIM variants).
    **options
        The method's options, as for :func:`creep_forces`.

    Returns
    -------
    TractionField
        The element centres x, y [m], pressure pn and tractions px, py [Pa],
        the adhesion/slip map, element areas [m^2], the total forces fx, fy
        [N] and moment mz [N m] and the status (:class:`TractionField`).

    Raises
    ------
    RollerRigError
        For an invalid case (naming the argument and its value, as
        creep_forces with errors="raise"), a method without a traction
        field, or array inputs (one case at a time).

    See Also
    --------
    creep_forces : the forces alone, vectorised.
    exact_field : the exact theory's field.
    rollerrig.plot.traction_field : draws it.

    Examples
    --------
    >>> import rollerrig as rr
    >>> t = rr.fastsim_field(2e-4, a=6e-3, b=4e-3, N=1e4, mu=0.3, nx=10, ny=10)
    >>> t.pn.shape, int(t.slip.sum())
    ((10, 10), 22)
    >>> print(f"{t.fx:.1f}")
    -1640.8
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


# the methods from the registry; cleandoc first, so that the list (at column 0) sits in the
# Notes whatever the interpreter's docstring indentation
creep_forces.__doc__ = inspect.cleandoc(creep_forces.__doc__ or "").replace("{methods}",
                                                                      methods_doc())
