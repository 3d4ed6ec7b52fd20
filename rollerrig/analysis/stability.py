"""Lateral dynamics and stability of the rig's wheelset, on its rollers and on
tangent track (issue 25; the physics and the checks: docs/lateral_dynamics.md)::

    import rollerrig as rr
    lin = rr.linearize(roller_speed=5.0)             # the plant at its steady state
    lin.A, lin.B, lin.C, lin.D, lin.states, lin.eigenvalues, lin.modes
    scipy.signal.StateSpace(lin.A, lin.B, lin.C, lin.D)   # or lin.to_scipy()
    st = rr.stability(np.linspace(1, 60, 60), track=True)
    st.critical_speed                                # [m/s], NaN if none in the range

The linearisation is of the whole plant (csrc/rig/rr_rig_plant.c: the normal
loads from the vertical and roll balance, the creep forces of the chosen
method, the gyroscopic terms, the drives' lags): central finite differences
of the C right-hand side around a steady state computed here (the wheelset
rolling freely, its drive's torque zero, the roller drive's torque holding
the roller's speed; on track the rails' speed is held by the plant).  The
steps move each contact's creepage by about 2e-8 (a position by 2e-8 m, a
rate by 2e-8 V): the creep forces are linear there (no contact element
saturates before the steady state's own spin does), and the rounding of the
right-hand side (about 1e-13 N on forces of 500 N) stays 1e-11 of the
differences.  tests/test_lateral_linearize.py checks the matrix against a
ten times larger step and the eigenvalues against the time response.

The plant alone: the controllers, encoders and the creepage controller are
not in this linearisation (its inputs are the drives' torque references);
linearize(closed_loop=True) linearises the sampled closed loop with them
(rollerrig/analysis/closed_loop.py).
"""
from __future__ import annotations

import math
from typing import (TYPE_CHECKING, Any, Callable, Dict, List, Literal, NamedTuple, Optional,
                    Sequence, Tuple, Union, overload)

import numpy as np
import numpy.typing as npt

from .._errors import RollerRigError, status_message
from .._optional import require
from .._typing import F64Array, Params
from ..rig.build import build_rig
from ..rig.params import _parameters, _short, _with_track

if TYPE_CHECKING:
    from ..rig.build import Rig
    from .closed_loop import ClosedLoopLinearization

#: the plant's state, in the C order (csrc/rig/rr_rig.h, rr_rig_state_index)
STATES = ("x", "y", "yaw", "chi", "theta_r", "vx", "vy", "yaw_rate", "spin", "roller_spin",
          "torque_roller", "torque_wheelset")
#: the linearisation's inputs: the drives' torque references [N m]
INPUTS = ("torque_ref_roller", "torque_ref_wheelset")
_X, _Y, _YAW, _CHI, _THR, _VX, _VY, _YR, _SPIN, _RSPIN, _TR, _TW = range(12)

#: the finite-difference step of each state, per unit of the scales below
#: (see the module's docstring)
FD_STEP = 2e-8
#: a steady state's accelerations, relative to the largest the plant makes at
#: a 1e-3 disturbance of each state, above which it is refused as not steady
STEADY_TOL = 1e-6
#: a mode whose |eigenvalue| is at most this share of the largest is neutral
#: (Mode.neutral): on the rollers with both torques held, the wheelset and
#: rollers turning faster or slower together (finite differences leave it
#: at about 1e-16 of the largest); not a sign of (in)stability
NEUTRAL_TOL = 1e-10


class Mode(NamedTuple):
    """One mode of a linearisation.

    The states that dominate a mode are those whose participation factors
    ``abs(v_i * w_i)`` (right and left eigenvectors: unit-free) reach 0.1 of
    the largest, the largest first.
    """
    eigenvalue: complex            #: [1/s], the one with Im >= 0 of its pair
    frequency_hz: float            #: damped frequency Im / (2 pi) [Hz]
    damping_ratio: float           #: -Re / abs(eigenvalue): 1 decaying real, -1 growing real
    dominant: Tuple[str, ...]      #: the states that dominate it, the largest first
    neutral: bool = False          #: abs(eigenvalue) <= NEUTRAL_TOL of the largest: a free rotation


