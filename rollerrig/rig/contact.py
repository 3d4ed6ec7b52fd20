"""One contact evaluation of the rig's wheelset on its two rollers.

From the wheelset and roller state and the normal load of each wheel to the
contact points and frames, the Hertz ellipses, the creepages and the creep
forces, returned as forces and moments on the wheelset in the rig's
coordinates (csrc/rig/rr_rig_contact.h, the same C function the time step
calls)::

    g = rr.RigGeometry(...)
    table = rr.contact_table(g, -0.01, 0.01, 401)
    c = rr.rig_contact(table, y=0.002, spin=5 / 0.46, roller_spin=5 / 0.46 * 0.999,
                       N_left=1e4, N_right=1e4)
    c.left.cx, c.left.fx, c.left.force      # creepage, creep force, force on the wheelset

Rig frame: X forward, Y left, Z up, Z = 0 at the roller top of radius R0
(RigGeometry.roller_radius), the rollers' common axis at (X, Z) = (0, -R0).
spin > 0 rolls the wheelset forward (bottoms of the wheels moving
backward); roller_spin > 0 moves the rollers' tops backward; free rolling:
spin r = roller_spin R at each contact.  Creepages and forces follow the
contact core (Kalker's sign, forces on the wheel): a braked wheelset has
cx > 0, fx < 0.

The wheelset's height and roll come from the contact table at its lateral
shift y; its longitudinal shift x turns it about the roller axis (the seed
paper's tilt beta), and its yaw moves each wheel's contact point round the
roller (see csrc/rig/rr_rig_contact.h for the first-order law and its
reference).  linear_creepages() gives the seed paper's linearised eq. 7-9
for comparison.
"""
from __future__ import annotations

import warnings
from typing import (TYPE_CHECKING, Any, Callable, Dict, Generic, List, Literal, Mapping,
                    NamedTuple, Optional, Tuple, TypeVar, Union, cast, overload)

import numpy as np
import numpy.typing as npt

from .. import _core
from .._errors import RollerRigError, RollerRigWarning, check_number, status_message
from .._binding import (_broadcast, _finish, _friction, check_creep_options, core, loop_method,
                        swap_blame)
from .._typing import F64Array
from ..geometry.wheelset import ContactTable
from ._nonhertz_contact import (NonHertzPatch, NonHertzWheel, _Loads, _Status,
                                nonhertz_rig_contact)

__all__ = ["RigPose", "WheelContact", "RigContact", "rig_contact", "LinearCreepages",
           "linear_creepages", "NonHertzWheel", "NonHertzPatch"]


class RigPose(NamedTuple):
    """The wheelset's pose and motion, as :func:`rig_contact` returns it
    (its ``pose``); rig frame (module docstring)."""

    c: np.ndarray        #: wheelset centre (X, Y, Z) [m], shape (3, ...)
    roll: np.ndarray     #: roll angle [rad], > 0 lifting the left wheel
    beta: np.ndarray     #: turn about the roller axis [rad], > 0 forward
    v: np.ndarray        #: centre velocity incl. the constrained vertical rate [m/s], (3, ...)
    w: np.ndarray        #: wheelset angular velocity [rad/s], (3, ...)


#: the per-wheel block of the binding, declared in C (csrc/rig/rr_rig_params.c,
#: rr_wheel_field): (name, width, unit, meaning), width 3 for a vector in the
#: rig frame (shape (3, ...)), 1 for a scalar
WHEEL_FIELDS = _core.RIG_WHEEL_FIELDS

