"""The rig's sampled-data closed loop linearised at its steady state
(rollerrig.linearize(..., closed_loop=True); docs/lateral_dynamics.md).

The loop is a discrete-time map over one control sample T, x_{k+1} = F(x_k):
one sample of the C rig (the encoders read, the PI controllers and the
creepage controller act, the plant is integrated over T) from its full state
(Rig.full_state).  Its Jacobian A is taken by central differences of F about
the steady state the rig settles to under its speed controllers at the
roller speed, the wheelset held at free rolling (no creepage target), or
under the creepage controller at a target (_creep_loop: its proportional
law, K a coordinate); on the rollers or on track (_track_loop).

Coordinates: the plant's states but the two unwrapped angles, which grow
without bound; in their place each encoder's angle since its last count,
d = angle - count 2 pi / counts (what its next speed estimate differences);
the PI integrals.  The held references, the PI outputs and the creepage
controller's K, reference and estimate are overwritten at every sample
without a creepage target, so F does not depend on them: they are not
coordinates.

The encoders' quantisation: F is piecewise constant in an angle at the
sample's start (the counter takes its floor), so a difference over a step
that is not a whole number of counts would see the quantiser's jumps.  The
steps of d are whole numbers of counts (at least one): the counter then
moves by exactly that number and the encoder's part of F is exact; the other
coordinates do not move the angle at the sample's start (the counter reads
it before the plant moves), so no difference crosses a count.  The matrix is
checked against steps four times larger: its dominant |z| must agree to
CHECK_TOL, or the call fails naming the disagreement.
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Dict, List, NamedTuple, Optional, Protocol, Sequence, Tuple

import numpy as np
import numpy.typing as npt

from .._errors import RollerRigError, status_message
from .._typing import F64Array

if TYPE_CHECKING:
    from ..rig.build import Rig

#: a full state (Rig.full_state): name -> value
FullState = Dict[str, float]


class _PlantLike(Protocol):
    """What the loop takes of stability._Plant (not imported: it imports us)."""
    rig: Rig
    R0: float
    r0: float
    track: bool

#: the closed loop's coordinates, in this order
STATES = ("x", "y", "yaw", "vx", "vy", "yaw_rate", "spin", "roller_spin", "torque_roller",
          "torque_wheelset", "roller_angle_since_count", "wheelset_angle_since_count",
          "roller_pi_integral", "wheelset_pi_integral", "creepctl_K")
_PLANT = STATES[:10]
_K = STATES.index("creepctl_K")
#: the relative finite-difference step (per unit of each coordinate's scale)
FD_STEP = 2e-8
#: the dominant |z| at FD_STEP and at 4 FD_STEP must agree to this (relative)
CHECK_TOL = 1e-5
#: samples run to reach the steady state, at most
MAX_SETTLE = 200_000
#: under creepage control the samples are taken at the target plus this
#: (see _creep_loop): 20 counts' creepage of the default encoders
CREEP_OFFSET = 2e-4
#: samples run under creepage control before the fixed point is sought
CREEP_SETTLE = 4000
#: Newton steps to the fixed point under creepage control, at most
CREEP_NEWTON = 8
#: steady: the fixed point lies within this (per unit of each scale) of the
#: state, besides the shift two encoder counts make
STEADY_TOL = 1e-6


class ClosedLoopMode(NamedTuple):
    """One mode of the sampled closed loop: z (Im >= 0 of its pair), the
    continuous equivalent log(z)/T [1/s], its frequency [Hz] and damping
    ratio from that, and the coordinates that dominate it (participation
    >= 0.1 of the largest, largest first)."""
    z: complex
    eigenvalue: complex
    frequency_hz: float
    damping_ratio: float
    dominant: Tuple[str, ...]


class ClosedLoopLinearization(NamedTuple):
    """x_{k+1} - x* = A (x_k - x*) over one sample T [s]: A (discrete), the
    coordinates `states`, the eigenvalues z of A (largest |z| first) and
    their continuous equivalents log(z)/T [1/s], the modes (one per pair,
    largest |z| first), the steady state x* and the rig's full state there,
    the roller speed [m/s]; a closed loop is stable where every |z| < 1."""
    A: np.ndarray
    states: Tuple[str, ...]
    z: np.ndarray
    eigenvalues: np.ndarray
    modes: Tuple[ClosedLoopMode, ...]
    state: np.ndarray
    full_state: Dict[str, float]
    T: float
    roller_speed: float
    track: bool
    #: the creepage controller's target (NaN: free rolling, no creepage control)
    creepage_target: float = math.nan
    #: the roller drive's speed reference the loop runs at [rad/s] (a time
    #: run from full_state reproduces the loop with it)
    roller_reference: float = math.nan

    @property
    def spectral_radius(self) -> float:
        return float(np.max(np.abs(self.z)))


class _Loop:
    """One sample of the rig from the closed loop's coordinates."""

    def __init__(self, rig: Rig, func: str, roller_ref: float, R0: float, r0: float) -> None:
        self.rig, self.func, self.roller_ref = rig, func, roller_ref
        self.R0, self.r0 = R0, r0
        info = rig.info
        self.T = float(info.dt)
        self.q = (2.0 * math.pi / info.roller_counts, 2.0 * math.pi / info.wheelset_counts)
        self.base: FullState = {}
        self.keep = list(range(14))
        # the creepage target (NaN: free rolling), the offset the samples are
        # taken at and the change of the controller's K it makes (_creep_loop)
        self.xi, self.delta, self.shift_K = math.nan, 0.0, 0.0

    def coords(self, s: FullState) -> F64Array:
        return np.array([s[k] for k in _PLANT]
                        + [s["theta_r"] - s["roller_count"] * self.q[0],
                           s["chi"] - s["wheelset_count"] * self.q[1],
                           s["roller_pi_integral"], s["wheelset_pi_integral"],
                           s["creepctl_K"]])

    def full(self, x: F64Array) -> FullState:
        s = dict(self.base, **dict(zip(_PLANT, (float(v) for v in x[:10]))))
        s["theta_r"] = self.base["roller_count"] * self.q[0] + x[10]
        s["chi"] = self.base["wheelset_count"] * self.q[1] + x[11]
        s["roller_pi_integral"], s["wheelset_pi_integral"] = float(x[12]), float(x[13])
        s["creepctl_K"] = float(x[_K])
        return s

    def F(self, x: F64Array) -> F64Array:
        st = self.rig.set_full_state(self.full(x))
        if st >= 0:
            _, st = self.rig.run([self.roller_ref], [self.xi + self.delta])
        if st < 0:
            raise RollerRigError(f"{self.func}: the closed loop cannot take a sample from "
                                 f"{dict(zip(STATES, np.round(x, 12)))}: {status_message(st)}")
        return self.coords(self.rig.full_state())

    def scales(self, x: F64Array) -> F64Array:
        """Each coordinate's unit for the steps and the steadiness test: the
        positions 1 m, the rates the speed, the torques and integrals 100
        N m, the angles since a count the angle a sample turns."""
        V = max(abs(x[7]) * self.R0, 1e-3)
        turn = (max(abs(x[7]), 1e-3) * self.T, max(abs(x[6]), 1e-3) * self.T)
        return np.array([1.0, 1.0, 1.0, V, V, V, V / self.r0, V / self.R0, 100.0, 100.0,
                         turn[0], turn[1], 100.0, 100.0, 1.0])

    def residual(self, x: F64Array, A: F64Array) -> F64Array:
        """F(x) - x over `keep` for the loop's own target: under creepage
        control less the offset's part, the K column of A times the change
        of K the offset makes (exact to first order: K enters the sample
        only through K + sense alpha (target - creepage))."""
        r = (self.F(x) - x)[self.keep]
        if self.shift_K:
            r -= A[:, self.keep.index(_K)] * self.shift_K
        return r

    def jacobian(self, x: F64Array, step: float) -> F64Array:
        """Central differences over the coordinates `keep`: A[keep, keep]."""
        sc = self.scales(x)
        A = np.empty((len(self.keep), len(self.keep)))
        for c, j in enumerate(self.keep):
            h = step * sc[j]
            if j in (10, 11):     # whole counts: the counter moves by exactly as many
                q = self.q[j - 10]
                h = max(1.0, round(h / q)) * q
            xp, xm = x.copy(), x.copy()
            xp[j] += h
            xm[j] -= h
            A[:, c] = ((self.F(xp) - self.F(xm)) / (xp[j] - xm[j]))[self.keep]
        return A