class Linearization(NamedTuple):
    """The plant linearised at a steady state (:func:`rollerrig.linearize`).

    ``d(dx)/dt = A dx + B du``, ``dy = C dx + D du``, with dx the state's
    change from `state` and du the inputs' from `inputs0`.
    """
    A: np.ndarray                  #: state matrix [SI per state]
    B: np.ndarray                  #: input matrix
    C: np.ndarray                  #: output matrix (the outputs are the states)
    D: np.ndarray                  #: feedthrough (zero)
    states: Tuple[str, ...]        #: the states' names, in A's order
    inputs: Tuple[str, ...]        #: the inputs' names (the drives' torque references)
    outputs: Tuple[str, ...]       #: the outputs' names
    #: eigenvalues of A [1/s], the structural zeros of the cyclic angles chi,
    #: theta_r and, on track, the rails' held speed included
    eigenvalues: np.ndarray
    modes: Tuple[Mode, ...]        #: the rest, one per pair, least damped first
    state: np.ndarray              #: the steady state linearised about
    inputs0: np.ndarray            #: the inputs there
    roller_speed: float            #: roller (or track) surface speed [m/s]
    track: bool                    #: on tangent track

    def to_scipy(self) -> Any:
        """The model as ``scipy.signal.StateSpace(A, B, C, D)`` (needs scipy)."""
        from scipy import signal  # type: ignore[import-untyped]  # (no stubs: scipy-stubs)
        return signal.StateSpace(self.A, self.B, self.C, self.D)

    @property
    def least_damped(self) -> Mode:
        """The mode of largest real part, not neutral (rollerrig.stability's)."""
        return self.modes[0]


class Stability(NamedTuple):
    """The plant's modes against speed (:func:`rollerrig.stability`)."""
    speeds: np.ndarray             #: [m/s]
    #: the modes' eigenvalues per speed (speeds x modes, complex, Im >= 0 of
    #: each pair, NaN-padded) [1/s]
    eigenvalues: np.ndarray
    max_real: np.ndarray           #: the largest real part per speed [1/s]
    min_damping: np.ndarray        #: the least damping ratio per speed
    #: the first speed where the largest real part crosses zero upward,
    #: refined by Brent's method to 1e-10 relative [m/s]; NaN if none in the range
    critical_speed: float
    critical_mode: object          #: the Mode there (None without a critical speed)
    track: bool                    #: on tangent track
    modes: Tuple[Tuple[Mode, ...], ...] = ()   #: each speed's Linearization.modes


def _scales(V: float, r0: float, R0: float) -> F64Array:
    """The step unit of each state (module docstring)."""
    V = max(abs(V), 1e-3)
    return np.array([1.0, 1.0, 1.0, 100.0, 100.0, V, V, V, V / r0, V / R0, 100.0, 100.0])