#: one wheel's contact: the fields of WHEEL_FIELDS, then its status.  The
#: class is made from the C declaration at run time; for the type checker it
#: is spelt out (tests/test_typing.py holds the two to the same fields): a
#: scalar field a numpy scalar for a call on scalars, else an array
_Scalar = Union[np.float64, npt.NDArray[np.float64]]
if TYPE_CHECKING:
    _Vector = npt.NDArray[np.float64]          # shape (3, ...)

    class WheelContact(NamedTuple):
        p: _Vector
        theta: _Scalar
        t1: _Vector
        t2: _Vector
        n: _Vector
        cx: _Scalar
        cy: _Scalar
        cphi: _Scalar
        V: _Scalar
        N: _Scalar
        a: _Scalar
        b: _Scalar
        p0: _Scalar
        fx: _Scalar
        fy: _Scalar
        mz: _Scalar
        force: _Vector
        moment: _Vector
        r: _Scalar
        R: _Scalar
        delta: _Scalar
        s_wheel: _Scalar
        s_roller: _Scalar
        status: Union[np.int8, npt.NDArray[np.int8]]
else:
    WheelContact = NamedTuple("WheelContact", [(name, np.ndarray) for name, *_ in WHEEL_FIELDS]
                              + [("status", np.ndarray)])
WheelContact.__doc__ = "One wheel's contact; fields, units [SI] and meanings:\n" + "\n".join(
    f"    {name} [{unit}]{' (3, ...)' if width == 3 else ''}: {meaning}"
    for name, width, unit, meaning in WHEEL_FIELDS) + "\n    status: this wheel's status"


#: the worse of the two wheels' statuses (_Status, from _nonhertz_contact):
#: an int8 array, a numpy int8 for a call on scalars, an int for
#: patch="nonhertz" on one state

#: both wheels' contact.  For the type checker RigContact is generic in its
#: wheels' type (tests/test_typing_decl.py holds it to the run-time fields):
#: rig_contact's overloads give RigContact[WheelContact] for patch="hertz",
#: RigContact[NonHertzWheel] for "nonhertz"; a bare RigContact has wheels of
#: either type, whose shared fields (force, moment, N, status) read as both
if TYPE_CHECKING:
    from typing_extensions import TypeVar as _DefaultTypeVar    # PEP 696's default=

    _Wheel = _DefaultTypeVar("_Wheel", bound=Union["WheelContact", "NonHertzWheel"],
                             default=Union["WheelContact", "NonHertzWheel"], covariant=True)

    class RigContact(NamedTuple, Generic[_Wheel]):
        pose: RigPose
        left: _Wheel
        right: _Wheel
        status: _Status
else:
    class RigContact(NamedTuple):
        """Both wheels' contact, as :func:`rig_contact` returns it.

        ``left`` and ``right`` are :class:`WheelContact` (or
        :class:`NonHertzWheel` for patch="nonhertz"); each field an array of
        the broadcast shape of the states (numpy scalars for a call on
        scalars; 3-vectors shape (3, ...)).
        """

        pose: RigPose                                 #: the wheelset's pose and motion
        left: Union[WheelContact, NonHertzWheel]      #: the left wheel's contact
        right: Union[WheelContact, NonHertzWheel]     #: the right wheel's contact
        status: _Status       #: the worse of the two wheels' statuses


def _wheel(block: F64Array, status: npt.NDArray[np.int8], shape: Tuple[int, ...]) -> WheelContact:
    vals: Dict[str, F64Array] = {}
    k = 0
    for name, width, _, _ in WHEEL_FIELDS:
        vals[name] = (block[k:k + 3].reshape((3,) + shape) if width == 3
                      else block[k].reshape(shape))
        k += width
    return WheelContact(**vals, status=status.reshape(shape))


def _check_table(func: str, table: object) -> None:
    if not isinstance(table, ContactTable):
        raise RollerRigError(f"{func}: table must be a ContactTable (rr.contact_table), "
                             f"got {table!r:.60}")


def elastic_constants(E: float, nu: float) -> Tuple[float, float]:
    """(E*, G) of wheel and roller of the same material: the contact modulus
    E* = E / (2 (1 - nu^2)) and the shear modulus G = E / (2 (1 + nu))."""
    return E / (2.0 * (1.0 - nu * nu)), E / (2.0 * (1.0 + nu))


#: the contact model's constants as the binding takes them:
#: (R0, E*, G, nu, mu, friction's A, B, vmin)
_Model = Tuple[float, float, float, float, float, float, float, float]