def _continuous(z: complex, T: float) -> complex:
    """log(z) / T; a mode gone within one sample (z exactly 0: on track the
    rail encoder's angle since a count, read exactly) at -inf."""
    return complex(-math.inf, 0.0) if z == 0 else complex(np.log(complex(z))) / T


def _modes(A: F64Array, T: float, names: Sequence[str]) -> Tuple[ClosedLoopMode, ...]:
    z, V = np.linalg.eig(A)
    try:
        W = np.linalg.inv(V)
    except np.linalg.LinAlgError:
        W = np.linalg.pinv(V)
    out: List[ClosedLoopMode] = []
    for k in np.argsort(-np.abs(z)):
        if z[k].imag < 0:
            continue
        lam = _continuous(complex(z[k]), T)
        part = np.abs(V[:, k] * W[k, :])
        order = np.argsort(-part)
        dom = tuple(names[i] for i in order if part[i] >= 0.1 * part[order[0]])
        mag = abs(lam)
        zeta = 1.0 if math.isinf(mag) else float(-lam.real / mag) if mag > 0 else math.nan
        out.append(ClosedLoopMode(complex(z[k]), lam, abs(lam.imag) / (2 * math.pi), zeta, dom))
    return tuple(out)


def _rebased(rig: Rig, s: FullState, func: str) -> FullState:
    """The full state with each angle moved back by whole turns into [0, 2
    pi) and its counter by as many turns' counts: the same state to the rig
    (the angles are cyclic but for the adhesion patch, which repeats each
    turn), whose angles' rounding (1e-13 rad at 600 rad) no longer swamps
    the differences of F's angles since a count."""
    info = rig.info
    s = dict(s)
    for angle, count, counts in (("theta_r", "roller_count", info.roller_counts),
                                 ("chi", "wheelset_count", info.wheelset_counts)):
        n = math.floor(s[angle] / (2.0 * math.pi))
        s[angle] -= 2.0 * math.pi * n
        s[count] -= float(n) * counts
    st = rig.set_full_state(s)
    if st < 0:
        raise RollerRigError(f"{func}: the rig refuses its own state rebased by whole turns: "
                             f"{status_message(st)}")
    out: FullState = rig.full_state()
    return out