class _Plant:
    """The C plant at one parameter set, for any roller speed."""

    def __init__(self, func: str, params: Params, roller_speed: Optional[float], track: bool,
                 method: Optional[str], creep: Dict[str, Any]) -> None:
        P: Dict[str, Dict[str, Any]] = _with_track(func, _parameters(func, params), track)
        self.rig: Rig
        self.P: Dict[str, Dict[str, Any]]
        self.rig, self.P, _ = build_rig(P, method=method, roller_speed=roller_speed, **creep)
        self.track = bool(P["scenario"]["track"])
        self.R0 = float(P["roller"]["radius_m"])
        self.r0 = float(P["wheelset"]["wheel_radius_m"])
        self.taus = (float(P["roller_drive"]["lag_time_constant_s"]),
                     float(P["wheelset_drive"]["lag_time_constant_s"]))
        self.y_init: F64Array = np.array(self.rig.y, dtype=np.float64)
        self.V0 = float(self.y_init[_RSPIN] * self.R0)
        self.func = func

    def f(self, y: F64Array) -> F64Array:
        dy: F64Array
        st: int
        dy, st = self.rig.rhs(0.0, y)
        if st < 0:
            raise RollerRigError(f"{self.func}: the plant cannot be evaluated at state "
                                 f"{dict(zip(STATES, np.round(y, 12)))}: "
                                 f"{status_message(st)}")
        return dy

    # the unknowns of the steady state and the rates that must vanish
    def unknowns(self) -> List[int]:
        return [_X, _Y, _YAW, _SPIN] + ([] if self.track else [_TR])

    def residual_rows(self) -> List[int]:
        return [_VX, _VY, _YR, _SPIN] + ([] if self.track else [_RSPIN])

    def steady(self, V: float) -> F64Array:
        """The steady state at roller surface speed V: the rates zero, the
        wheelset's torque zero, positions, spin and the roller's torque by
        Newton's method on central differences of the plant, each step held
        to 0.1 mm (0.1 mrad, 1e-4 of the spin): a nearly free wheelset's
        lateral stiffness is close to zero, and its centred state is steady
        by symmetry up to rounding."""
        y = self.y_init.copy()
        y[_RSPIN] = V / self.R0
        y[_SPIN] = self.y_init[_SPIN] * V / self.V0 if self.V0 else V / self.r0
        y[[_X, _Y, _YAW, _VX, _VY, _YR, _TR, _TW]] = 0.0
        u, rows = self.unknowns(), self.residual_rows()
        cap = np.array([1e-4, 1e-4, 1e-4, 1e-4 * abs(y[_SPIN]) + 1e-9, 10.0])[:len(u)]
        scale = self._accel_scale(y)[rows]
        for _ in range(60):
            r = self.f(y)[rows]
            if np.all(np.abs(r) <= 1e-12 * scale):
                return y
            h = FD_STEP * _scales(V, self.r0, self.R0)
            J = np.empty((len(rows), len(u)))
            for c, j in enumerate(u):
                zp, zm = y.copy(), y.copy()
                zp[j] += h[j]
                zm[j] -= h[j]
                J[:, c] = (self.f(zp)[rows] - self.f(zm)[rows]) / (2.0 * h[j])
            step = np.linalg.lstsq(J, -r, rcond=1e-12)[0]
            y[u] += step * min(1.0, float(np.min(cap / np.maximum(np.abs(step), 1e-300))))
        return y

    def _accel_scale(self, y: F64Array) -> F64Array:
        """The largest rate change of each row at a 1e-3 disturbance of each
        state (relative units): what 'steady' is measured against."""
        s = 1e-3 * _scales(y[_RSPIN] * self.R0, self.r0, self.R0)
        f0 = self.f(y)
        out = np.zeros(12)
        for j in (_Y, _YAW, _VX, _VY, _SPIN):
            z = y.copy()
            z[j] += s[j]
            out = np.maximum(out, np.abs(self.f(z) - f0))
        return np.maximum(out, 1e-300)

    def jacobian(self, y: F64Array, step: float = FD_STEP) -> F64Array:
        """Central differences of the C right-hand side at y."""
        h = step * _scales(y[_RSPIN] * self.R0, self.r0, self.R0)
        A = np.empty((12, 12))
        for j in range(12):
            zp, zm = y.copy(), y.copy()
            zp[j] += h[j]
            zm[j] -= h[j]
            A[:, j] = (self.f(zp) - self.f(zm)) / (2.0 * h[j])
        return A


def _structural(A: F64Array) -> List[int]:
    """The states that take part in the dynamics: not a cyclic angle (a zero
    column: chi; theta_r without an adhesion patch) nor a held one (a zero
    row: the rails' speed on track).  Their eigenvalues are exactly zero."""
    keep = np.ones(A.shape[0], dtype=bool)
    while keep.any():
        sub = A[np.ix_(keep, keep)]
        drop = ~sub.any(axis=0) | ~sub.any(axis=1)
        if not drop.any():
            break
        keep[np.flatnonzero(keep)[drop]] = False
    return [int(i) for i in np.flatnonzero(keep)]