_TINY = np.finfo(float).tiny      # a subnormal modulus has too few digits for a force


def _model(func: str, table: ContactTable, mu: float, E: float, nu: float, vmin: float,
           friction: object) -> _Model:
    g = table.geometry
    # a number by check_number's rule, then its range (one message for both)
    checks: Tuple[Tuple[str, float, Callable[[float], bool], str], ...] = (
        ("mu", mu, lambda x: 0 < x <= _core.FRICTION_MAX, f"in (0, {_core.FRICTION_MAX:g}]"),
        ("E", E, lambda x: x > 0, "> 0"), ("nu", nu, lambda x: 0 <= x <= 0.5, "in [0, 0.5]"),
        ("vmin", vmin, lambda x: x > 0, "> 0"))
    for name, v, ok, words in checks:
        try:
            good = ok(check_number(func, name, v))
        except RollerRigError:
            good = False
        if not good:
            raise RollerRigError(f"{func}: {name} must be a finite number {words}, got {v!r:.60}")
    fA, fB = _friction(func, friction)
    estar, G = elastic_constants(E, nu)
    if not (estar >= _TINY and G >= _TINY):
        raise RollerRigError(f"{func}: E = {E!r} Pa gives a contact modulus {estar:g} Pa and a "
                             f"shear modulus {G:g} Pa, under the least normal double")
    return (float(g.roller_radius), estar, G, float(nu), float(mu), fA, fB, float(vmin))


# one valid state and model, whose values replace a failed element's one at a
# time to find the arguments its status is about (swap_blame: the C core
# judges, no rule is restated here)
_VALID_STATE = dict(x=0.0, y=0.0, yaw=0.0, vx=0.0, vy=0.0, yaw_rate=0.0, spin=10.0,
                    roller_spin=10.0, N_left=1e4, N_right=1e4, mu=0.4, E=2.1e11, nu=0.28,
                    vmin=1e-3)


# the wheels' type by `patch` (RigContact's comment)
@overload
def rig_contact(table: ContactTable, *, x: npt.ArrayLike = 0.0, y: npt.ArrayLike = 0.0,
                yaw: npt.ArrayLike = 0.0, vx: npt.ArrayLike = 0.0, vy: npt.ArrayLike = 0.0,
                yaw_rate: npt.ArrayLike = 0.0, spin: npt.ArrayLike, roller_spin: npt.ArrayLike,
                N_left: Optional[npt.ArrayLike] = None, N_right: Optional[npt.ArrayLike] = None,
                Fz_left: Optional[npt.ArrayLike] = None, Fz_right: Optional[npt.ArrayLike] = None,
                mu: float = 0.4, friction: object = None, E: float = 2.1e11,
                nu: float = 0.28, vmin: float = 1e-3, method: str = "fastsim",
                kinematics_only: bool = False, errors: Optional[str] = None,
                patch: Literal["hertz"] = ..., nonhertz: object = None,
                **options: Any) -> RigContact[WheelContact]: ...


@overload
def rig_contact(table: ContactTable, *, x: npt.ArrayLike = 0.0, y: npt.ArrayLike = 0.0,
                yaw: npt.ArrayLike = 0.0, vx: npt.ArrayLike = 0.0, vy: npt.ArrayLike = 0.0,
                yaw_rate: npt.ArrayLike = 0.0, spin: npt.ArrayLike, roller_spin: npt.ArrayLike,
                N_left: Optional[npt.ArrayLike] = None, N_right: Optional[npt.ArrayLike] = None,
                Fz_left: Optional[npt.ArrayLike] = None, Fz_right: Optional[npt.ArrayLike] = None,
                mu: float = 0.4, friction: object = None, E: float = 2.1e11,
                nu: float = 0.28, vmin: float = 1e-3, method: str = "fastsim",
                kinematics_only: bool = False, errors: Optional[str] = None,
                patch: Literal["nonhertz"], nonhertz: object = None,
                **options: Any) -> RigContact[NonHertzWheel]: ...