def _track_loop(loop: _Loop, rig: Rig, state: Optional[FullState], func: str) -> None:
    """On track: the rails' held speed and the roller drive, which acts on
    nothing there, are not coordinates (roller_spin is constant, the roller
    PI's integral and torque move nothing: their z = 1 and exp(-T/tau) would
    only hide the loop's own); and the track encoder must read a whole number
    of counts each sample.  Its counts are capped at 2^31 - 1 a turn of the
    1000 m rail (rollerrig.rig.params), 2.9 um: at 5 m/s a sample is 6835.65
    counts, so the speed it reads alternates by one count (1.5e-4 of the
    speed) and the wheelset's reference with it -- the loop is forced at the
    sample rate, never steady (the 'drift' of -8e-5 m/s a block end showed
    was that forced cycle, x +-2.4e-7 m, vx +-1.5e-4 m/s, its mean 3e-8 m/s).
    So the rail's speed is rounded to a whole number n of counts a sample
    (a relative change below 1 / (2 n): 5.1e-5 at 5 m/s) and its angle starts
    half a count past a count: the reading is then the same every sample
    and the loop has a fixed point.  A given `state` keeps its own rail
    speed (and must be steady on its own)."""
    loop.keep = [i for i in range(14)
                 if STATES[i] not in ("roller_spin", "torque_roller", "roller_pi_integral")]
    q = loop.q[0]
    if state is not None:
        if isinstance(state, dict) and isinstance(state.get("roller_spin"), (int, float)):
            loop.roller_ref = float(state["roller_spin"])
        return
    n = max(1, round(loop.roller_ref * loop.T / q))
    loop.roller_ref = n * q / loop.T
    s = rig.full_state()
    s.update(roller_spin=loop.roller_ref, theta_r=0.5 * q, roller_count=0.0,
             roller_enc_speed=loop.roller_ref)
    st = rig.set_full_state(s)
    if st < 0:
        raise RollerRigError(f"{func}: the rig refuses the rail's speed rounded to whole "
                             f"counts a sample: {status_message(st)}")