def _modes(A: F64Array, states: Sequence[str]) -> Tuple[Mode, ...]:
    keep = _structural(A)
    if not keep:
        return ()
    Ar = A[np.ix_(keep, keep)]
    lam, V = np.linalg.eig(Ar)
    try:
        W = np.linalg.inv(V)
    except np.linalg.LinAlgError:
        W = np.linalg.pinv(V)
    modes: List[Mode] = []
    top = float(np.max(np.abs(lam)))
    for k in np.argsort(-lam.real):
        z = lam[k]
        if z.imag < 0:
            continue
        part = np.abs(V[:, k] * W[k, :])
        order = np.argsort(-part)
        dom = tuple(states[keep[i]] for i in order if part[i] >= 0.1 * part[order[0]])
        mag = abs(z)
        zeta = -z.real / mag if mag > 0 else math.nan
        modes.append(Mode(complex(z), abs(z.imag) / (2 * math.pi), float(zeta), dom,
                          bool(mag <= NEUTRAL_TOL * top)))
    # least damped first, the neutral ones last
    return tuple(sorted(modes, key=lambda m: (m.neutral, -m.eigenvalue.real)))


def _speed_arg(func: str, name: str, v: object) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float, np.floating, np.integer)):
        raise RollerRigError(f"{func}: {name} must be a real number [m/s], got {_short(v)}")
    try:
        v = float(v)
    except OverflowError:                      # an int beyond a double
        v = math.inf
    if not math.isfinite(v) or v <= 0.0:
        raise RollerRigError(f"{func}: {name} must be a finite speed > 0 [m/s], got {v!r}")
    return v


def _linearize_at(plant: _Plant, V: float, state: Optional[npt.ArrayLike] = None,
                  func: str = "linearize") -> Linearization:
    if state is None:
        y = plant.steady(V)
    else:
        y = np.asarray(state, dtype=float)
        if y.shape != (12,) or not np.all(np.isfinite(y)):
            raise RollerRigError(f"{func}: state must be 12 finite values (STATES), got "
                                 f"{_short(state)}")
    rows = plant.residual_rows()
    r = plant.f(y)
    scale = plant._accel_scale(y)
    bad = [STATES[i] for i in rows if abs(r[i]) > STEADY_TOL * scale[i]]
    if bad:
        what = "state" if state is not None else "the steady state found"
        raise RollerRigError(f"{func}: {what} is not steady: the rates of "
                             f"{', '.join(bad)} are {', '.join(f'{r[STATES.index(b)]:.3g}' for b in bad)}"
                             f" (a linearisation holds only about a steady state)")
    A = plant.jacobian(y)
    B = np.zeros((12, 2))
    B[_TR, 0] = 1.0 / plant.taus[0]
    B[_TW, 1] = 1.0 / plant.taus[1]
    C = np.eye(12)
    D = np.zeros((12, 2))
    lam = np.linalg.eigvals(A)
    lam = lam[np.argsort(-lam.real)]
    return Linearization(A, B, C, D, STATES, INPUTS, STATES, lam, _modes(A, STATES), y,
                         np.array([y[_TR], y[_TW]]), float(y[_RSPIN] * plant.R0),
                         plant.track)


# the result's type follows closed_loop (a user's strict script gets the one it asked for)
@overload
def linearize(params: Params = None, *, roller_speed: Optional[float] = None,
              track: bool = False, state: Optional[npt.ArrayLike] = None,
              method: Optional[str] = None, closed_loop: Literal[False] = False,
              creepage_target: None = None, **creep: Any) -> Linearization: ...
@overload
def linearize(params: Params = None, *, roller_speed: Optional[float] = None,
              track: bool = False, state: Optional[npt.ArrayLike] = None,
              method: Optional[str] = None, closed_loop: Literal[True],
              creepage_target: Optional[float] = None,
              **creep: Any) -> "ClosedLoopLinearization": ...
@overload
def linearize(params: Params = None, *, roller_speed: Optional[float] = None,
              track: bool = False, state: Optional[npt.ArrayLike] = None,
              method: Optional[str] = None, closed_loop: bool = False,
              creepage_target: Optional[float] = None,
              **creep: Any) -> Union[Linearization, "ClosedLoopLinearization"]: ...