@overload
def rig_contact(table: ContactTable, *, x: npt.ArrayLike = 0.0, y: npt.ArrayLike = 0.0,
                yaw: npt.ArrayLike = 0.0, vx: npt.ArrayLike = 0.0, vy: npt.ArrayLike = 0.0,
                yaw_rate: npt.ArrayLike = 0.0, spin: npt.ArrayLike, roller_spin: npt.ArrayLike,
                N_left: Optional[npt.ArrayLike] = None, N_right: Optional[npt.ArrayLike] = None,
                Fz_left: Optional[npt.ArrayLike] = None, Fz_right: Optional[npt.ArrayLike] = None,
                mu: float = 0.4, friction: object = None, E: float = 2.1e11,
                nu: float = 0.28, vmin: float = 1e-3, method: str = "fastsim",
                kinematics_only: bool = False, errors: Optional[str] = None, patch: str = ...,
                nonhertz: object = None, **options: Any) -> RigContact: ...


def rig_contact(table: ContactTable, *, x: npt.ArrayLike = 0.0, y: npt.ArrayLike = 0.0,
                yaw: npt.ArrayLike = 0.0, vx: npt.ArrayLike = 0.0, vy: npt.ArrayLike = 0.0,
                yaw_rate: npt.ArrayLike = 0.0, spin: npt.ArrayLike, roller_spin: npt.ArrayLike,
                N_left: Optional[npt.ArrayLike] = None, N_right: Optional[npt.ArrayLike] = None,
                Fz_left: Optional[npt.ArrayLike] = None, Fz_right: Optional[npt.ArrayLike] = None,
                mu: float = 0.4, friction: object = None, E: float = 2.1e11,
                nu: float = 0.28, vmin: float = 1e-3, method: str = "fastsim",
                kinematics_only: bool = False, errors: Optional[str] = None, patch: str = "hertz",
                nonhertz: object = None, **options: Any) -> RigContact[Any]:
    """Contact of both wheels for wheelset states (numpy-broadcast arrays).

    Parameters
    ----------
    table : ContactTable
        The contact table of the rig's wheel/roller pair
        (:func:`contact_table`).
    x, y : float or array_like, optional
        The wheelset centre's longitudinal and lateral position [m].
    yaw : float or array_like, optional
        Yaw angle about Z [rad].
    vx, vy : float or array_like, optional
        The rates of x and y [m/s].
    yaw_rate : float or array_like, optional
        The rate of yaw [rad/s].
    spin : float or array_like
        The wheelset's angular speed about its axle [rad/s], > 0 rolling
        it forward.
    roller_spin : float or array_like
        The rollers' angular speed [rad/s], > 0 moving their tops backward.
    N_left, N_right : float or array_like, optional
        Normal loads [N], > 0; or
    Fz_left, Fz_right : float or array_like, optional
        The wheels' vertical loads [N] (CONTACT's FZ), > 0: the normal load
        found so that N n_z + fy t2_z = Fz (to 1e-9 Fz).  Give the normal
        or the vertical loads, not both.
    mu : float, optional
        Static friction coefficient [-], in (0, FRICTION_MAX].
    friction : None or FallingFriction, optional
        None (Coulomb) or a :class:`FallingFriction`.
    E : float, optional
        Young's modulus of wheel and roller steel [Pa], > 0.
    nu : float, optional
        Poisson ratio of wheel and roller steel [-], in [0, 0.5].
    vmin : float, optional
        Least rolling speed for the creepages [m/s] (standstill), > 0.
    method : str, optional
        The creep-force method, as for :func:`creep_forces`
        (``rollerrig.METHODS``).
    kinematics_only : bool, optional
        Skip Hertz and the forces (their fields are NaN; no loads needed).
    errors : {None, "raise", "warn", "ignore"}, optional
        As for :func:`creep_forces`: None is "raise" for a call on scalars,
        "warn" for arrays.
    patch : {"hertz", "nonhertz"}, optional
        "hertz" (default): one Hertz ellipse at the rigid contact point;
        "nonhertz": the non-Hertzian, multi-patch contact from the tables
        of `nonhertz`, Coulomb friction (x and yaw turn each patch's frame
        by the rig's first-order law); states as arrays too, one at a time
        in C (about 0.1 ms a state).
    nonhertz : NonHertzTable, optional
        For patch="nonhertz": an :class:`rollerrig.NonHertzTable` built for
        this pair (:func:`nonhertz_table`).
    **options
        The creep-force method's options, as for :func:`creep_forces`;
        FASTSIM's grid defaults to 20 x 20 here.

    Returns
    -------
    RigContact
        ``(pose, left, right, status)`` (:class:`RigContact`): the pose
        (:class:`RigPose`), each wheel's :class:`WheelContact` (for
        patch="nonhertz" a :class:`NonHertzWheel`: each wheel's total force
        and moment, its patches) and the worse of the wheels' statuses.

    Raises
    ------
    RollerRigError
        table not a ContactTable; patch unknown; both or neither of the
        normal and vertical loads (the latter both needed); mu, E, nu or
        vmin not finite or out of range; an unknown method or option; with
        errors="raise", a bad state, naming the argument and its value.
        For patch="nonhertz": nonhertz not a NonHertzTable, a friction law,
        method or options given, mu, E, nu or vmin not one finite number, E
        and nu not those of the table, states not numbers, empty or not
        broadcasting; with errors="raise", a state not finite, y beyond the
        table's rows, a load not positive or with no vertical balance, or
        vertical loads that do not settle.

    See Also
    --------
    linear_creepages : the seed paper's linearised creepages.
    rig_exact : one wheel solved by the exact theory.
    replay : this function over a run's records.

    Notes
    -----
    One wheel's error leaves the other's results valid (see each wheel's
    status).  For patch="nonhertz" with errors "warn" or "ignore", a wheel
    that fails has NaN numbers, no patches and its status (< 0), the other
    wheel is kept (and "warn" warns).

    Examples
    --------
    The centred wheelset on the rig's own pair, the rollers' speed 0.1 %
    under that of the nominal radii (the rolling radii differ from those:
    cx is not -0.001):

    >>> import rollerrig as rr
    >>> rig, params, table = rr.build_rig()
    >>> g, V = table.geometry, 2.0                      # roller surface speed [m/s]
    >>> c = rr.rig_contact(table, y=0.0, spin=V / g.wheel_radius,
    ...                    roller_spin=0.999 * V / g.roller_radius,
    ...                    N_left=100.0, N_right=100.0)
    >>> print(f"cx = {c.left.cx:.5f}, fx = {c.left.fx:.2f} N, status {c.status}")
    cx = -0.00310, fx = 39.95 N, status 0
    """
    func = "rig_contact"
    _check_table(func, table)
    if patch not in ("hertz", "nonhertz"):
        raise RollerRigError(f"{func}: patch must be 'hertz' or 'nonhertz', got {patch!r:.60}")
    loads = _loads(func, N_left, N_right, Fz_left, Fz_right, kinematics_only)
    if patch == "nonhertz":
        return cast("RigContact[NonHertzWheel]", nonhertz_rig_contact(
            func, table, nonhertz, loads, x=x, y=y, yaw=yaw, vx=vx, vy=vy, yaw_rate=yaw_rate,
            spin=spin, roller_spin=roller_spin, mu=mu, friction=friction, E=E, nu=nu,
            vmin=vmin, method=method, options=options, errors=errors, rig_contact=rig_contact,
            make=RigContact, settle=(FZ_TOL, FZ_ITER)))
    if loads[0] == "Fz":
        return _hertz_from_vertical(table, loads[1], loads[2], x=x, y=y, yaw=yaw, vx=vx, vy=vy,
                                    yaw_rate=yaw_rate, spin=spin, roller_spin=roller_spin,
                                    mu=mu, friction=friction, E=E, nu=nu, vmin=vmin,
                                    method=method, errors=errors, **options)
    N_left, N_right = loads[1], loads[2]
    # the rig's grid, 20 x 20, where the method has one (the registry's default is 30 x 30)
    grid = {k: 20 for k in ("nx", "ny") if k in loop_method(func, method).options}
    opts = check_creep_options(func, method, {**grid, **options})
    model = _model(func, table, mu, E, nu, vmin, friction)
    named = dict(x=x, y=y, yaw=yaw, vx=vx, vy=vy, yaw_rate=yaw_rate, spin=spin,
                 roller_spin=roller_spin, N_left=N_left, N_right=N_right)
    shape, scalar, full, flat = _broadcast(func, named)
    status, pose, left, right, sl, sr = core(_core.rig_contact,
        table.data, table.y0, table.dy, model, *flat, kinematics_only=bool(kinematics_only),
        **opts)
    if kinematics_only:
        # no loads were used: do not let a placeholder load be blamed
        full = {k: v for k, v in full.items() if not k.startswith("N_")}
    # the model's constants may explain a failure too (an extreme modulus)
    constants = {name: np.asarray(float(v)) for name, v in
                 (("mu", mu), ("E", E), ("nu", nu), ("vmin", vmin))}
    full.update(constants)

    def status_of(*v: float) -> int:
        """the status of one state under the model of constants v[10:]"""
        m = _model(func, table, v[10], v[11], v[12], v[13], friction)       # mu, E, nu, vmin
        return int(core(_core.rig_contact, table.data, table.y0, table.dy, m,
                        *(np.array([x]) for x in v[:10]),
                        kinematics_only=bool(kinematics_only), **opts)[0][0])
    names = list(named) + list(constants)
    _finish(func, shape, scalar, full, (), status, errors,
            swap_blame(status_of, flat + list(constants.values()), names, _VALID_STATE))
    status = status.reshape(shape)
    p = RigPose(pose[0:3].reshape((3,) + shape), pose[3].reshape(shape),
                pose[4].reshape(shape), pose[5:8].reshape((3,) + shape),
                pose[8:11].reshape((3,) + shape))
    res: RigContact[WheelContact] = RigContact(p, _wheel(left, sl, shape),
                                               _wheel(right, sr, shape), status)
    if scalar:
        res = _scalarise(res)
    return res