def _creep_loop(loop: _Loop, rig: Rig, xi: float, state: Optional[FullState],
                func: str) -> None:
    """Under the creepage controller (eq. 13-14): K moves by sense alpha
    (target - creepage) while the creepage is short of the target in its
    sense (the proportional law), by a fixed -sense beta past it (the
    recovery law).  The map jumps at the target, so the loop never rests
    there: it runs a sawtooth (a recovery step, then the proportional law's
    geometric approach, until the encoders' jitter crosses the target).  Its
    linearisation is the proportional law's, about its fixed point (the
    creepage at the target): what the loop follows between recovery steps.
    The samples are taken at the target plus CREEP_OFFSET (20 counts of
    creepage: no difference crosses the target), which adds sense alpha
    CREEP_OFFSET to the K a sample ends with, the same for every difference:
    the derivatives are of the same law, at K 2e-6 off (their change from
    that is below the differences' own error), and the residual is taken
    less it (_Loop.residual)."""
    if state is not None and not (state.get("creep_control") == 1.0
                                  and state.get("xi_ref") == xi):
        raise RollerRigError(f"{func}: with creepage_target {xi:g}, state must be under "
                             f"creepage control at that target (creep_control 1, xi_ref "
                             f"{xi:g}), got creep_control {state.get('creep_control')!r}, "
                             f"xi_ref {state.get('xi_ref')!r}")
    info = rig.info
    loop.keep = loop.keep + [_K]
    loop.xi, loop.delta = xi, CREEP_OFFSET
    loop.shift_K = info.sense * info.alpha * CREEP_OFFSET


def _settle_creep(loop: _Loop, rig: Rig, V: float, func: str) -> int:
    """Settled under creepage control: CREEP_SETTLE samples (onto the
    sawtooth), then Newton's method on the proportional law's fixed point
    (each step's matrix by the differences the linearisation takes)."""
    _, st = rig.run(np.full(CREEP_SETTLE, loop.roller_ref), np.full(CREEP_SETTLE, loop.xi))
    if st < 0:
        raise RollerRigError(f"{func}: the closed loop under creepage control does not "
                             f"settle at {V:g} m/s: {status_message(st)}")
    loop.base = _rebased(rig, rig.full_state(), func)
    x = loop.coords(loop.base)
    for _ in range(CREEP_NEWTON):
        A = loop.jacobian(x, FD_STEP)
        dx = np.linalg.solve(np.eye(len(loop.keep)) - A, loop.residual(x, A))
        x[loop.keep] += dx
        if np.all(np.abs(dx) <= 1e-3 * STEADY_TOL * loop.scales(x)[loop.keep]):
            break
    st = rig.set_full_state(loop.full(x))
    if st < 0:
        raise RollerRigError(f"{func}: the rig refuses the fixed point under creepage "
                             f"control: {status_message(st)}")
    return CREEP_SETTLE