def linearize(params: Params = None, *, roller_speed: Optional[float] = None,
              track: bool = False, state: Optional[npt.ArrayLike] = None,
              method: Optional[str] = None, closed_loop: bool = False,
              creepage_target: Optional[float] = None,
              **creep: Any) -> Union[Linearization, "ClosedLoopLinearization"]:
    """The rig's plant linearised at its steady state.

    Parameters
    ----------
    params : None, dict or str
        The rig's parameters as for :func:`rollerrig.simulate` (a nested dict
        or a TOML path); ``{"wheelset": {"gyroscopic": False}}`` leaves the
        gyroscopic terms out.
    roller_speed : float, optional
        Roller surface speed [m/s] (on track: the speed along it), > 0;
        default ``scenario.roller_speed_m_s``.
    track : bool
        True: the same wheelset on tangent track.
    state : array_like, optional
        A plant state (12 values, ``STATES``) to linearise about instead of
        the steady state found here; refused where it is not steady.
    method : str, optional
        The creep-force method (as :func:`rollerrig.simulate`).
    closed_loop : bool
        True: the sampled closed loop with the drives, encoders and
        controllers, the wheelset held at free rolling, as a map over one
        control sample (``state`` then a full state dict,
        :meth:`rollerrig.Rig.full_state`), on the rollers or on track (the
        rail's speed then rounded to whole counts of its encoder a sample:
        ``roller_speed`` of the result, within half a count a sample, 7e-5
        of 5 m/s, 4e-4 of 1 m/s).
    creepage_target : float, optional
        With ``closed_loop``: the loop under the rig's creepage controller
        at this target creepage (finite, ``abs < 0.5``), linearised on its
        proportional law about the creepage at the target (the recovery
        law's fixed step past the target is not differentiable: between
        its steps the loop follows the proportional law;
        docs/lateral_dynamics.md).  Default: free rolling.
    **creep
        The method's options.

    Returns
    -------
    Linearization or ClosedLoopLinearization
        A, B, C, D with the named states, inputs and outputs, the eigenvalues
        and the modes; closed loop: the discrete map over one sample, its
        eigenvalues z and their continuous equivalents log(z) / T.

    Raises
    ------
    RollerRigError
        A bad argument, named; a state that is not steady; a closed loop
        whose finite differences the encoders' counts do not resolve.
    """
    func = "linearize"
    if not isinstance(closed_loop, bool):
        raise RollerRigError(f"{func}: closed_loop must be True or False, got "
                             f"{_short(closed_loop)}")
    if creepage_target is not None:
        if not closed_loop:
            raise RollerRigError(f"{func}: creepage_target needs closed_loop=True (the "
                                 "plant alone has no creepage controller)")
        if (isinstance(creepage_target, bool) or not isinstance(creepage_target, (int, float))
                or not abs(creepage_target) < 0.5):
            raise RollerRigError(f"{func}: creepage_target must be a finite number with "
                                 f"abs < 0.5, got {_short(creepage_target)}")
        creepage_target = float(creepage_target)
    if roller_speed is not None:
        roller_speed = _speed_arg(func, "roller_speed", roller_speed)
    plant = _Plant(func, params, roller_speed, track, method, creep)
    if closed_loop:
        from .closed_loop import closed_loop_linearize
        return closed_loop_linearize(plant, plant.V0, state, func, creepage_target)
    return _linearize_at(plant, plant.V0, state, func)


def _max_real(modes: Sequence[Mode]) -> float:
    return max((m.eigenvalue.real for m in modes if not m.neutral), default=math.nan)


def _speeds_arg(func: str, speeds: npt.ArrayLike) -> F64Array:
    try:
        s = np.asarray(speeds, dtype=float)
    except (TypeError, ValueError):
        raise RollerRigError(f"{func}: speeds must be an array of speeds [m/s], got "
                             f"{_short(speeds)}") from None
    if s.ndim == 0:
        s = s.reshape(1)
    if s.ndim != 1 or s.size == 0:
        raise RollerRigError(f"{func}: speeds must be a non-empty 1-D array [m/s], got shape "
                             f"{s.shape}")
    bad = ~np.isfinite(s) | (s <= 0)
    if np.any(bad):
        raise RollerRigError(f"{func}: speeds must be finite and > 0 [m/s], got "
                             f"{s[bad][0]!r} at index {int(np.flatnonzero(bad)[0])}")
    if np.any(np.diff(s) <= 0):
        raise RollerRigError(f"{func}: speeds must be increasing")
    return s