def _loads(func: str, N_left: Optional[npt.ArrayLike], N_right: Optional[npt.ArrayLike],
           Fz_left: Optional[npt.ArrayLike], Fz_right: Optional[npt.ArrayLike],
           kinematics_only: bool) -> _Loads:
    """("N" or "Fz", left, right): the normal or the vertical loads, not both."""
    N_given = N_left is not None or N_right is not None
    Fz_given = Fz_left is not None or Fz_right is not None
    if N_given and Fz_given:
        raise RollerRigError(f"{func}: give the normal loads N_left, N_right or the vertical "
                             f"loads Fz_left, Fz_right, not both")
    if Fz_given:
        if Fz_left is None or Fz_right is None:
            raise RollerRigError(f"{func}: give both Fz_left and Fz_right")
        return ("Fz", Fz_left, Fz_right)
    if N_left is None or N_right is None:
        if kinematics_only:
            return ("N", 1.0 if N_left is None else N_left, 1.0 if N_right is None else N_right)
        raise RollerRigError(f"{func}: give the normal loads N_left, N_right or the vertical "
                             f"loads Fz_left, Fz_right [N]")
    return ("N", N_left, N_right)


#: the vertical balance N n_z + fy t2_z = Fz of the Hertzian contact: its
#: fixed point on N converges by the creep force's share (|fy t2_z| << N)
FZ_TOL, FZ_ITER = 1e-9, 50
#: a named tuple of arrays (_scalarise)
_NT = TypeVar("_NT", bound=Tuple[Any, ...])