def closed_loop_linearize(plant: _PlantLike, V: float, state: object, func: str,
                          creepage_target: Optional[float] = None) -> ClosedLoopLinearization:
    """The closed loop of the rig `plant.rig` (stability._Plant) at roller
    surface speed V, free rolling or under creepage control at
    `creepage_target`: settled there from its start (or at `state`, a full
    state dict of Rig.full_state, refused if not steady)."""
    rig = plant.rig
    loop = _Loop(rig, func, V / plant.R0, plant.R0, plant.r0)
    if state is not None and not isinstance(state, dict):
        raise RollerRigError(f"{func}: with closed_loop, state must be a full state dict "
                             f"(Rig.full_state()), got {type(state).__name__}")
    if plant.track:
        _track_loop(loop, rig, state, func)
        V = loop.roller_ref * plant.R0
    if creepage_target is not None:
        _creep_loop(loop, rig, creepage_target, state, func)
    keep = loop.keep
    names = tuple(STATES[i] for i in keep)
    plant_rows = [i for i in keep if i < 10]
    if state is not None:
        st = rig.set_full_state(state)
        if st < 0:
            raise RollerRigError(f"{func}: state refused by the rig: {status_message(st)}")
        if creepage_target is None and state.get("creep_control", 0.0) != 0.0:
            raise RollerRigError(f"{func}: state is under creepage control (creep_control 1);"
                                 " linearise it with creepage_target (its xi_ref)")
    done = 0
    if state is None and creepage_target is not None:
        done = _settle_creep(loop, rig, V, func)
    elif state is None:
        block = 2000
        prev = None
        while done < MAX_SETTLE:
            _, st = rig.run(np.full(block, loop.roller_ref), np.full(block, math.nan))
            if st < 0:
                raise RollerRigError(f"{func}: the closed loop does not settle at "
                                     f"{V:g} m/s: {status_message(st)}")
            done += block
            x = loop.coords(rig.full_state())
            if prev is not None and np.all(np.abs(x - prev)[plant_rows]
                                           <= 1e-9 * loop.scales(x)[plant_rows]):
                break
            prev = x
    loop.base = _rebased(rig, rig.full_state(), func)
    xfull = loop.coords(loop.base)
    x0 = xfull[keep]
    A = loop.jacobian(xfull, FD_STEP)
    n = len(keep)
    # steady: the fixed point of the linearised map lies within STEADY_TOL of x0;
    # the angles since a count only to within a count (the quantiser's jitter)
    r = loop.residual(xfull, A)
    sc = loop.scales(xfull)[keep]
    try:
        M = np.linalg.inv(np.eye(n) - A)
    except np.linalg.LinAlgError:
        M = np.full((n, n), math.inf)
    dx = M @ r
    # the quantised loop is steady to within the encoders' jitter: the fixed
    # point's shift from two counts on each angle read
    jitter = np.zeros(n)
    for e, name in enumerate(("roller_angle_since_count", "wheelset_angle_since_count")):
        c = names.index(name)
        jitter += np.abs(M @ A[:, c]) * 2.0 * loop.q[e]
        jitter[c] += 2.0 * loop.q[e]
    tol = STEADY_TOL * sc + jitter
    bad = [names[i] for i in range(n) if not abs(dx[i]) <= tol[i]]
    if bad:
        what = "state" if state is not None else "the state the loop settled to"
        info = rig.info
        why = (" (a linearisation holds only about a steady state)" if state is not None else
               f" after {done} samples: the loop hunts, e.g. on its encoders' quantisation "
               f"({info.roller_counts} and {info.wheelset_counts} counts, speed quanta "
               f"{loop.q[0] / loop.T:.3g} and {loop.q[1] / loop.T:.3g} rad/s); the "
               "linearisation takes the quantiser at unit gain, which does not depend on the "
               "counts: linearise with finer encoders (roller_drive and wheelset_drive "
               "encoder_counts_per_rev, e.g. 2**30)")
        raise RollerRigError(f"{func}: {what} is not steady: the fixed point is off in "
                             + ", ".join(f"{names[i]} by {dx[i]:.3g}" for i in range(n)
                                         if names[i] in bad) + why)
    A4 = loop.jacobian(xfull, 4.0 * FD_STEP)
    rho, rho4 = (float(np.max(np.abs(np.linalg.eigvals(M)))) for M in (A, A4))
    if not abs(rho - rho4) <= CHECK_TOL * rho:
        raise RollerRigError(f"{func}: the closed loop's derivative is not resolved: the "
                             f"dominant |z| is {rho:.9g} at the step {FD_STEP:g} and "
                             f"{rho4:.9g} at four times it (the loop is not linear over "
                             f"the steps, or the encoders' quantisation shows)")
    rig.set_full_state(loop.base)
    z = np.linalg.eigvals(A)
    z = z[np.argsort(-np.abs(z))]
    lam = np.array([_continuous(complex(v), loop.T) for v in z])
    return ClosedLoopLinearization(A, names, z, lam, _modes(A, loop.T, names), x0,
                                   dict(loop.base), loop.T, float(V), plant.track,
                                   math.nan if creepage_target is None
                                   else float(creepage_target), float(loop.roller_ref))