def _sweep(s: F64Array, modes_at: Callable[[float], Tuple[Mode, ...]]
           ) -> Tuple[npt.NDArray[np.complex128], F64Array, F64Array, float, Optional[Mode],
                      Tuple[Tuple[Mode, ...], ...]]:
    """Modes at each speed, the largest real part and least damping, and the
    first upward zero crossing of the largest real part refined by Brent's
    method (NaN, None where there is none)."""
    per = [modes_at(V) for V in s]
    n = max((len(m) for m in per), default=0)
    eig = np.full((s.size, n), complex(math.nan, math.nan))
    for i, m in enumerate(per):
        eig[i, :len(m)] = [x.eigenvalue for x in m]
    mr = np.array([_max_real(m) for m in per])
    md = np.array([min((x.damping_ratio for x in m if not x.neutral), default=math.nan)
                   for m in per])
    crit, mode = math.nan, None
    up = np.flatnonzero((mr[:-1] < 0) & (mr[1:] >= 0))
    if up.size:
        brentq = require("scipy.optimize", "the critical speed (stability, critical_speed)", "fit").brentq
        i = int(up[0])
        crit = brentq(lambda V: _max_real(modes_at(V)), s[i], s[i + 1], xtol=1e-12,
                      rtol=1e-10)
        mode = next(m for m in modes_at(crit) if not m.neutral)
    return eig, mr, md, float(crit), mode, tuple(per)


def _system_modes(func: str, system: Callable[[float], npt.ArrayLike],
                  V: float) -> Tuple[Mode, ...]:
    A = np.asarray(system(V), dtype=float)
    if A.ndim != 2 or A.shape[0] != A.shape[1] or not np.all(np.isfinite(A)):
        raise RollerRigError(f"{func}: system({V:g}) must return a finite square matrix, got "
                             f"shape {A.shape}")
    return _modes(A, tuple(f"s{i}" for i in range(A.shape[0])))


def critical_speed(system: Callable[[float], npt.ArrayLike], speeds: npt.ArrayLike) -> float:
    """The linear critical speed of any linear model.

    Parameters
    ----------
    system : callable
        ``system(V) -> A``, a square matrix with ``dx/dt = A x`` at speed V.
    speeds : array_like
        Increasing speeds [m/s], each finite and > 0.

    Returns
    -------
    float
        The first upward zero crossing of the largest real part of A's modes
        (neutral ones and the structural zeros left out, as
        :func:`rollerrig.stability`) in `speeds`, refined by Brent's method to
        1e-10 relative [m/s]; NaN if none.  :func:`rollerrig.stability` is
        this with the rig's plant.
    """
    func = "critical_speed"
    if not callable(system):
        raise RollerRigError(f"{func}: system must be a callable V -> A, got {_short(system)}")
    s = _speeds_arg(func, speeds)
    return _sweep(s, lambda V: _system_modes(func, system, V))[3]


def stability(speeds: npt.ArrayLike, params: Params = None, *, track: bool = False,
              method: Optional[str] = None, **creep: Any) -> Stability:
    """The plant's eigenvalues against speed and its linear critical speed.

    Parameters
    ----------
    speeds : array_like
        Increasing roller (or track) speeds [m/s], each finite and > 0, at
        least one.
    params, track, method, **creep
        As :func:`rollerrig.linearize`.

    Returns
    -------
    Stability
        The critical speed is the first interval of `speeds` where the largest
        real part of the modes (not neutral) goes from < 0 to >= 0, refined by
        Brent's method to 1e-10 relative; NaN if none (below the first speed
        the plant may already be unstable: ``max_real`` says).
    """
    func = "stability"
    s = _speeds_arg(func, speeds)
    plant = _Plant(func, params, float(s[0]), track, method, creep)
    eig, mr, md, crit, mode, per = _sweep(s, lambda V: _linearize_at(plant, V, None,
                                                                      func).modes)
    return Stability(s, eig, mr, md, crit, mode, plant.track, per)