def _hertz_from_vertical(table: ContactTable, Fz_left: npt.ArrayLike, Fz_right: npt.ArrayLike,
                         **kw: Any) -> RigContact[WheelContact]:
    """rig_contact with the normal loads that carry the vertical loads."""
    func = "rig_contact"
    for name, v in (("Fz_left", Fz_left), ("Fz_right", Fz_right)):
        a = np.asarray(v, dtype=float) if not isinstance(v, bool) else np.array(np.nan)
        if a.dtype.kind != "f" or not np.all(np.isfinite(a)) or not np.all(a > 0):
            raise RollerRigError(f"{func}: {name} must be finite and > 0 [N], got {v!r:.60}")
    Fl, Fr = np.asarray(Fz_left, dtype=float), np.asarray(Fz_right, dtype=float)
    N = [Fl.copy(), Fr.copy()]
    # (N, residual) of the last pass, for the secant
    prev: List[Optional[Tuple[F64Array, F64Array]]] = [None, None]
    for _ in range(FZ_ITER):
        # (kw holds no patch: Hertz's wheels; overloads cannot tell through **kw)
        c = cast("RigContact[WheelContact]", rig_contact(table, N_left=N[0], N_right=N[1], **kw))
        done = True
        for k, (w, F) in enumerate(((c.left, Fl), (c.right, Fr))):
            n_z, t2_z = np.asarray(w.n)[2], np.asarray(w.t2)[2]
            r = (F - np.asarray(w.fy) * t2_z) / n_z - N[k]
            done &= bool(np.all(np.abs(r) <= FZ_TOL * F))
            # a secant on the fixed point's residual: at the flange the creep
            # force's share is large and the plain iteration slow
            step = r
            last = prev[k]
            if last is not None:
                N0, r0 = last
                with np.errstate(all="ignore"):
                    sec = -r * (N[k] - N0) / (r - r0)
                ok = np.isfinite(sec) & (r != r0) & (N[k] + sec > 0)
                step = np.where(ok, sec, r)
            prev[k] = (N[k], r)
            N[k] = np.maximum(N[k] + step, 1e-3 * F)
        if done:
            return c
    raise RollerRigError(f"{func}: the normal loads for Fz_left, Fz_right did not settle")


def _scalarise(t: _NT) -> _NT:
    """0-d arrays of a scalar call as numpy scalars; 3-vectors stay arrays."""
    return type(t)(*(_scalarise(v) if isinstance(v, tuple) else v[()] for v in t))


class LinearCreepages(NamedTuple):
    """One wheel's linearised creepages (eq. 7-9), as
    :func:`linear_creepages` returns them; arrays of the broadcast shape."""

    cx: _Scalar         #: longitudinal creepage [-] (eq. 7)
    cy: _Scalar         #: lateral creepage [-] (eq. 8)
    cphi: _Scalar       #: spin creepage [rad/m] (eq. 9)


def linear_creepages(table: ContactTable, *, y: npt.ArrayLike = 0.0, yaw: npt.ArrayLike = 0.0,
                     vx: npt.ArrayLike = 0.0, vy: npt.ArrayLike = 0.0,
                     yaw_rate: npt.ArrayLike = 0.0, spin: npt.ArrayLike,
                     roller_spin: npt.ArrayLike) -> Tuple[LinearCreepages, LinearCreepages]:
    """The seed paper's linearised creepages (eq. 7-9) at the table geometry.

    Parameters
    ----------
    table : ContactTable
        The contact table of the rig's wheel/roller pair.
    y : float or array_like, optional
        The wheelset's lateral shift [m], inside the table.
    yaw : float or array_like, optional
        Yaw angle [rad].
    vx, vy : float or array_like, optional
        Longitudinal and lateral speed [m/s].
    yaw_rate : float or array_like, optional
        [rad/s].
    spin : float or array_like
        The wheelset's angular speed about its axle [rad/s].
    roller_spin : float or array_like
        The rollers' angular speed [rad/s], non-zero.

    Returns
    -------
    left, right : LinearCreepages
        Each wheel's (cx, cy, cphi) (:class:`LinearCreepages`).

    Raises
    ------
    RollerRigError
        table not a ContactTable; an argument not finite; roller_spin zero
        (V_n = 0 needs the exact creepages); y beyond the table; a
        creepage that overflows.

    See Also
    --------
    rig_contact : the creepages and forces of the full kinematics.

    Notes
    -----
    In this library's conventions (Kalker's sign, a_j the signed lateral
    arm of contact j from the wheelset centre, sigma = +1 left, -1 right),
    with V = roller_spin R0 the roller surface speed and w0 = V/r0::

        cx = (r0 - r)/r0 + (R - R0)/R0 + vx/V - (spin - w0) r0/V - a yaw_rate/V   (7)
        cy = -yaw + (1 + A0 (r + sigma delta a)) vy / V                          (8)
        cphi = -sigma delta (1/r0 + 1/R0)                                        (9)

    A0 = d roll / d y is the paper's geometric parameter (the table's
    slope).  Eq. 7's first term is (r0 - r)(r0 + R0)/(r0 R0) in the paper,
    which is ours when R - R0 = r0 - r (the wheelset at constant height);
    eq. 9 omits the yaw rate's spin, yaw_rate cos(delta)/V, as does the
    paper.
    """
    func = "linear_creepages"
    _check_table(func, table)
    g = table.geometry
    r0, R0 = float(g.wheel_radius), float(g.roller_radius)
    _, _, full, _ = _broadcast(func, dict(y=y, yaw=yaw, vx=vx, vy=vy, yaw_rate=yaw_rate,
                                          spin=spin, roller_spin=roller_spin))
    for name, v in full.items():
        bad = np.flatnonzero(~np.isfinite(v).reshape(-1))
        if bad.size:
            raise RollerRigError(f"{func}: {name} = {float(v.reshape(-1)[bad[0]])!r}: "
                                 f"{status_message(-1)}")
    y, yaw, vx, vy, yaw_rate, spin, roller_spin = full.values()
    # the arithmetic under errstate: an overflow shows as a non-finite
    # creepage, refused below with the arguments named, not as numpy's warning
    with np.errstate(all="ignore"):
        V = roller_spin * R0
        w0 = V / r0
    if np.any(~(np.abs(V) > 0)):
        raise RollerRigError(f"{func}: roller_spin must be non-zero (V_n = 0 needs the exact "
                             f"creepages), got {roller_spin!r:.60}")
    geo = table.lookup(y.reshape(-1), errors="ignore")
    off = np.flatnonzero(geo.status < 0)
    if off.size:
        raise RollerRigError(f"{func}: y = {float(y.reshape(-1)[off[0]])!r}: "
                             f"{status_message(int(geo.status[off[0]]))} (the table spans "
                             f"{table.y_range[0]:g} to {table.y_range[1]:g} m)")
    A0 = table.slopes(y.reshape(-1))[1].reshape(y.shape)
    out = []
    for side, sigma in ((geo.left, 1.0), (geo.right, -1.0)):
        r, R, delta = (getattr(side, f).reshape(y.shape) for f in ("r", "R", "delta"))
        with np.errstate(all="ignore"):
            a = side.y.reshape(y.shape) - y
            cx = (r0 - r) / r0 + (R - R0) / R0 + vx / V - (spin - w0) * r0 / V \
                - a * yaw_rate / V
            cy = -yaw + (1.0 + A0 * (r + sigma * delta * a)) * vy / V
            cphi = -sigma * delta * (1.0 / r0 + 1.0 / R0)
        for name, c in (("cx", cx), ("cy", cy)):
            if not np.all(np.isfinite(c)):
                # a creepage is a rate over V: name the large rates and the divisor
                big = [n for n, v in full.items() if n != "roller_spin" and np.any(np.abs(v) > 1e30)]
                raise RollerRigError(f"{func}: {name} overflows: {', '.join(big) or 'the rates'} "
                                     f"over roller_spin (|roller_spin| down to "
                                     f"{float(np.min(np.abs(roller_spin))):g} rad/s): "
                                     f"{status_message(-12)}")
        out.append(LinearCreepages(cx, cy, cphi))
    return out[0], out[1]
